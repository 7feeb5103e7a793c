// The largest frequency of an SPG part, by power iteration on its linearised equations of
// motion: x'' = -A x with A = W K, K the stiffness of direct nodal integration (Eq. 5) with the
// elastic tangent at the current state, and W what MC-SPG does with a force: a_J = f_J / m_J
// (Eq. 20 masses), u-hat_K = sum_J phi_J(X_K) a_J (Eq. 30), u_I = sum_K psi_I(X_K) u-hat_K
// (Eq. 13); pinned particles (FE-coupled, constrained) move with their node mass and their
// share of the neighbours' accelerations, as in smoothing.cpp. The central-difference update is
// stable for dt < 2 / omega_max with omega_max^2 the largest eigenvalue of A.
//
// ITB 1 (gradient_stabilization.cpp): its stabilisation forces, linearised with the elastic
// tangent, join K.
//
// What it leaves out: the FE elements around pinned particles (their own step bounds them),
// contact springs (bounded by SOFT 1, contact_forces.cpp), bulk viscosity (it damps), MSC
// mode-control springs and PDAMP. The elastic tangent is used where the material yields: the
// plastic tangent is softer, so the elastic frequency bounds it.
#include <cmath>
#include <limits>
#include <vector>

#include "core/bounded_sum.hpp"
#include "solver/material/constitutive.hpp"
#include "solver/spg/distribution.hpp"
#include "solver/spg/pair_sums.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

// Where a product A x can be nonzero when x is nonzero on a patch of particles only: the
// iterations started on the rows a renewal changed (kRenewalIterations, stiffness_length.cpp),
// about 0.1 % of the rows on the FDS plate. Each pass of apply() gathers over the neighbour
// lists or their transpose, so the patch grows by one reach per pass: the rows whose lists hold
// a patch particle (their strain), the particles of those rows (their forces), and for MC-SPG
// the rows again (u-hat, Eq. 30) and their particles (the gather, Eq. 13). Outside it every term
// of the whole-domain product is an exact zero, so the product formed on the patch has the same
// bits (up to the sign of zeros, which no later operation turns into a value).
struct ProductPatch {
  ParticleSubset rows, particles, hat, out;
};

void list_subset(ParticleSubset& s) {
  s.index.clear();
  for (std::size_t i = 0; i < s.flag.size(); ++i)
    if (s.flag[i]) s.index.push_back(static_cast<Index>(i));
}

// `from` and every entry of the compressed lists (offsets, entries) of its particles: over the
// transpose, the rows whose neighbour lists hold one of them; over the lists, their neighbours.
void reach(const ParticleSubset& from, const std::vector<Index>& offsets,
           const std::vector<Index>& entries, ParticleSubset& to) {
  to.flag = from.flag;
  for (const Index k : from.index)
    for (Index t = offsets[static_cast<std::size_t>(k)];
         t < offsets[static_cast<std::size_t>(k) + 1]; ++t)
      to.flag[static_cast<std::size_t>(entries[static_cast<std::size_t>(t)])] = 1;
  list_subset(to);
}

// The patch of a product of x nonzero on `live`.
void spread(const Domain& d, const ParticleSubset& live, ProductPatch& patch) {
  const auto rows_of = [&d](const ParticleSubset& from, ParticleSubset& to) {
    reach(from, d.kernel.transpose.offsets, d.kernel.transpose.rows, to);
  };
  const auto particles_of = [&d](const ParticleSubset& from, ParticleSubset& to) {
    reach(from, d.kernel.list.offsets, d.kernel.list.neighbours, to);
  };
  rows_of(live, patch.rows);
  particles_of(patch.rows, patch.particles);
  if (d.settings.stabilization != Stabilization::momentum_consistent) return;
  rows_of(patch.particles, patch.hat);
  particles_of(patch.hat, patch.out);
}

// What a product's result is nonzero on.
const ParticleSubset& result_support(const Domain& d, const ProductPatch& patch) {
  return d.settings.stabilization == Stabilization::momentum_consistent ? patch.out
                                                                        : patch.particles;
}

