// The shapes' closest exits: a node found inside leaves by the shortest way out (the gap is minus
// that depth, the normal its direction), which the constraint then gives it in one step.
#include "solver/walls/geometric_wall.hpp"

#include <array>
#include <cmath>

namespace mcdyna::solver::walls {

namespace {

// Within [0, length] along an axis, or anywhere when the length is 0 (infinite).
bool within(double a, double length) {
  return length <= 0.0 || (a >= 0.0 && a <= length);
}

Penetration flat(const GeometricWall& w, const Vec3& r) {
  const double gap = r.dot(w.normal);
  if (gap >= 0.0 || !within(r.dot(w.edge_l), w.length_l) || !within(r.dot(w.edge_m), w.length_m))
    return {};
  return {true, gap, w.normal};
}

// Inside the box [0, L] x [0, M] x [0, P] along l, m, n: out through the nearest face.
Penetration prism(const GeometricWall& w, const Vec3& r) {
  const std::array<Vec3, 3> axes{w.edge_l, w.edge_m, w.normal};
  const std::array<double, 3> lengths{w.length_l, w.length_m, w.length_p};
  Penetration p;
  double depth = INFINITY;
  for (std::size_t k = 0; k < 3; ++k) {
    const double a = r.dot(axes[k]);
    if (!(a > 0.0 && a < lengths[k])) return {};
    if (a < depth) {
      depth = a;
      p.normal = -axes[k];
    }
    if (lengths[k] - a < depth) {
      depth = lengths[k] - a;
      p.normal = axes[k];
    }
  }
  p.inside = true;
  p.gap = -depth;
  return p;
}

// Inside the radius (and the length, when finite): out along the radius.
Penetration cylinder(const GeometricWall& w, const Vec3& r) {
  const double along = r.dot(w.normal);
  if (!within(along, w.cylinder_length)) return {};
  const Vec3 radial = r - along * w.normal;
  const double distance = radial.norm();
  if (distance >= w.radius || !(distance > 0.0)) return {};
  return {true, distance - w.radius, radial / distance};
}

Penetration sphere(const GeometricWall& w, const Vec3& r) {
  const double distance = r.norm();
  if (distance >= w.radius || !(distance > 0.0)) return {};
  return {true, distance - w.radius, r / distance};
}

}  // namespace

Penetration penetration(const GeometricWall& w, const Vec3& offset, const Vec3& x) {
  const Vec3 r = x - w.point - offset;
  switch (w.shape) {
    case Shape::flat:
      return flat(w, r);
    case Shape::prism:
      return prism(w, r);
    case Shape::cylinder:
      return cylinder(w, r);
    case Shape::sphere:
      return sphere(w, r);
  }
  return {};
}

}  // namespace mcdyna::solver::walls
