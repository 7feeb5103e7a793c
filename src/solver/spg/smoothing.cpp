// Velocity update and smoothing of MC-SPG (paper §2, Eqs. 13-31).
//
// With S_IJ = phi_J(X_I) (scatter, Eq. 18/30) and T_IJ = psi_I(X_J) = m-hat_J phi_I(X_J) / m_I
// (gather, Eq. 14), m-hat_I S_IJ = m_J T_JI. The update
//   u-hat_I += dt sum_J phi_J(X_I) a_J,  a_J = f_J / m_J          (Eq. 30, m_J of Eq. 20)
// is m-hat u-hat += dt T^T f, so sum m-hat u-hat changes by dt sum_J f_J (sum_I T_JI = 1):
// linear momentum is kept to round-off (Eq. 31). The particles move with u_I = sum_J T_IJ u-hat_J
// (Eqs. 13, 25, 28). Pinned particles (shared with FE elements, constrained, or with a
// degenerate neighbourhood) keep one plain velocity v_c, smoothed as the identity: the block form
// of the same argument gives them M_c v_c += dt (f_c + m-hat_c sum_J phi_J(X_c) a_J) over the
// smoothed J, which keeps total momentum exact for coupled FE/SPG models as well.
#include <chrono>
#include <cmath>
#include <limits>

#include "solver/spg/distribution.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

// PDAMP: particle-to-particle damping of the smoothed particles' unsmoothed velocities. Each
// row pair (I, J) exchanges the central impulse k ((u-hat_J - u-hat_I) . e) e, e the unit vector
// from x_I to x_J, equal and opposite: linear and angular momentum are kept, translation and
// rigid rotation are not damped (their relative velocity is normal to e), and
// k = |PDAMP| mu_IJ / n_I (mu the reduced mass, n_I the neighbours of I) removes about |PDAMP|
// of I's normal velocity difference to its neighbours per step. The impulses are taken from
// the velocities of the previous half step, so particle I sums, in its own pass of the velocity
// update, the impulses of its row's pairs (I, J) and, over its transpose, minus those of the
// pairs (J, I): each pair is computed twice with the same arithmetic (the same bits at both
// ends), which costs less than storing 24 bytes per pair and reading them back in transpose
// order (measured, issue 46: 14 % fewer instructions in the pass but 1.8 % slower, the
// transposed read being a scattered gather from a 12 MB array; manual/verification.md).
// ((u_J - u_I) . e) e = ((u_J - u_I) . r) r / |r|^2 for r = x_J - x_I: one division, no root.
struct PairEnd {
  Vec3 position, velocity;  ///< x and the previous u-hat
  double mass = 0.0;        ///< m-hat
  double share = 0.0;       ///< |PDAMP| / n of the row the pair belongs to (used for I)
};

// Particle i's end, from the column pack_pair_ends filled for it.
PairEnd pair_end(const Domain& d, Index i) {
  const auto e = d.scratch.damping_ends.col(i);
  return {e.head<3>(), e.segment<3>(3), e(6), e(7)};
}

// Every particle's end packed in one column (x through the particle's node, the previous u-hat,
// m-hat, and |PDAMP| / n of its row: 64 bytes), once per cycle rather than gathered from four
// arrays and a node index at each of the ~50 pairs that read it.
void pack_pair_ends(const State& s, Domain& d) {
  const Index n = d.count();
  d.scratch.damping_ends.resize(8, n);
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    auto e = d.scratch.damping_ends.col(i);
    e.head<3>() = s.nodes.position.col(d.particles.nodes[ii]);
    e.segment<3>(3) = d.fields.unsmoothed_previous.col(i);
    e(6) = d.particles.mass[ii];
    e(7) = d.settings.damping / static_cast<double>(std::max<Index>(d.kernel.list.count(i) - 1, 1));
  }
}

// The impulse of the pair (I, J) of row I on I.
inline Vec3 pair_impulse(const PairEnd& i, const PairEnd& j) {
  const Vec3 r = j.position - i.position;
  const double r2 = r.squaredNorm();
  if (!(r2 > 0.0)) return Vec3::Zero();  // coincident: no direction to damp along
  const double along = (j.velocity - i.velocity).dot(r);
  return (i.share * i.mass * j.mass * along / ((i.mass + j.mass) * r2)) * r;
}

// The particles a process advances: its own over several processes (distribution.hpp), else all
// (null).
const ParticleSubset* advanced_particles(const parallel::ParticleShare* share) {
  return share ? &share->owned : nullptr;
}

}  // namespace

