#pragma once
/// Geometry of the 8-node hexahedron: shape-function gradients at a point of the parent cube,
/// the Flanagan-Belytschko hourglass base vectors and the characteristic length LS-DYNA uses for
/// the time step (volume / largest face area). Node order is LS-DYNA's: 1-4 bottom, 5-8 top.
#include <array>
#include <cmath>

namespace mcdyna::solver::hex {

/// Parent coordinates of the corners.
inline constexpr double kXi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

/// Corner coordinates (or velocities): x[corner][component].
using Corners = std::array<std::array<double, 3>, 8>;

/// Gradients dN/dx of the 8 shape functions at parent point (r, s, t) and det(dx/dxi).
struct Gradients {
  double b[8][3];
  double det;
};

/// dN_I/dxi_j at parent point p.
inline void parent_gradients(const double p[3], double g[8][3]) {
  for (int i = 0; i < 8; ++i) {
    const double a = 1.0 + kXi[i][0] * p[0], b = 1.0 + kXi[i][1] * p[1], c = 1.0 + kXi[i][2] * p[2];
    g[i][0] = 0.125 * kXi[i][0] * b * c;
    g[i][1] = 0.125 * kXi[i][1] * a * c;
    g[i][2] = 0.125 * kXi[i][2] * a * b;
  }
}

/// Inverse of a 3x3 matrix: out = a^-1; returns det(a) (out is left unset when det <= 0).
inline double invert(const double a[3][3], double out[3][3]) {
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  if (!(det > 0.0)) return det;
  const double inv = 1.0 / det;
  out[0][0] = c00 * inv;
  out[1][0] = c01 * inv;
  out[2][0] = c02 * inv;
  out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * inv;
  out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * inv;
  out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * inv;
  out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * inv;
  out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * inv;
  out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * inv;
  return det;
}

/// Gradients at a parent point from the parent gradients g; det <= 0 flags an inverted element.
inline Gradients gradients(const Corners& x, const double g[8][3]) {
  double j[3][3] = {};  // j[i][k] = dx_i / dxi_k
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        j[i][k] += x[n][i] * g[n][k];
  Gradients out;    // b is filled only for a valid element (det > 0); no zeroing on the hot path
  double ji[3][3];  // inverse of j: ji[k][i] = dxi_k / dx_i
  out.det = invert(j, ji);
  if (!(out.det > 0.0)) return out;
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      out.b[n][i] = g[n][0] * ji[0][i] + g[n][1] * ji[1][i] + g[n][2] * ji[2][i];
  return out;
}

/// The 2x2x2 Gauss points (parent coordinates) and the parent gradients there, computed once.
struct GaussPoints {
  double at[8][3];
  double gradients[8][8][3];  ///< [point][corner][direction]
  GaussPoints() {
    const double p = 1.0 / std::sqrt(3.0);
    for (int q = 0; q < 8; ++q) {
      for (int k = 0; k < 3; ++k)
        at[q][k] = p * kXi[q][k];
      parent_gradients(at[q], gradients[q]);
    }
  }
};

inline const GaussPoints& gauss_points() {
  static const GaussPoints kPoints;
  return kPoints;
}

/// Corner sign patterns of the parent cube, indexed by a 3-bit mask k (bit 0: xi, bit 1: eta,
/// bit 2: zeta): pattern k at a corner is the product of the corner's parent coordinates named
/// by k. k = 0 is the constant, 1 / 2 / 4 the linear patterns, 3 / 5 / 6 / 7 the hourglass
/// patterns xi eta, xi zeta, eta zeta, xi eta zeta (the Flanagan-Belytschko hourglass base vectors
/// of 1981, in kHourglassPattern). kBinary[n] is corner n's position in binary order (bit set:
/// parent coordinate +1).
inline constexpr int kBinary[8] = {0, 1, 3, 2, 4, 5, 7, 6};
inline constexpr int kHourglassPattern[4] = {6, 5, 3, 7};

/// Pattern sums m[k][i] = sum_n pattern_k(n) x[n][i], by a fast Walsh-Hadamard transform: 24
/// additions per component instead of 64 multiply-adds. The loops are unrolled so that the
/// branch on the bit folds away and everything stays in registers.
inline void pattern_sums(const Corners& x, double m[8][3]) {
#pragma GCC unroll 8
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      m[kBinary[n]][i] = x[n][i];
#pragma GCC unroll 3
  for (int bit = 1; bit < 8; bit <<= 1)
#pragma GCC unroll 8
    for (int b = 0; b < 8; ++b)
      if (!(b & bit))
        for (int i = 0; i < 3; ++i) {
          const double lo = m[b][i], hi = m[b | bit][i];
          m[b][i] = lo + hi;
          m[b | bit][i] = hi - lo;
        }
}

/// The transpose map: f[3 n + i] += sum_k c[k][i] pattern_k(n). Overwrites c.
inline void add_pattern_combination(double c[8][3], double* f) {
#pragma GCC unroll 3
  for (int bit = 1; bit < 8; bit <<= 1)
#pragma GCC unroll 8
    for (int b = 0; b < 8; ++b)
      if (!(b & bit))
        for (int i = 0; i < 3; ++i) {
          const double lo = c[b][i], hi = c[b | bit][i];
          c[b][i] = lo - hi;
          c[b | bit][i] = lo + hi;
        }
#pragma GCC unroll 8
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      f[3 * n + i] += c[kBinary[n]][i];
}

/// Jacobian at the element centre from the pattern sums of the corners: J[i][k] = hx[2^k][i] / 8.
inline void centre_jacobian(const double hx[8][3], double jac[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      jac[i][k] = 0.125 * hx[1 << k][i];
}

/// The one-point (ELFORM 1) volume 8 det J(0), computed as the element pass computes it, so a
/// relative volume starts at exactly 1.
inline double centre_volume(const Corners& x) {
  double hx[8][3], jac[3][3], inverse[3][3];
  pattern_sums(x, hx);
  centre_jacobian(hx, jac);
  return 8.0 * invert(jac, inverse);
}

/// Largest face area (faces as quadrilaterals, area = |d1 x d2| / 2 from the diagonals).
inline double max_face_area(const Corners& x) {
  static constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double best = 0.0;
  for (const auto& f : kFaces) {
    double d1[3], d2[3];
    for (int i = 0; i < 3; ++i) {
      d1[i] = x[f[2]][i] - x[f[0]][i];
      d2[i] = x[f[3]][i] - x[f[1]][i];
    }
    const double cx = d1[1] * d2[2] - d1[2] * d2[1], cy = d1[2] * d2[0] - d1[0] * d2[2],
                 cz = d1[0] * d2[1] - d1[1] * d2[0];
    best = std::max(best, cx * cx + cy * cy + cz * cz);
  }
  return 0.5 * std::sqrt(best);
}

// Exact volume of the trilinear hexahedron (det J is at most quadratic in each parent
// coordinate, so 2x2x2 Gauss points integrate it exactly), also for degenerate hexahedra.
inline double exact_volume(const Corners& x) {
  double v = 0.0;
  for (const auto& g : gauss_points().gradients)
    v += gradients(x, g).det;
  return v;
}

}  // namespace mcdyna::solver::hex
