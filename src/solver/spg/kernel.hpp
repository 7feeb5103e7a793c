#pragma once
/// Kernel (window) functions of *SECTION_SOLID_SPG, ISPLINE 0/1/2 (keywords.md §2.6). A kernel
/// centred at particle J with support half-sizes a = (a_x, a_y, a_z) = DX/DY/DZ x nodal spacing:
///   ISPLINE 0: cubic spline, box support       w = c(|r_x|/a_x) c(|r_y|/a_y) c(|r_z|/a_z)
///   ISPLINE 1: quadratic spline, box support   w = q(|r_x|/a_x) q(|r_y|/a_y) q(|r_z|/a_z)
///   ISPLINE 2: cubic spline, spherical support w = c(|(r_x/a_x, r_y/a_y, r_z/a_z)|)
/// (an ellipsoid when the a_k differ). The splines are the B-splines on [-1, 1]; their
/// normalisation does not matter because the reproducing-kernel correction removes it.
#include <Eigen/Core>

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

/// True when r lies inside the support (half-sizes a) of the given shape.
inline bool in_support(KernelShape shape, const Eigen::Vector3d& r, const Eigen::Vector3d& a) {
  if (shape == KernelShape::cubic_sphere) return (r.cwiseQuotient(a)).squaredNorm() < 1.0;
  return std::abs(r.x()) < a.x() && std::abs(r.y()) < a.y() && std::abs(r.z()) < a.z();
}

inline KernelValue kernel(KernelShape shape, const Eigen::Vector3d& r, const Eigen::Vector3d& a) {
  KernelValue k;
  if (shape == KernelShape::cubic_sphere) {
    const Eigen::Vector3d s = r.cwiseQuotient(a);
    const double z = s.norm();
    const Window c = cubic_spline(z);
    k.w = c.value;
    // dw/dx_k = c'(z) s_k / (z a_k); at z = 0 the slope is 0 and so is the gradient.
    if (z > 0.0) k.grad = (c.slope / z) * s.cwiseQuotient(a);
    return k;
  }
  Window f[3];
  for (int i = 0; i < 3; ++i) {
    const double z = std::abs(r[i]) / a[i];
    f[i] = shape == KernelShape::cubic_box ? cubic_spline(z) : quadratic_spline(z);
    const double sign = r[i] < 0.0 ? -1.0 : 1.0;
    f[i].slope *= sign / a[i];  // now d/dr_i
  }
  k.w = f[0].value * f[1].value * f[2].value;
  k.grad = {f[0].slope * f[1].value * f[2].value, f[0].value * f[1].slope * f[2].value,
            f[0].value * f[1].value * f[2].slope};
  return k;
}

}  // namespace mcdyna::solver::spg