Index advance_velocities(State& s, Domain& d, const Eigen::Matrix3Xd& force, double dt) {
  const auto start = std::chrono::steady_clock::now();
  Nodes& nd = s.nodes;
  const Index n = d.count();
  parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const ParticleSubset* mine = advanced_particles(share);
  const std::size_t advanced = members(mine, n);
  const double exchanged = share ? share->exchange_seconds : 0.0;  // before this update
  const Stabilization mode = d.settings.stabilization;
  const bool mc = mode == Stabilization::momentum_consistent;
  const bool damping = d.settings.damping > 0.0 && smooths_velocity(mode);
  // The previous u-hat of the particles whose u-hat is current here (all on one process).
  const ParticleSubset* current = share ? &share->current : nullptr;
  const std::size_t kept = members(current, n);
  for (std::size_t m = 0; m < kept; ++m) {
    const Index i = member(current, m);
    d.fields.unsmoothed_previous.col(i) = d.fields.unsmoothed.col(i);
  }
  // Accelerations of the smoothed particles (zero for pinned ones).
  Eigen::Matrix3Xd& acc = d.scratch.acceleration;
  acc.resize(3, n);
  if (smooths_velocity(mode)) {
#pragma omp parallel for schedule(static, 256) if (advanced > 512)
    for (std::size_t m = 0; m < advanced; ++m) {
      const Index i = member(mine, m);
      const auto ii = static_cast<std::size_t>(i);
      if (d.kernel.pinned[ii]) {
        acc.col(i).setZero();
        continue;
      }
      acc.col(i) = force.col(d.particles.nodes[ii]) /
                   (mc ? d.kernel.smoothed_mass[ii] : d.particles.mass[ii]);
      nd.acceleration.col(d.particles.nodes[ii]) = acc.col(i);
    }
    if (share) exchange_columns(*share, share->row_ghosts, acc);  // a_J of Eq. 30 over the rows
  }
  // Over the rows: u-hat_I += dt sum_J phi_J(X_I) a_J (Eqs. 29-30; `direct`: dt a_I), and the
  // PDAMP impulses of I's pairs at both ends; a pinned particle takes its share of the smoothed
  // accelerations into its one (node) velocity, which is also its u-hat in the smoothing.
  // PDAMP: the kinetic energy of the unsmoothed velocities taken out, per particle, summed in
  // particle order after the loop (an OpenMP reduction would round differently for each
  // thread count) with core::ExactSum (over processes as well).
  if (damping) {
    pack_pair_ends(s, d);
    d.scratch.damping_removed.assign(static_cast<std::size_t>(n), 0.0);
  }
  if (smooths_velocity(mode)) {
#pragma omp parallel for schedule(static, 256) if (advanced > 512)
    for (std::size_t m = 0; m < advanced; ++m) {
      const Index i = member(mine, m);
      const auto ii = static_cast<std::size_t>(i);
      const bool free_i = d.kernel.pinned[ii] == 0;
      const bool damp_i = damping && free_i;
      const PairEnd end_i = damp_i ? pair_end(d, i) : PairEnd{};
      Vec3 sum = Vec3::Zero(), own = Vec3::Zero();
      for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
        const auto pp = static_cast<std::size_t>(p);
        const Index j = d.kernel.list.neighbours[pp];
        if (mc) sum += d.kernel.shape.value[pp] * acc.col(j);
        if (damp_i && j != i && !d.kernel.pinned[static_cast<std::size_t>(j)])
          own += pair_impulse(end_i, pair_end(d, j));
      }
      if (!mc) sum = acc.col(i);
      if (free_i) {
        d.fields.unsmoothed.col(i) += dt * sum;
      } else {
        const auto node = static_cast<std::size_t>(d.particles.nodes[ii]);
        if (mc)
          nd.velocity.col(d.particles.nodes[ii]) +=
              dt * d.particles.mass[ii] * sum / (nd.mass[node] + nd.added_mass[node]);
        d.fields.unsmoothed.col(i) = nd.velocity.col(d.particles.nodes[ii]);
      }
      if (!damp_i) continue;
      // The other end: I receives minus the impulses of the pairs (J, I) of the rows it is in.
      Vec3 total = own;
      for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
        const Index j = d.kernel.transpose.rows[static_cast<std::size_t>(t)];
        if (j != i && !d.kernel.pinned[static_cast<std::size_t>(j)])
          total -= pair_impulse(pair_end(d, j), end_i);
      }
      const Vec3 undamped = d.fields.unsmoothed.col(i);
      d.fields.unsmoothed.col(i) += total / d.particles.mass[ii];
      d.scratch.damping_removed[ii] =
          0.5 * d.particles.mass[ii] *
          (undamped.squaredNorm() - d.fields.unsmoothed.col(i).squaredNorm());
    }
  } else {
    for (std::size_t m = 0; m < advanced; ++m) {  // plain nodal integration: all pinned
      const Index i = member(mine, m);
      d.fields.unsmoothed.col(i) = nd.velocity.col(d.particles.nodes[static_cast<std::size_t>(i)]);
    }
  }
  if (share)
    exchange_columns(*share, share->column_ghosts, d.fields.unsmoothed);  // Eq. 13's u-hat_J
  if (damping) {  // an exact sum: the same bits whichever process holds which particle
    core::ExactSum removed;
    for (std::size_t m = 0; m < advanced; ++m)
      removed.add(d.scratch.damping_removed[static_cast<std::size_t>(member(mine, m))]);
    d.fields.damping_energy += share ? s.ownership.comm.sum(removed) : removed.value();
  }

  // Smoothing: the node velocity of every smoothed particle (Eq. 13 or, for `direct`, Eq. 7),
  // from u-hat only (which holds the pinned particles' node velocities).
  const Eigen::Matrix3Xd& source = d.fields.unsmoothed;
  Index bad = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static, 256) reduction(min : bad) if (advanced > 512)
  for (std::size_t m = 0; m < advanced; ++m) {
    const Index i = member(mine, m);
    const auto ii = static_cast<std::size_t>(i);
    Vec3 u = source.col(i);
    if (!d.kernel.pinned[ii] && mc) {
      u = gathered(d, i, source);
    } else if (!d.kernel.pinned[ii] && mode == Stabilization::direct) {
      u.setZero();
      for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
        const auto pp = static_cast<std::size_t>(p);
        u += d.kernel.shape.value[pp] * source.col(d.kernel.list.neighbours[pp]);
      }
    }
    d.fields.smoothed.col(i) = u;
    nd.velocity.col(d.particles.nodes[ii]) = u;
    if (!std::isfinite(u.sum())) bad = std::min(bad, d.particles.nodes[ii]);
  }
  d.times.smoothing += seconds_since(start) - (share ? share->exchange_seconds - exchanged : 0.0);
  return bad == std::numeric_limits<Index>::max() ? -1 : bad;
}

