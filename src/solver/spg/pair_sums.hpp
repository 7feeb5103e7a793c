#pragma once
/// The sums over a row or a transpose that the SPG passes form per pair, written for two-wide
/// registers (GCC/Clang vector extensions: SSE2 on x86-64, NEON on arm64). The SPG passes are
/// bound by the instructions they issue and by their indexed reads, not by the bytes they move
/// (manual/verification.md, the roofline of the cycle); Eigen's fixed 3 x 3 expressions leave
/// one lane idle in most of these products (measured: F-hat and L of a row 25 % fewer
/// instructions here, the force gather 6 %). Each entry is formed by the same products and sums
/// in the same order as the Eigen expression it replaces (named at each function), so the bits
/// are the same.
#include <cstddef>
#include <cstdint>

namespace mcdyna::solver::spg::pairs {

using Index = std::int32_t;
/// Two doubles in one register; + - * act lane by lane, each an IEEE operation.
using Pair = double __attribute__((vector_size(16)));

/// Column c of a 3 x N column-major field.
inline const double* column(const double* field, Index c) {
  return field + 3 * static_cast<std::ptrdiff_t>(c);
}

/// sum_p (y_{k(p)} - y_j) (x) g_p over p in [begin, end), as Eigen's
/// `s.noalias() += (y.col(k) - y.col(j)) * g.transpose()` summed over p from zero: s_ab gets
/// (y_ka - y_ja) g_b added at each p. `column_of(p)` gives k(p)'s column of `y`; `out` is 3 x 3
/// column-major. Rows 0 and 1 share a register, row 2 is scalar.
template <class ColumnOf>
inline void row_gradient(const double* y, const double* yj, const double* gradients, Index begin,
                         Index end, ColumnOf&& column_of, double* out) {
  const Pair own = {yj[0], yj[1]};
  Pair top[3] = {};  // (s_0b, s_1b)
  double bottom[3] = {0.0, 0.0, 0.0};
  for (Index p = begin; p < end; ++p) {
    const double* yk = column(y, column_of(p));
    const double* g = column(gradients, p);
    const Pair d = Pair{yk[0], yk[1]} - own;
    const double d2 = yk[2] - yj[2];
    for (int b = 0; b < 3; ++b) {
      top[b] += d * Pair{g[b], g[b]};
      bottom[b] += d2 * g[b];
    }
  }
  for (int b = 0; b < 3; ++b) {
    out[3 * b] = top[b][0];
    out[3 * b + 1] = top[b][1];
    out[3 * b + 2] = bottom[b];
  }
}

/// The same sum for two fields y and z at once (F-hat and the velocity gradient of a row): each
/// entry (s_ab, t_ab) in one register. `out_y`, `out_z`: 3 x 3 column-major.
template <class ColumnOf>
inline void row_gradients(const double* y, const double* z, const double* yj, const double* zj,
                          const double* gradients, Index begin, Index end, ColumnOf&& column_of,
                          double* out_y, double* out_z) {
  const Pair own[3] = {{yj[0], zj[0]}, {yj[1], zj[1]}, {yj[2], zj[2]}};
  Pair sum[9] = {};  // entry (a, b) at 3 b + a
  for (Index p = begin; p < end; ++p) {
    const Index k = column_of(p);
    const double* yk = column(y, k);
    const double* zk = column(z, k);
    const double* g = column(gradients, p);
    const Pair d[3] = {Pair{yk[0], zk[0]} - own[0], Pair{yk[1], zk[1]} - own[1],
                       Pair{yk[2], zk[2]} - own[2]};
    for (int b = 0; b < 3; ++b) {
      const Pair gb = {g[b], g[b]};
      for (int a = 0; a < 3; ++a)
        sum[3 * b + a] += d[a] * gb;
    }
  }
  for (int e = 0; e < 9; ++e) {
    out_y[e] = sum[e][0];
    out_z[e] = sum[e][1];
  }
}

/// sum_t -P_{r(t)} g_t over t in [begin, end): the internal-force gather over a transpose, as
/// Eigen's `f.noalias() -= p * g` summed over t from zero, P a 3 x 3 column-major tensor per
/// row (`tensors`, 9 per column) and g per pair. Eigen forms rows 0 and 1 of p g in a register as
/// (p_a0 g_0 + p_a1 g_1) + p_a2 g_2 and row 2 as a scalar sum, p_20 g_0 + (p_21 g_1 + p_22 g_2)
/// (measured bit for bit on random data): the same here. `out` is the 3-vector.
template <class RowOf>
inline void transpose_force(const double* tensors, const double* gradients, Index begin, Index end,
                            RowOf&& row_of, double* out) {
  Pair top = {0.0, 0.0};
  double bottom = 0.0;
  for (Index t = begin; t < end; ++t) {
    const double* p = tensors + 9 * static_cast<std::ptrdiff_t>(row_of(t));
    const double* g = column(gradients, t);
    const Pair product =
        (Pair{p[0], p[1]} * Pair{g[0], g[0]} + Pair{p[3], p[4]} * Pair{g[1], g[1]}) +
        Pair{p[6], p[7]} * Pair{g[2], g[2]};
    top -= product;
    bottom -= p[2] * g[0] + (p[5] * g[1] + p[8] * g[2]);
  }
  out[0] = top[0];
  out[1] = top[1];
  out[2] = bottom;
}

}  // namespace mcdyna::solver::spg::pairs
