// Kernel renewal: the adaptive anisotropic Lagrangian kernel of paper §3.1. The shape functions
// are built in a reference configuration X-hat (Eq. 33) and reused until the next renewal; every
// SMSTEP steps the reference becomes the current configuration and F^n takes up F-hat (Eq. 32).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "solver/spg/distribution.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

using Clock = std::chrono::steady_clock;

// A smoothed mass below this share of the particle's own mass (a neighbourhood whose shape
// functions nearly cancel, or only degenerate rows around it) would turn force / m into a huge
// acceleration; such a particle is integrated plainly until the next renewal.
constexpr double kMinimumSmoothedMassShare = 0.1;

// Bounds on the principal stretches of an updated-Lagrangian support relative to the initial
// one: guards against a deformation gradient that has lost its meaning, not a modelling limit
// (the support follows the particle spacing, which follows F).
constexpr double kSupportMinimumStretch = 0.02, kSupportMaximumStretch = 50.0;

Eigen::Map<Mat3> mat(Eigen::Matrix<double, 9, Eigen::Dynamic>& m, Index i) {
  return Eigen::Map<Mat3>(m.col(i).data());
}

// KERNEL 0 (Eq. 34): the initial support A0 (symmetric, particles.hpp) deformed with the
// material, S = (F A0^2 F^T)^(1/2), the left stretch of F A0, with F = F-hat F^n the total
// deformation now: the ellipsoid F A0 (unit ball) exactly, and for the box kernels the image of
// the unit box under the stretch of F A0 without its rotation. The support keeps its size relative
// to the particle spacing, which deforms the same way: compression along the axis of a Taylor bar
// shrinks it there (a support fixed in size would span many compressed layers and let them collapse
// unseen), and it widens where the material spreads. KERNEL 1 (Eulerian): the initial supports.
// Over several processes each computes the supports of its own particles and all share them.
Supports current_supports(const State& s, const Domain& d) {
  if (d.settings.kernel_update == KernelUpdate::eulerian)
    return deformed(d.settings.shape, d.particles.initial_support);
  Eigen::Matrix<double, 9, Eigen::Dynamic> shapes(9, d.count());
  const std::size_t domain = d.index;
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  const std::size_t count = members(owned, d.count());
#pragma omp parallel for schedule(static) if (count > 4096)
  for (std::size_t m = 0; m < count; ++m) {
    const Index i = member(owned, m);
    const Mat3 f = Eigen::Map<const Mat3>(d.fields.deformation.col(i).data()) *
                   Eigen::Map<const Mat3>(d.kernel.reference_deformation.col(i).data());
    const Eigen::Map<const Mat3> a0(d.particles.initial_support.col(i).data());
    const Mat3 fa = f * a0;
    Eigen::SelfAdjointEigenSolver<Mat3> eig;
    eig.computeDirect(fa * fa.transpose());
    const double scale = a0.trace() / 3.0;
    Vec3 half = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    for (int k = 0; k < 3; ++k)
      half[k] = std::clamp(half[k], kSupportMinimumStretch * scale, kSupportMaximumStretch * scale);
    mat(shapes, i) = eig.eigenvectors() * half.asDiagonal() * eig.eigenvectors().transpose();
  }
  if (share) share_columns(s, domain, shapes.data(), 9);
  return deformed(d.settings.shape, shapes);
}

// Drops the pairs whose bond is broken (Eq. 36: phi = 0 for a disconnected pair, for good).
void remove_broken_pairs(const Domain& d, NeighbourList& l) {
  if (d.diagnostics.broken_bonds == 0) return;
  std::vector<Index> offsets(l.offsets.size(), 0);
  std::size_t out = 0;
  for (Index i = 0; i < d.count(); ++i) {
    const auto first = static_cast<std::size_t>(l.offsets[static_cast<std::size_t>(i)]);
    const auto last = static_cast<std::size_t>(l.offsets[static_cast<std::size_t>(i) + 1]);
    for (std::size_t p = first; p < last; ++p) {
      const Index j = l.neighbours[p];
      if (j != i && d.kernel.bonds.is_broken(i, j)) continue;
      l.neighbours[out++] = j;
    }
    offsets[static_cast<std::size_t>(i) + 1] = static_cast<Index>(out);
  }
  l.neighbours.resize(out);
  l.offsets = std::move(offsets);
}