void absorb_constraints(State& s, Domain& d) {
  const Nodes& nd = s.nodes;
  const Index n = d.count();
  parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const ParticleSubset* mine = advanced_particles(share);
  const std::size_t advanced = members(mine, n);
  // The change each constraint or wall made to a smoothed particle's velocity, as an impulse
  // p_I = m_I change_I on that particle: set for its own particles (zero for pinned ones), and
  // for the row ghosts by the exchange below; no other entry is read.
  Eigen::Matrix3Xd& change = d.scratch.change;
  change.resize(3, n);
  bool any = false;
  for (std::size_t m = 0; m < advanced; ++m) {
    const Index i = member(mine, m);
    const auto ii = static_cast<std::size_t>(i);
    const Vec3 v = nd.velocity.col(d.particles.nodes[ii]);
    if (d.kernel.pinned[ii]) {
      d.fields.unsmoothed.col(i) = v;
      change.col(i).setZero();
    } else {
      change.col(i) = v - d.fields.smoothed.col(i);
      any = any || change.col(i).squaredNorm() > 0.0;
    }
    d.fields.smoothed.col(i) = v;
  }
  if (share) {  // every process takes part in the exchange when any particle changed
    any = s.ownership.comm.bitwise_or(any ? 1U : 0U) != 0;
    if (any) exchange_columns(*share, share->row_ghosts, change);
  }
  // PDAMP's pairs read next cycle the row partners' u-hat as this cycle leaves it: the ghosts'
  // again from their owners, after what the conditions changed (pinned and smoothed).
  const bool damping =
      share && d.settings.damping > 0.0 && smooths_velocity(d.settings.stabilization);
  if (!any) {
    if (damping) exchange_columns(*share, share->column_ghosts, d.fields.unsmoothed);
    return;
  }
  if (d.settings.stabilization == Stabilization::direct) {
    for (std::size_t m = 0; m < advanced; ++m) {
      const Index i = member(mine, m);
      d.fields.unsmoothed.col(i) += change.col(i);
    }
    return;
  }
  // MC-SPG: an impulse enters like a force (Eq. 30), u-hat_J += sum_I phi_I(X_J) p_I / m_I, so
  // total momentum changes by exactly the impulses and the wall's reaction is the momentum it
  // takes. The smoothed velocity follows over the next steps; this step the particle moves
  // with the constrained velocity (no penetration). The share that falls on pinned particles
  // is not applied (they have their own constraints and FE forces).
#pragma omp parallel for schedule(static, 256) if (advanced > 512)
  for (std::size_t m = 0; m < advanced; ++m) {
    const Index j = member(mine, m);
    const auto jj = static_cast<std::size_t>(j);
    if (d.kernel.pinned[jj]) continue;
    Vec3 sum = Vec3::Zero();
    for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      sum += d.kernel.shape.value[pp] * change.col(d.kernel.list.neighbours[pp]);
    }
    d.fields.unsmoothed.col(j) += sum;
  }
  if (damping) exchange_columns(*share, share->column_ghosts, d.fields.unsmoothed);
}

SmoothedKinetic smoothed_kinetic(const State& s, const Domain& d) {
  SmoothedKinetic k;
  for (Index i = 0; i < d.count(); ++i) {
    const auto ii = static_cast<std::size_t>(i);
    if (s.nodes.smoothed[static_cast<std::size_t>(d.particles.nodes[ii])] != 1) continue;
    const double m = d.particles.mass[ii];
    k.kinetic += 0.5 * m * d.fields.unsmoothed_previous.col(i).dot(d.fields.unsmoothed.col(i));
    k.momentum += 0.5 * m * (d.fields.unsmoothed_previous.col(i) + d.fields.unsmoothed.col(i));
    k.mass += m;
  }
  return k;
}

}  // namespace mcdyna::solver::spg
