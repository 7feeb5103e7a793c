#pragma once
/// Kernel (window) functions of *SECTION_SOLID_SPG, ISPLINE 0/1/2 (keywords.md §2.6). A kernel
/// centred at particle J is evaluated at z = B r, r = x - X_J, where B maps J's support onto
/// the unit box or ball. Initially the support is axis-aligned with half-sizes
/// a = (a_x, a_y, a_z) = DX/DY/DZ x nodal spacing, B = diag(1/a); the updated-Lagrangian kernel
/// deforms it with the material (Eq. 34, renewal.cpp), making B a general matrix:
///   ISPLINE 0: cubic spline, box support       w = c(|z_x|) c(|z_y|) c(|z_z|)
///   ISPLINE 1: quadratic spline, box support   w = q(|z_x|) q(|z_y|) q(|z_z|)
///   ISPLINE 2: cubic spline, spherical support w = c(|z|)  (an ellipsoid in r)
/// The splines are the B-splines on [-1, 1]; their normalisation does not matter because the
/// reproducing-kernel correction removes it.
#include <Eigen/Core>
#include <Eigen/Dense>

#include <cmath>

namespace mcdyna::solver::spg {

enum class KernelShape { cubic_box = 0, quadratic_box = 1, cubic_sphere = 2 };

/// One-dimensional window and its derivative d/dz at z = |r| / a >= 0.
struct Window {
  double value = 0.0, slope = 0.0;
};

inline Window cubic_spline(double z) {
  if (z >= 1.0) return {};
  if (z <= 0.5) return {2.0 / 3.0 - 4.0 * z * z + 4.0 * z * z * z, -8.0 * z + 12.0 * z * z};
  const double u = 1.0 - z;
  return {4.0 / 3.0 * u * u * u, -4.0 * u * u};
}

inline Window quadratic_spline(double z) {
  if (z >= 1.0) return {};
  const double s = 1.5 * z;  // the quadratic B-spline on [-1.5, 1.5], scaled to [-1, 1]
  if (s <= 0.5) return {0.75 - s * s, -2.0 * s * 1.5};
  const double u = 1.5 - s;
  return {0.5 * u * u, -u * 1.5};
}

/// Kernel value and gradient with respect to the evaluation point x, for r = x - X_J.
struct KernelValue {
  double w = 0.0;
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();
};

/// True when z = B r lies inside the unit support of the given shape.
inline bool in_unit_support(KernelShape shape, const Eigen::Vector3d& z) {
  if (shape == KernelShape::cubic_sphere) return z.squaredNorm() < 1.0;
  return std::abs(z.x()) < 1.0 && std::abs(z.y()) < 1.0 && std::abs(z.z()) < 1.0;
}

/// How far z = B r lies from the centre in units of the support: < 1 inside (|z| for the ball,
/// max |z_k| for the box).
inline double unit_distance(KernelShape shape, const Eigen::Vector3d& z) {
  return shape == KernelShape::cubic_sphere ? z.norm() : z.cwiseAbs().maxCoeff();
}

/// Kernel value and gradient d/dr at z = B r (`to_unit` = B).
inline KernelValue kernel(KernelShape shape, const Eigen::Vector3d& r,
                          const Eigen::Matrix3d& to_unit) {
  KernelValue k;
  const Eigen::Vector3d z = to_unit * r;
  Eigen::Vector3d grad_z = Eigen::Vector3d::Zero();
  if (shape == KernelShape::cubic_sphere) {
    const double length = z.norm();
    const Window c = cubic_spline(length);
    k.w = c.value;
    // dw/dz = c'(|z|) z / |z|; at z = 0 the slope is 0 and so is the gradient.
    if (length > 0.0) grad_z = (c.slope / length) * z;
  } else {
    Window f[3];
    for (int i = 0; i < 3; ++i) {
      f[i] = shape == KernelShape::cubic_box ? cubic_spline(std::abs(z[i]))
                                             : quadratic_spline(std::abs(z[i]));
      if (z[i] < 0.0) f[i].slope = -f[i].slope;  // now d/dz_i
    }
    k.w = f[0].value * f[1].value * f[2].value;
    grad_z = {f[0].slope * f[1].value * f[2].value, f[0].value * f[1].slope * f[2].value,
              f[0].value * f[1].value * f[2].slope};
  }
  k.grad = to_unit.transpose() * grad_z;
  return k;
}

/// The same for an axis-aligned support of half-sizes a.
inline KernelValue kernel(KernelShape shape, const Eigen::Vector3d& r, const Eigen::Vector3d& a) {
  return kernel(shape, r, Eigen::Matrix3d(a.cwiseInverse().asDiagonal()));
}

/// The supports of a set of particles: B per particle (column-major 3x3 in a column) and the
/// half-sizes of the axis-aligned box around each support, for the cell search.
struct Supports {
  Eigen::Matrix<double, 9, Eigen::Dynamic> to_unit;
  Eigen::Matrix3Xd reach;
  [[nodiscard]] Eigen::Map<const Eigen::Matrix3d> matrix(Eigen::Index j) const {
    return Eigen::Map<const Eigen::Matrix3d>(to_unit.col(j).data());
  }
};

/// Axis-aligned supports of half-sizes a (3 x N).
inline Supports axis_aligned(const Eigen::Matrix3Xd& a) {
  Supports s;
  s.reach = a;
  s.to_unit.setZero(9, a.cols());
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = 0; k < 3; ++k)
      s.to_unit(4 * k, j) = 1.0 / a(k, j);
  return s;
}

/// Supports that are the images S_j (unit box or ball) of general matrices S (9 x N).
inline Supports deformed(KernelShape shape, const Eigen::Matrix<double, 9, Eigen::Dynamic>& s) {
  Supports out;
  out.to_unit.resize(9, s.cols());
  out.reach.resize(3, s.cols());
  for (Eigen::Index j = 0; j < s.cols(); ++j) {
    const Eigen::Map<const Eigen::Matrix3d> m(s.col(j).data());
    Eigen::Map<Eigen::Matrix3d>(out.to_unit.col(j).data()) = m.inverse();
    // Half-widths of the bounding box: corners of the parallelepiped, or the ellipsoid's.
    for (int k = 0; k < 3; ++k)
      out.reach(k, j) =
          shape == KernelShape::cubic_sphere ? m.row(k).norm() : m.row(k).cwiseAbs().sum();
  }
  return out;
}

}  // namespace mcdyna::solver::spg