Transpose transpose_of(const NeighbourList& l, Index n) {
  Transpose t;
  t.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const Index j : l.neighbours)
    ++t.offsets[static_cast<std::size_t>(j) + 1];
  for (Index i = 0; i < n; ++i)
    t.offsets[static_cast<std::size_t>(i) + 1] += t.offsets[static_cast<std::size_t>(i)];
  t.pairs.resize(l.neighbours.size());
  t.rows.resize(l.neighbours.size());
  t.gather.resize(l.neighbours.size());
  t.gradient.resize(3, static_cast<Eigen::Index>(l.neighbours.size()));
  std::vector<Index> fill(t.offsets.begin(), t.offsets.end() - 1);
  for (Index row = 0; row < n; ++row)  // rows ascending: each transposed list is sorted
    for (Index p = l.offsets[static_cast<std::size_t>(row)];
         p < l.offsets[static_cast<std::size_t>(row) + 1]; ++p) {
      const auto slot = static_cast<std::size_t>(
          fill[static_cast<std::size_t>(l.neighbours[static_cast<std::size_t>(p)])]++);
      t.pairs[slot] = p;
      t.rows[slot] = row;
    }
  return t;
}

// grad phi_I(X_J) in transpose order, for the internal force.
void copy_transpose_gradients(Domain& d) {
  const Index n = d.count();
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t)
      d.kernel.transpose.gradient.col(t) =
          d.kernel.shape.gradient.col(d.kernel.transpose.pairs[static_cast<std::size_t>(t)]);
  }
}

// The renewed rows of `fresh` (lists and shape functions computed for them alone) replace
// those of the current lists; the other rows are kept as they are, in their own reference.
// ITB 1 integrates the strain gradient with the second-derivative functions.
bool second_derivatives(const Domain& d) {
  return d.settings.stabilization == Stabilization::strain_gradient;
}

void merge_rows(Domain& d, const NeighbourList& fresh, const ShapeFunctions& fresh_shape,
                const std::vector<std::uint8_t>& rows) {
  const Index n = d.count();
  NeighbourList list;
  list.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  for (Index i = 0; i < n; ++i)
    list.offsets[static_cast<std::size_t>(i) + 1] =
        list.offsets[static_cast<std::size_t>(i)] +
        (rows[static_cast<std::size_t>(i)] ? fresh.count(i) : d.kernel.list.count(i));
  const auto pairs = static_cast<std::size_t>(list.offsets.back());
  list.neighbours.resize(pairs);
  ShapeFunctions shape;
  shape.value.resize(pairs);
  shape.gradient.resize(3, static_cast<Eigen::Index>(pairs));
  const bool second = d.kernel.shape.hessian.cols() > 0;
  if (second) shape.hessian.resize(6, static_cast<Eigen::Index>(pairs));
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const bool renewed = rows[static_cast<std::size_t>(i)] != 0;
    const NeighbourList& from = renewed ? fresh : d.kernel.list;
    const ShapeFunctions& from_shape = renewed ? fresh_shape : d.kernel.shape;
    Index q = list.offsets[static_cast<std::size_t>(i)];
    for (Index p = from.offsets[static_cast<std::size_t>(i)];
         p < from.offsets[static_cast<std::size_t>(i) + 1]; ++p, ++q) {
      list.neighbours[static_cast<std::size_t>(q)] = from.neighbours[static_cast<std::size_t>(p)];
      shape.value[static_cast<std::size_t>(q)] = from_shape.value[static_cast<std::size_t>(p)];
      shape.gradient.col(q) = from_shape.gradient.col(p);
      if (second) shape.hessian.col(q) = from_shape.hessian.col(p);
    }
  }
  d.kernel.list = std::move(list);
  d.kernel.shape = std::move(shape);
}