// A x for displacements x (3 x count) into `out`, with the domain's workspace for the stress,
// the forces (turned into the smoothed particles' accelerations in place) and u-hat. With
// `patch`, formed on it only and zero elsewhere. Over several processes (`share`), formed on
// this process's stressed rows and own particles, as the cycle's passes are (distribution.hpp):
// x must hold the stress ghosts' iterate; the accelerations reach the row ghosts and u-hat the
// column ghosts between the passes; `out` is current on the own particles only.
void apply(const State& s, Domain& d, const Material& mat, const Eigen::Matrix3Xd& x,
           Eigen::Matrix3Xd& out, bool stabilization, const ProductPatch* patch,
           parallel::ParticleShare* share) {
  const Index n = d.count();
  const double shear = mat.shear_modulus;
  const bool mc = d.settings.stabilization == Stabilization::momentum_consistent;
  Eigen::Matrix<double, 9, Eigen::Dynamic>& p = d.scratch.stress;
  Eigen::Matrix3Xd& acc = d.scratch.force;
  Eigen::Matrix3Xd& hat = d.scratch.hat;
  const ParticleSubset* rows = patch != nullptr   ? &patch->rows
                               : share != nullptr ? &share->stressed
                                                  : nullptr;
  const ParticleSubset* particles = patch != nullptr   ? &patch->particles
                                    : share != nullptr ? &share->owned
                                                       : nullptr;
  const ParticleSubset* hats = patch == nullptr ? particles : mc ? &patch->hat : particles;
  const ParticleSubset* outs = patch == nullptr ? particles : &result_support(d, *patch);
  if (patch != nullptr) {
    p.setZero(9, n);
    acc.setZero(3, n);
    hat.setZero(3, n);
    out.setZero(3, n);
  } else {
    p.resize(9, n);
    acc.resize(3, n);
    hat.resize(3, n);
  }
  const auto row_count = static_cast<std::int64_t>(members(rows, n));
#pragma omp parallel for schedule(static, 256) if (row_count > 512)
  for (std::int64_t r = 0; r < row_count; ++r) {
    const Index j = member(rows, static_cast<std::size_t>(r));
    const auto jj = static_cast<std::size_t>(j);
    Eigen::Map<Mat3> pj(p.col(j).data());
    if (d.kernel.isolated[jj] || d.fields.debris[jj]) {
      pj.setZero();
      continue;
    }
    double sums[9];
    const Index* neighbours = d.kernel.list.neighbours.data();
    pairs::row_gradient(
        x.data(), x.col(j).data(), d.kernel.shape.gradient.data(), d.kernel.list.offsets[jj],
        d.kernel.list.offsets[jj + 1], [&](Index q) { return neighbours[q]; }, sums);
    const Mat3 df = Eigen::Map<const Mat3>(sums);
    const Eigen::Map<const Mat3> f_hat(d.fields.deformation.col(j).data());
    const Mat3 f_inv = f_hat.inverse();
    const Mat3 l = df * f_inv;
    const Mat3 e = 0.5 * (l + l.transpose());
    const double physical = d.particles.mass[jj] - d.particles.added_mass[jj];
    const double rc2 =
        physical / d.fields.volume[jj] *
        wave_speed_squared(mat, d.fields.volume[jj] / d.particles.initial_volume[jj]);
    const double g = d.fields.failed[jj] ? 0.0 : shear;
    const Mat3 sigma = (rc2 - 2.0 * g) * e.trace() * Mat3::Identity() + 2.0 * g * e;
    const double weight =
        d.fields.volume[jj] * (d.particles.surface[jj] ? d.settings.surface_factor : 1.0);
    pj = weight * sigma * f_inv.transpose();
  }
  // Forces, gathered over the transpose; for the smoothed particles the accelerations f / m
  // (Eq. 20 masses), for the pinned ones the force itself (their node mass takes it below).
  const auto particle_count = static_cast<std::int64_t>(members(particles, n));
#pragma omp parallel for schedule(static, 256) if (particle_count > 512)
  for (std::int64_t r = 0; r < particle_count; ++r) {
    const Index i = member(particles, static_cast<std::size_t>(r));
    const auto ii = static_cast<std::size_t>(i);
    Vec3 f;
    const Index* rows_of = d.kernel.transpose.rows.data();
    pairs::transpose_force(
        p.data(), d.kernel.transpose.gradient.data(), d.kernel.transpose.offsets[ii],
        d.kernel.transpose.offsets[ii + 1], [&](Index t) { return rows_of[t]; }, f.data());
    acc.col(i) = !d.kernel.pinned[ii] && mc ? Vec3(f / d.kernel.smoothed_mass[ii]) : f;
  }
  if (stabilization) {  // ITB 1: every particle pinned, acc holds forces
    stabilization_operator(d, mat, x, d.fields.gradient.force, rows, particles);
    acc += d.fields.gradient.force;
  }
  if (share != nullptr && mc) exchange_columns(*share, share->row_ghosts, acc);  // Eq. 30's a_J
  const auto hat_count = static_cast<std::int64_t>(members(hats, n));
#pragma omp parallel for schedule(static, 256) if (hat_count > 512)
  for (std::int64_t r = 0; r < hat_count; ++r) {
    const Index k = member(hats, static_cast<std::size_t>(r));
    const auto kk = static_cast<std::size_t>(k);
    Vec3 sum = Vec3::Zero();
    if (mc)
      for (Index q = d.kernel.list.offsets[kk]; q < d.kernel.list.offsets[kk + 1]; ++q) {
        const Index j = d.kernel.list.neighbours[static_cast<std::size_t>(q)];
        if (!d.kernel.pinned[static_cast<std::size_t>(j)])
          sum += d.kernel.shape.value[static_cast<std::size_t>(q)] * acc.col(j);
      }
    if (d.kernel.pinned[kk] || !mc) {
      const auto node = static_cast<std::size_t>(d.particles.nodes[kk]);
      const double m = s.nodes.mass[node] + s.nodes.added_mass[node];
      hat.col(k) =
          (acc.col(k) + d.particles.mass[kk] * sum) / m;  // acc holds the pinned one's force
    } else {
      hat.col(k) = sum;
    }
  }
  if (share != nullptr && mc) exchange_columns(*share, share->column_ghosts, hat);  // Eq. 13's
  const auto out_count = static_cast<std::int64_t>(members(outs, n));
#pragma omp parallel for schedule(static, 256) if (out_count > 512)
  for (std::int64_t r = 0; r < out_count; ++r) {
    const Index i = member(outs, static_cast<std::size_t>(r));
    const auto ii = static_cast<std::size_t>(i);
    if (d.kernel.pinned[ii] || !mc) {
      out.col(i) = hat.col(i);
      continue;
    }
    out.col(i) = gathered(d, i, hat);
  }
}

