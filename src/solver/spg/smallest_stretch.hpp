#pragma once
/// The smallest principal stretch of a deformation gradient, sigma_min(F) =
/// sqrt(lambda_min(F^T F)), which the SPG step length follows (particle_pass.cpp, step_length) at
/// every particle and cycle.
///
/// Why not Eigen's closed form: SelfAdjointEigenSolver::computeDirect finds all three roots of
/// the characteristic cubic through atan2 and sincos; at one particle-step it was 8.8 % of an FDS
/// h 0.15 run's samples (perf: the solve 5.1 %, atan2 2.3 %, sincos 1.4 %). Only the smallest
/// root is needed, and it is a smooth function of one bounded variable, so a polynomial gives it.
///
/// The method. With m = tr C / 3, B = C - m I, p = sqrt(tr(B^2) / 6) and r = det B / (2 p^3) in
/// [-1, 1], the eigenvalues are m + p t with t the roots of t^3 - 3 t - 2 r = 0 (the
/// trigonometric solution: t = 2 cos((acos r + 2 pi k) / 3)). The smallest root,
/// t = 2 cos((acos r + 2 pi) / 3), lies in [-2, -1] and is analytic in u = sqrt(1 - r) on
/// [0, sqrt 2] (at r = 1 it meets the middle root, t = -1 - sqrt(2/3) u + ..., which is why u and
/// not r is the variable). A degree-13 polynomial in u, interpolated at Chebyshev nodes, gives t
/// within 4.9e-13 over the whole interval, so lambda_min within 4.9e-13 p plus round-off:
/// tests/unit/solver/spg/spg_stretch_test.cpp holds it against Eigen's iterative solver.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

#include <Eigen/Core>

namespace mcdyna::solver::spg {

inline double smallest_stretch(const Eigen::Matrix3d& f) {
  // C = F^T F: its six distinct entries, dot products of F's columns.
  const double c00 = f.col(0).squaredNorm(), c11 = f.col(1).squaredNorm(),
               c22 = f.col(2).squaredNorm();
  const double c01 = f.col(0).dot(f.col(1)), c02 = f.col(0).dot(f.col(2)),
               c12 = f.col(1).dot(f.col(2));
  const double m = (c00 + c11 + c22) / 3.0;
  const double b00 = c00 - m, b11 = c11 - m, b22 = c22 - m;
  const double p2 =
      (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (c01 * c01 + c02 * c02 + c12 * c12)) / 6.0;
  if (!(p2 > 0.0)) return std::sqrt(std::max(m, 0.0));  // C = m I: every stretch equal
  const double p = std::sqrt(p2);
  const double det_b =
      b00 * (b11 * b22 - c12 * c12) - c01 * (c01 * b22 - c12 * c02) + c02 * (c01 * c12 - b11 * c02);
  const double r = std::clamp(det_b / (2.0 * p2 * p), -1.0, 1.0);
  const double u = std::sqrt(1.0 - r);
  // t(u), highest power first (Horner), from tools/verify/smallest_root_fit.py.
  static constexpr double kRoot[] = {
      -1.0095770275718335e-06, 1.1634760812739808e-05,  -6.3262159091042998e-05,
      0.0002199392175953102,   -0.00056563104677267225, 0.0011967057318258846,
      -0.0022833443804676137,  0.00423834855576359,     -0.0080777360056594819,
      0.016459666077635084,    -0.037800642409084526,   0.11111110445394219,
      -0.81649658078747422,    -1.0000000000004907};
  double t = kRoot[0];
  for (std::size_t k = 1; k < std::size(kRoot); ++k)
    t = t * u + kRoot[k];
  return std::sqrt(std::max(m + p * t, 0.0));
}

}  // namespace mcdyna::solver::spg