// MC-SPG moves a smoothed particle I with u_I = sum_K T_IK u-hat_K, u-hat_K += dt sum_J
// phi_J(X_K) f_J / m_J (smoothing.cpp): its effective inverse mass is W = T S M^-1 (T_IK =
// m-hat_K phi_I(X_K) / m_I, S_KJ = phi_J(X_K), M the smoothed masses of Eq. 20), which for a
// regular neighbourhood is about 1 / m-hat on the diagonal, like a plain particle. Its row sums
// bound W's largest eigenvalue (Gershgorin): r_I = m-hat_I sum_K |T_IK| sum_J |S_KJ| / m_J.
// Measured on the FDS plate at h 0.15 (manual/verification.md): the run blew up from a torn
// particle whose smoothed mass had fallen to 0.1 m-hat (just above kMinimumSmoothedMassShare),
// at a sixth of the step its length and sound speed gave; with this factor it ran through.
// Over several processes each computes r for its own particles (their transposes are complete
// there) from the rows it reads, and the mobility of the rows it reads once every process has
// every r; the run's largest mobility is agreed on (the largest, at the lowest particle).
void update_mobility(State& s, Domain& d) {
  const Index n = d.count();
  d.kernel.mobility.assign(static_cast<std::size_t>(n), 1.0);
  if (d.settings.stabilization != Stabilization::momentum_consistent) return;
  const std::size_t domain = d.index;
  parallel::ParticleShare* share = s.ownership.split_part(domain);
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  const std::size_t count = members(owned, n);
  std::vector<double> inverse_mass_sum(static_cast<std::size_t>(n), 0.0), r(d.kernel.mobility);
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index k = 0; k < n; ++k) {
    double sum = 0.0;
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(k)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(k) + 1]; ++p) {
      const auto j =
          static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
      if (!d.kernel.pinned[j])
        sum +=
            std::abs(d.kernel.shape.value[static_cast<std::size_t>(p)]) / d.kernel.smoothed_mass[j];
    }
    inverse_mass_sum[static_cast<std::size_t>(k)] = sum;
  }
#pragma omp parallel for schedule(static) if (count > 4096)
  for (std::size_t m = 0; m < count; ++m) {
    const auto ii = static_cast<std::size_t>(member(owned, m));
    if (d.kernel.pinned[ii]) continue;
    double sum = 0.0;
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto tt = static_cast<std::size_t>(t);
      sum += std::abs(d.kernel.transpose.gather[tt]) *
             inverse_mass_sum[static_cast<std::size_t>(d.kernel.transpose.rows[tt])];
    }
    r[ii] = d.particles.mass[ii] * sum;
  }
  if (share) timed_exchange(s, domain, [&] { share_columns(s, domain, r.data(), 1); });
  // Normalised by the largest bound of the initial particle arrangement, where length / c is
  // the stable step (verified); Gershgorin alone overestimates at free surfaces, whose shape
  // functions have negative lobes (r up to 1.36 on the elastic-wave rod: 16 % more cycles for
  // no change in the result).
  if (d.diagnostics.renewals == 0)
    d.kernel.mobility_scale = std::max(1.0, *std::max_element(r.begin(), r.end()));
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    double worst = 0.0;  // row I's stress drives every particle of row I
    for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p)
      worst = std::max(
          worst,
          r[static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)])]);
    d.kernel.mobility[ii] = std::max(1.0, worst / d.kernel.mobility_scale);
  }
  // The largest over the rows read here (first of equals: the lowest particle), then over the
  // processes; a row's mobility is the same wherever it is read.
  const auto top = std::max_element(d.kernel.mobility.begin(), d.kernel.mobility.end());
  double largest = *top;
  auto at = static_cast<Index>(top - d.kernel.mobility.begin());
  if (share) {
    const std::vector<double> all = s.ownership.comm.all_gather({largest, static_cast<double>(at)});
    for (std::size_t k = 0; k < all.size(); k += 2)
      if (all[k] > largest || (all[k] == largest && static_cast<Index>(all[k + 1]) < at)) {
        largest = all[k];
        at = static_cast<Index>(all[k + 1]);
      }
  }
  if (largest > d.diagnostics.largest_mobility) {
    d.diagnostics.largest_mobility = largest;
    d.diagnostics.largest_mobility_particle = at;
    d.diagnostics.largest_mobility_time = s.time;
  }
}

}  // namespace

