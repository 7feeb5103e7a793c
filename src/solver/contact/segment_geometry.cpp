#include "solver/contact/segment_geometry.hpp"

namespace mcdyna::solver::contact {

using Vec3 = Eigen::Vector3d;

std::array<double, 3> closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};  // vertex a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);  // inside
  const double v = vb * denom, w = vc * denom;
  return {1.0 - v - w, v, w};
}

SegmentPoint closest_on_segment(const Vec3& p, const std::array<Vec3, 4>& x) {
  SegmentPoint s;
  const bool triangle = (x[3] - x[2]).squaredNorm() == 0.0;
  const Vec3 n =
      triangle ? Vec3((x[1] - x[0]).cross(x[2] - x[0])) : Vec3((x[2] - x[0]).cross(x[3] - x[1]));
  const double length = n.norm();
  s.normal = length > 0.0 ? Vec3(n / length) : Vec3::UnitZ();
  const std::array<double, 3> t1 = closest_on_triangle(p, x[0], x[1], x[2]);
  const Vec3 p1 = t1[0] * x[0] + t1[1] * x[1] + t1[2] * x[2];
  s.weights = {t1[0], t1[1], t1[2], 0.0};
  s.point = p1;
  if (triangle) return s;
  const std::array<double, 3> t2 = closest_on_triangle(p, x[0], x[2], x[3]);
  const Vec3 p2 = t2[0] * x[0] + t2[1] * x[2] + t2[2] * x[3];
  if ((p2 - p).squaredNorm() < (p1 - p).squaredNorm()) {
    s.point = p2;
    s.weights = {t2[0], 0.0, t2[1], t2[2]};
  }
  return s;
}

}  // namespace mcdyna::solver::contact