double start_value(Index i, int k) {
  std::uint64_t z =
      (static_cast<std::uint64_t>(i) * 3 + static_cast<std::uint64_t>(k)) * 0x9E3779B97F4A7C15ULL +
      0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
}

// The power iteration's norms are order-free sums (core::BoundedSum, after a pass for the
// largest term): the same bits for any thread count and any split of the particles over
// processes (issue 25): over several, each process adds the terms of its own particles under
// the largest term of all, and the integer digits are summed over the processes.
template <class Term>
double order_free_sum(Index count, const ParticleSubset* own, const core::Communicator& comm,
                      Term&& term) {
  const std::size_t terms = members(own, count);
  double bound = 0.0;
  for (std::size_t k = 0; k < terms; ++k)
    bound = std::max(bound, std::abs(term(member(own, k))));
  if (own != nullptr) bound = -comm.min(-bound);
  core::BoundedSum sum(bound);
  for (std::size_t k = 0; k < terms; ++k)
    if (const double t = term(member(own, k)); t != 0.0) sum.add(t);
  if (own == nullptr) return sum.value();
  const core::BoundedSum::Digits mine = sum.digits();
  const std::vector<std::int64_t> all =
      comm.sum(std::vector<std::int64_t>(mine.begin(), mine.end()));
  return core::BoundedSum::from_digits(bound, {all[0], all[1]}).value();
}

// The norms and products of the iteration, over the whole part (`own` null) or a process's own
// particles.
struct OrderFree {
  const ParticleSubset* own = nullptr;
  core::Communicator comm;

  [[nodiscard]] double norm(const Eigen::Matrix3Xd& x) const {
    return std::sqrt(order_free_sum(static_cast<Index>(x.cols()), own, comm,
                                    [&](Index i) { return x.col(i).squaredNorm(); }));
  }
  // sum_i w_i x_i . y_i.
  [[nodiscard]] double weighted_dot(const std::vector<double>& w, const Eigen::Matrix3Xd& x,
                                    const Eigen::Matrix3Xd& y) const {
    return order_free_sum(static_cast<Index>(x.cols()), own, comm, [&](Index i) {
      return w[static_cast<std::size_t>(i)] * x.col(i).dot(y.col(i));
    });
  }
  // |x| in the product of `w` (empty: the Euclidean norm).
  [[nodiscard]] double length_in(const std::vector<double>& w, const Eigen::Matrix3Xd& x) const {
    return w.empty() ? norm(x) : std::sqrt(weighted_dot(w, x, x));
  }
  // The particle where x is largest (the lowest index among equals), over every process.
  [[nodiscard]] Index largest(const Eigen::Matrix3Xd& x) const {
    double value = -1.0;
    Index at = -1;
    for (std::size_t k = 0; k < members(own, static_cast<Index>(x.cols())); ++k) {
      const Index i = member(own, k);
      if (x.col(i).squaredNorm() > value) {
        value = x.col(i).squaredNorm();
        at = i;
      }
    }
    if (own == nullptr) return at;
    const double top = -comm.min(-value);
    return static_cast<Index>(
        comm.min(static_cast<std::int64_t>(value == top ? at : std::numeric_limits<Index>::max())));
  }
};