// Smoothed masses (Eq. 20), gathered over the transpose: m_I = sum_J m-hat_J phi_I(X_J), the
// gather weights psi_I(X_J) = m-hat_J phi_I(X_J) / m_I (Eq. 14), which particles are pinned, and
// the node masses. Run at every renewal and whenever mass scaling changed a particle mass.
// Over several processes each computes them for its own particles (their transposes are
// complete there) and every process receives every particle's.
void smooth_masses(State& s, Domain& d) {
  const Index n = d.count();
  const Stabilization mode = d.settings.stabilization;
  const std::size_t domain = d.index;
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  const std::size_t count = members(owned, n);
#pragma omp parallel for schedule(static) if (count > 4096)
  for (std::size_t k = 0; k < count; ++k) {
    const auto ii = static_cast<std::size_t>(member(owned, k));
    double m = 0.0;
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto tt = static_cast<std::size_t>(t);
      m += d.particles.mass[static_cast<std::size_t>(d.kernel.transpose.rows[tt])] *
           d.kernel.shape.value[static_cast<std::size_t>(d.kernel.transpose.pairs[tt])];
    }
    d.kernel.smoothed_mass[ii] = m;
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto tt = static_cast<std::size_t>(t);
      d.kernel.transpose.gather[tt] =
          d.particles.mass[static_cast<std::size_t>(d.kernel.transpose.rows[tt])] *
          d.kernel.shape.value[static_cast<std::size_t>(d.kernel.transpose.pairs[tt])] / m;
    }
    const bool pin = !smooths_velocity(mode) || d.particles.shared[ii] || d.kernel.isolated[ii] ||
                     (mode == Stabilization::momentum_consistent &&
                      !(m > kMinimumSmoothedMassShare * d.particles.mass[ii]));
    d.kernel.pinned[ii] = pin ? 1 : 0;
  }
  if (share) {
    std::vector<double> shared(2 * static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      shared[2 * i] = d.kernel.smoothed_mass[i];
      shared[2 * i + 1] = d.kernel.pinned[i];
    }
    timed_exchange(s, domain, [&] { share_columns(s, domain, shared.data(), 2); });
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      d.kernel.smoothed_mass[i] = shared[2 * i];
      d.kernel.pinned[i] = static_cast<std::uint8_t>(shared[2 * i + 1]);
    }
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    const bool pin = d.kernel.pinned[i] != 0;
    const auto node = static_cast<std::size_t>(d.particles.nodes[i]);
    s.nodes.smoothed[node] = pin ? 0 : (mode == Stabilization::momentum_consistent ? 1 : 2);
    // Impulses of walls and constraints on a smoothed particle act on its smoothed momentum
    // m_I u_I (Eq. 19), so they see the smoothed mass.
    s.nodes.mass[node] =
        pin ? d.particles.base_mass[i]
            : (mode == Stabilization::momentum_consistent ? d.kernel.smoothed_mass[i]
                                                          : d.particles.mass[i]);
  }
  update_mobility(s, d);
}

Eigen::Matrix3Xd particle_positions(const State& s, const Domain& d) {
  Eigen::Matrix3Xd x(3, d.count());
  for (Index i = 0; i < d.count(); ++i)
    x.col(i) = s.nodes.position.col(d.particles.nodes[static_cast<std::size_t>(i)]);
  return x;
}

void renew_kernel(State& s, Domain& d) {
  renew_kernel(s, d, {});
}

void renew_kernel(State& s, Domain& d, const std::vector<std::uint8_t>& rows) {
  const Index n = d.count();
  const bool all = rows.empty() || d.diagnostics.renewals == 0;
  auto renewed = [&](Index i) { return all || rows[static_cast<std::size_t>(i)] != 0; };
  auto start = Clock::now();
  const Eigen::Matrix3Xd x = particle_positions(s, d);
  if (d.settings.stabilization == Stabilization::strain_gradient)
    carry_stabilization(s, d, all ? std::vector<std::uint8_t>{} : rows);
  // Eq. 32: F^{n+m} = F-hat F^n; a renewed row starts again from F-hat = I.
  for (Index i = 0; i < n; ++i) {
    if (!renewed(i)) continue;
    const Mat3 total = mat(d.fields.deformation, i) * mat(d.kernel.reference_deformation, i);
    mat(d.kernel.reference_deformation, i) = total;
    mat(d.fields.deformation, i).setIdentity();
  }
  if (all)
    d.kernel.support = current_supports(s, d);  // a partial renewal has them from rows_to_renew
  std::vector<Index> degenerate;
  std::vector<std::uint8_t> damaged;  // particles that lost bonds: the stricter conditioning
  if (d.diagnostics.broken_bonds > 0) {
    damaged.assign(static_cast<std::size_t>(n), 0);
    for (Index i = 0; i < n; ++i)
      damaged[static_cast<std::size_t>(i)] = d.kernel.bonds.damage(i) > 0.0 ? 1 : 0;
  }
  const std::size_t domain = d.index;
  const parallel::ParticleShare* split = s.ownership.split_part(domain);
  const double exchanged_before = split ? split->exchange_seconds : 0.0;
  if (split) {
    // Over several processes (distribution.hpp): the particles are owned again by their current
    // positions; each process builds an equal share of the flagged rows (not by owner: the
    // rows due gather where the material flows, at the impact end of a Taylor bar, on one
    // process) and sends each to the processes that read it under the new owners.
    reown_particles(s, domain);
    std::vector<std::uint8_t> flagged(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i)
      flagged[static_cast<std::size_t>(i)] = renewed(i) ? 1 : 0;
    const std::vector<int> builder = row_builders(flagged, s.ownership.comm.size());
    std::vector<std::uint8_t> mine(static_cast<std::size_t>(n), 0);
    for (std::size_t i = 0; i < mine.size(); ++i)
      mine[i] = builder[i] == s.ownership.comm.rank() ? 1 : 0;
    NeighbourList fresh = find_neighbours(x, d.kernel.support, d.settings.shape, {}, mine);
    remove_broken_pairs(d, fresh);
    d.times.neighbours += seconds_since(start);
    start = Clock::now();
    const ShapeFunctions fresh_shape = shape_functions(x, d.kernel.support, d.settings.shape, fresh,
                                                       degenerate, damaged, second_derivatives(d));
    NeighbourList incoming;
    ShapeFunctions incoming_shape;
    std::vector<std::uint8_t> take;
    timed_exchange(s, domain, [&] {
      degenerate = share_degenerate(s, degenerate);
      redistribute_rows(s, domain, builder, fresh, fresh_shape, incoming, incoming_shape, take);
    });
    merge_rows(d, incoming, incoming_shape, take);
    for (Index i = 0; i < n; ++i)
      if (renewed(i)) d.kernel.isolated[static_cast<std::size_t>(i)] = 0;
  } else if (all) {
    d.kernel.list = find_neighbours(x, d.kernel.support, d.settings.shape);
    remove_broken_pairs(d, d.kernel.list);
    d.times.neighbours += seconds_since(start);
    start = Clock::now();
    d.kernel.shape = shape_functions(x, d.kernel.support, d.settings.shape, d.kernel.list,
                                     degenerate, damaged, second_derivatives(d));
    d.kernel.isolated.assign(static_cast<std::size_t>(n), 0);
  } else {
    NeighbourList fresh = find_neighbours(x, d.kernel.support, d.settings.shape, {}, rows);
    remove_broken_pairs(d, fresh);
    d.times.neighbours += seconds_since(start);
    start = Clock::now();
    const ShapeFunctions fresh_shape = shape_functions(x, d.kernel.support, d.settings.shape, fresh,
                                                       degenerate, damaged, second_derivatives(d));
    merge_rows(d, fresh, fresh_shape, rows);
    for (Index i = 0; i < n; ++i)
      if (renewed(i)) d.kernel.isolated[static_cast<std::size_t>(i)] = 0;
  }
  for (Index i = 0; i < n; ++i)
    if (renewed(i)) d.fields.debris[static_cast<std::size_t>(i)] = 0;
  d.kernel.transpose = transpose_of(d.kernel.list, n);
  // Over several processes the shares follow the new owners and rows; the per-row values of
  // the renewed rows are computed where the rows are read.
  if (split) share_particles(s, domain);
  const parallel::ParticleShare* share = split;
  auto read_here = [&](Index i) {
    return share == nullptr || share->stressed.flag[static_cast<std::size_t>(i)] != 0;
  };
  // The new row sees the same positions through new shape functions: its residual changes
  // without any motion, which is not work done (mode_control.cpp).
  if (d.settings.mode_control > 0.0)
    for (Index i = 0; i < n; ++i)
      if (renewed(i) && read_here(i)) d.fields.mode_residual.col(i) = mode_residual(s, d, i);
  d.diagnostics.renewed_rows +=
      all ? n : static_cast<long>(std::count(rows.begin(), rows.end(), 1));
  if (!degenerate.empty()) {
    ++d.diagnostics.degenerate_events;
    if (d.diagnostics.first_degenerate < 0) {
      d.diagnostics.first_degenerate = degenerate.front();
      d.diagnostics.first_degenerate_time = s.time;
    }
  }
  for (const Index i : degenerate)
    d.kernel.isolated[static_cast<std::size_t>(i)] = 1;

  // Characteristic length for the step: the nearest neighbour in the new reference, and no more
  // than kappa / |grad phi| of the row. The force a row's stress puts on its neighbours grows with
  // its shape-function gradients, and so does its highest frequency; in a regular row both scale
  // as 1 / h, but a row left with a few neighbours on one side (torn material under the screw)
  // has gradients many times larger at the same spacing.
  std::vector<double> gradient_norm(static_cast<std::size_t>(n), 0.0);
  copy_transpose_gradients(d);
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    if (renewed(i) && read_here(i)) {
      double nearest = std::numeric_limits<double>::infinity(), g2 = 0.0;
      for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
        const Index j = d.kernel.list.neighbours[static_cast<std::size_t>(p)];
        if (j != i) nearest = std::min(nearest, (x.col(j) - x.col(i)).norm());
        g2 += d.kernel.shape.gradient.col(p).squaredNorm();
      }
      d.kernel.length[ii] =
          std::isfinite(nearest) ? nearest : d.kernel.support.reach.col(i).minCoeff();
      gradient_norm[ii] = std::sqrt(g2);
      d.kernel.renewal_volume[ii] = d.fields.volume[ii];
    }
  }
  if (d.diagnostics.renewals == 0)
    for (Index i = 0; i < n; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      d.kernel.gradient_length_scale =
          std::max(d.kernel.gradient_length_scale, d.kernel.length[ii] * gradient_norm[ii]);
    }
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    if (renewed(i) && read_here(i) && gradient_norm[ii] > 0.0)
      d.kernel.length[ii] =
          std::min(d.kernel.length[ii], d.kernel.gradient_length_scale / gradient_norm[ii]);
  }
  if (d.settings.stabilization == Stabilization::strain_gradient)
    stabilization_moments(s, d, all ? std::vector<std::uint8_t>{} : rows);
  // After the moments: ITB 1's lengths include its stabilisation's stiffness.
  if (d.settings.step_estimate == StepEstimate::eigenvalue) update_stiffness_length(s, d);
  smooth_masses(s, d);
  if (d.diagnostics.renewals == 0)
    d.kernel.step_bound.initial_critical = calibrate_stiffness_length(s, d);
  d.kernel.steps_since_renewal = 0;
  ++d.diagnostics.renewals;
  d.times.shape_functions +=
      seconds_since(start) - (share ? share->exchange_seconds - exchanged_before : 0.0);
}