// The inner product in which A is self-adjoint, where it is known: without MC smoothing every
// particle moves with its node's mass, A = M^-1 K with K symmetric, and the Rayleigh quotient
// x.M A x / x.M x never exceeds omega_max^2. |A x| / |x| does, by up to the square root of the
// mass ratio of neighbours, once DT2MS has made neighbours' masses differ: measured on FDS h 0.3
// with ITB 1 and DT2MS 1e-8 (mass factors up to 35 beside 1), a check with renewed rows put
// 2 / omega at 4.98e-9 s where the next checks found 1.07e-8 and 1.7e-8 s; the one scale of the
// step lengths fell with it and in two cycles DT2MS took the added mass to 11 x the plate's, on
// 2,413 of its 2,454 nodes. Empty for MC-SPG (its A = T m-hat^-1 T^T K is self-adjoint in no
// diagonal product; the Euclidean norm is kept there).
std::vector<double> self_adjoint_weights(const State& s, const Domain& d) {
  std::vector<double> w;
  if (d.settings.stabilization == Stabilization::momentum_consistent) return w;
  w.resize(static_cast<std::size_t>(d.count()));
  for (Index k = 0; k < d.count(); ++k) {
    const auto node = static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(k)]);
    w[static_cast<std::size_t>(k)] = s.nodes.mass[node] + s.nodes.added_mass[node];
  }
  return w;
}

}  // namespace

Eigen::Matrix3Xd frequency_start(Index count, const std::vector<std::uint8_t>& rows) {
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, count);
  for (Index i = 0; i < count; ++i)
    if (rows.empty() || rows[static_cast<std::size_t>(i)])
      for (int k = 0; k < 3; ++k)
        x(k, i) = start_value(i, k);
  return x;
}

FrequencyEstimate largest_frequency(State& s, Domain& d, int iterations, Eigen::Matrix3Xd* mode,
                                    bool without_stabilization, bool on_support) {
  const bool stabilization =
      d.settings.stabilization == Stabilization::strain_gradient && !without_stabilization;
  const Index n = d.count();
  FrequencyEstimate r;
  if (n == 0) return r;
  const Material& mat = s.materials[static_cast<std::size_t>(d.material)];
  parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const OrderFree sums{share != nullptr ? &share->owned : nullptr, s.ownership.comm};
  Eigen::Matrix3Xd& x = d.scratch.vector;
  Eigen::Matrix3Xd& ax = d.scratch.product;
  ax.resize(3, n);
  if (mode && mode->cols() == n && sums.norm(*mode) > 0.0)
    x = *mode;
  else
    x = frequency_start(n);
  const std::vector<double> w = self_adjoint_weights(s, d);
  x /= sums.length_in(w, x);
  // Products on the patch while it stays small (past half the particles the whole-domain loops
  // cost less than the reaches and the zeroing). Over several processes a patch would reach
  // across them: the products are formed on each process's share, which gives the same bits.
  ParticleSubset live;
  ProductPatch patch;
  bool on_patch = on_support && share == nullptr;
  if (on_patch) {
    live.flag.assign(static_cast<std::size_t>(n), 0);
    for (Index i = 0; i < n; ++i)
      live.flag[static_cast<std::size_t>(i)] = (x.col(i).array() != 0.0).any() ? 1 : 0;
    list_subset(live);
  }
  double previous = 0.0;
  for (int it = 0; it < iterations; ++it) {
    if (on_patch) {
      spread(d, live, patch);
      on_patch = 2 * result_support(d, patch).index.size() < static_cast<std::size_t>(n);
    }
    if (share != nullptr) exchange_columns(*share, share->stress_ghosts, x);
    apply(s, d, mat, x, ax, stabilization, on_patch ? &patch : nullptr, share);
    if (on_patch) {
      live = result_support(d, patch);
      ++r.patch_products;
    }
    // |x| = 1: the Rayleigh quotient where the product is known (A x holds the forces' side,
    // -M^-1 K x), else |A x|.
    const double lambda = w.empty() ? sums.norm(ax) : -sums.weighted_dot(w, x, ax);
    r.omega_squared = lambda;
    r.iterations = it + 1;
    r.change = previous > 0.0 ? std::abs(lambda - previous) / lambda : 1.0;
    previous = lambda;
    if (!(lambda > 0.0)) break;
    x = ax / (w.empty() ? lambda : sums.length_in(w, ax));
  }
  r.particle = sums.largest(x);  // where the mode lives: the particle with the largest share
  if (mode) *mode = x;
  return r;
}

}  // namespace mcdyna::solver::spg