void keep_read_rows(State& s, Domain& d) {
  const parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const Index n = d.count();
  std::vector<std::uint8_t> dropped(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < dropped.size(); ++i)
    dropped[i] = share->stressed.flag[i] ? 0 : 1;
  NeighbourList none;
  none.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  ShapeFunctions no_shape;
  no_shape.gradient.resize(3, 0);
  merge_rows(d, none, no_shape, dropped);
  d.kernel.transpose = transpose_of(d.kernel.list, n);
  copy_transpose_gradients(d);
  smooth_masses(s, d);
}

// Why the updated-Lagrangian kernel is not renewed at every check: a renewal takes the current
// positions as the reference, including their particle-scale (odd-even) part, which direct
// nodal integration does not see and MC-SPG smoothing only attenuates. On such a perturbed
// reference the integration constraint sum_J V_J grad phi_I(X_J) = 0 no longer holds, and a
// uniform tension then pushes the perturbation further (the tensile instability of Eulerian and
// frequently updated kernels). Measured on the h = 0.1 elastic-wave rod (1 % strain): renewing
// every 15 steps lets it grow about 1.8x per renewal interval and the free-end error reaches
// 1.7; keeping the reference while the kernel is mildly deformed gives 0.015, as without
// renewal. Large deformation still renews as often as every SMSTEP steps.
Index rows_to_renew(const State& s, Domain& d, bool bonds_broke, std::vector<std::uint8_t>& rows) {
  const Index n = d.count();
  rows.assign(static_cast<std::size_t>(n), 0);
  if (d.settings.kernel_update == KernelUpdate::eulerian || !(d.settings.renewal_strain > 0.0)) {
    std::fill(rows.begin(), rows.end(), 1);
    return n;
  }
  const auto start = Clock::now();
  const double limit = d.settings.renewal_strain;
  // Renewing folds F-hat into F^n, which leaves F-hat F^n and so these supports as they are:
  // the partial renewal that may follow uses them.
  d.kernel.support = current_supports(s, d);
  const Supports& support = d.kernel.support;
  const Eigen::Matrix3Xd& x = s.nodes.position;
  const KernelShape shape = d.settings.shape;
  // Over several processes each decides for its own rows, and all share the decisions.
  const std::size_t domain = d.index;
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  const std::size_t decided = members(owned, n);
  std::vector<double> decision(static_cast<std::size_t>(n), 0.0);
#pragma omp parallel for schedule(static) if (decided > 4096)
  for (std::size_t m = 0; m < decided; ++m) {
    const Index i = member(owned, m);
    const auto ii = static_cast<std::size_t>(i);
    const Eigen::Map<const Mat3> f(d.fields.deformation.col(i).data());
    const Mat3 green = 0.5 * (f.transpose() * f - Mat3::Identity());
    // Under compression (pressure > 0) the tensile instability that argues against renewing
    // (the note above) does not arise, and compression is what crowds a Lagrangian
    // kernel's neighbours together: renew there at a fifth of the limit.
    const double strain = green.norm();
    bool renew = strain > limit ||
                 (d.fields.pressure[ii] > 0.0 && strain > kCompressionRenewalShare * limit) ||
                 d.fields.debris[ii];
    // A row is also rebuilt when it holds a pair whose bond broke (Eq. 36), or a neighbour that
    // has left its support by more than the strain limit: F-hat weights such a far neighbour
    // so little that it does not show in the Green strain, yet the pair would keep the two
    // particles connected (across a crack whose bonds at the other rows all broke) for good.
    const Vec3 xi = x.col(d.particles.nodes[ii]);
    for (Index p = d.kernel.list.offsets[ii]; !renew && p < d.kernel.list.offsets[ii + 1]; ++p) {
      const Index j = d.kernel.list.neighbours[static_cast<std::size_t>(p)];
      if (j == i) continue;
      const Vec3 z =
          support.matrix(j) * (xi - x.col(d.particles.nodes[static_cast<std::size_t>(j)]));
      renew =
          unit_distance(shape, z) > 1.0 + limit || (bonds_broke && d.kernel.bonds.is_broken(i, j));
    }
    decision[ii] = renew ? 1.0 : 0.0;
  }
  if (share) share_columns(s, domain, decision.data(), 1);
  Index count = 0;
  for (Index i = 0; i < n; ++i) {
    rows[static_cast<std::size_t>(i)] = decision[static_cast<std::size_t>(i)] != 0.0 ? 1 : 0;
    count += rows[static_cast<std::size_t>(i)];
  }
  d.times.neighbours += seconds_since(start);
  return count;
}

void initialise(State& s, Domain& d) {
  const Index n = d.count();
  d.kernel.reference_deformation.resize(9, n);
  d.fields.deformation.resize(9, n);
  for (Index i = 0; i < n; ++i) {
    mat(d.kernel.reference_deformation, i).setIdentity();
    mat(d.fields.deformation, i).setIdentity();
  }
  d.fields.debris.assign(static_cast<std::size_t>(n), 0);
  d.fields.mode_stiffness.assign(static_cast<std::size_t>(n), 0.0);
  d.fields.mode_residual.setZero(3, n);
  d.fields.mode_energy.assign(static_cast<std::size_t>(n), 0.0);
  d.fields.mode_force.setZero(3, n);
  d.kernel.smoothed_mass.assign(static_cast<std::size_t>(n), 0.0);
  d.kernel.pinned.assign(static_cast<std::size_t>(n), 0);
  d.kernel.length.assign(static_cast<std::size_t>(n), 0.0);
  d.fields.step.assign(static_cast<std::size_t>(n), 0.0);
  d.kernel.renewal_volume = d.fields.volume;
  d.fields.stress_gradient.setZero(9, n);
  d.fields.unsmoothed.resize(3, n);
  for (Index i = 0; i < n; ++i)
    d.fields.unsmoothed.col(i) =
        s.nodes.velocity.col(d.particles.nodes[static_cast<std::size_t>(i)]);
  d.fields.unsmoothed_previous = d.fields.unsmoothed;
  d.fields.smoothed = d.fields.unsmoothed;
  renew_kernel(s, d);
  d.kernel.bonds = initial_bonds(d);
}

}  // namespace mcdyna::solver::spg
