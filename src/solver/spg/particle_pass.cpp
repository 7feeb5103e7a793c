// Direct nodal integration at the particles (paper Eqs. 5-6) in the current reference
// configuration: F-hat from Eq. 33, the velocity gradient of the smoothed velocity, the
// updated-Lagrangian stress of the FE materials at one point per particle, density and volume
// from Eqs. 26-27, and the internal force f_I = -sum_J w_J sigma_J grad_x phi_I(X_J), gathered
// over the transposed neighbour lists so every particle writes only its own node.
#include <chrono>
#include <cmath>
#include <limits>
#include <variant>

#include "solver/material/constitutive.hpp"
#include "solver/spg/distribution.hpp"
#include "solver/spg/pair_sums.hpp"
#include "solver/spg/smallest_stretch.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

using Clock = std::chrono::steady_clock;

struct Outcome {
  double step = std::numeric_limits<double>::infinity();
  double physical_step = std::numeric_limits<double>::infinity();  ///< before mass scaling
  bool inverted = false;
  bool released = false;
  bool mass_added = false;
};

// Mass scaling (DT2MS), as LS-DYNA scales element masses: a particle whose step is below the
// target asks for the mass factor that brings it there; added mass never decreases. In MC-SPG a
// particle moves with its smoothed mass m_I = sum_J m-hat_J phi_I(X_J) (Eq. 20), so the factor
// is given to every particle of its row (grow_row_masses): scaling the particle alone changes
// m_I by its own weight only and leaves its step where it was (measured: the FDS plate blew up
// at 41 us with a 9e-9 s target that way). Returns the step with the masses the row has.
void scale_particle_mass(const State& s, Domain& d, Index j, Outcome& o) {
  const double target = s.mass_scaling_dt;
  if (!(target > 0.0) || !std::isfinite(o.step)) return;
  const auto jj = static_cast<std::size_t>(j);
  double factor = std::numeric_limits<double>::infinity();  // the row's smallest mass factor
  for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p)
    factor = std::min(factor, d.scratch.mass_factor[static_cast<std::size_t>(
                                  d.kernel.list.neighbours[static_cast<std::size_t>(p)])]);
  const double scale = s.time_control.scale_factor;
  const double with_added = o.step * std::sqrt(std::isfinite(factor) ? factor : 1.0);
  if (scale * with_added >= target) {
    o.step = with_added;
    return;
  }
  const double ratio = target / (scale * o.step);
  d.particles.mass_request[jj] = ratio * ratio;
  o.step = target / scale;
  o.mass_added = true;
}

// m / (m - added) of every particle, once per pass rather than once for every row it is in
// (25 rows per particle on the FDS plate: 25 divisions per particle and cycle).
void mass_factors(Domain& d) {
  const Index n = d.count();
  d.scratch.mass_factor.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    d.scratch.mass_factor[kk] =
        d.particles.mass[kk] / (d.particles.mass[kk] - d.particles.added_mass[kk]);
  }
}

// Every particle takes the largest factor asked for by the rows it is in (over the transpose);
// over several processes each takes its own particles (`owned`), then they share the masses.
void grow_row_masses(Domain& d, const ParticleSubset* owned) {
  const std::size_t count = members(owned, d.count());
#pragma omp parallel for schedule(static, 256) if (count > 512)
  for (std::size_t m = 0; m < count; ++m) {
    const Index k = member(owned, m);
    const auto kk = static_cast<std::size_t>(k);
    double factor = 0.0;
    for (Index t = d.kernel.transpose.offsets[kk]; t < d.kernel.transpose.offsets[kk + 1]; ++t)
      factor = std::max(factor, d.particles.mass_request[static_cast<std::size_t>(
                                    d.kernel.transpose.rows[static_cast<std::size_t>(t)])]);
    const double physical = d.particles.mass[kk] - d.particles.added_mass[kk];
    const double added = factor * physical - d.particles.mass[kk];
    if (!(added > 0.0)) continue;
    d.particles.mass[kk] += added;
    d.particles.base_mass[kk] += added;
    d.particles.added_mass[kk] += added;
  }
  std::fill(d.particles.mass_request.begin(), d.particles.mass_request.end(), 0.0);
}

// A particle that has lost bonds (Eq. 36) and whose neighbourhood then inverts is debris of the
// failed material: what is left of its row is one-sided and no longer measures a deformation.
// It carries no stress from then on, like an eroded element, until its row is renewed at the
// next check (rows_to_renew); every other inversion is an instability and stops the run.
Outcome release_or_invert(Domain& d, Index j) {
  // Designated fields: a positional {0.0, true, false} silently shifted when physical_step was
  // added (an inversion then read as a zero step, a release as an inversion).
  if (!d.settings.bond_failure || !(d.kernel.bonds.damage(j) > 0.0))
    return {.step = 0.0, .inverted = true};
  d.fields.debris[static_cast<std::size_t>(j)] = 1;
  d.fields.stress_gradient.col(j).setZero();
  return {.released = true};
}

// The length that bounds particle j's step, times the smallest principal stretch of F-hat
// since the renewal: for an affine motion of the support every neighbour distance |F-hat dX| is
// at least sigma_min |dX|, and the current gradients F-hat^-T grad phi at most
// |grad phi| / sigma_min, so this follows the most compressed direction: under the flat screw
// tip at h 0.125 the rows are squeezed axially (stretch ~0.6, volume ratio ~0.8) and the
// isotropic length L (V / V_renewal)^(1/3) overestimated the stable step enough to blow the
// plate up at 7.4 us (TSSFAC 0.9; it ran at 0.6).
//   nearest_neighbour: the nearest-neighbour distance at the renewal, capped by the isotropic
//     length (the verified default; far too strict for squeezed pairs, manual/verification.md)
//   eigenvalue: the stiffness length (stiffness_length.cpp), scaled every second cycle to the
//     largest eigenvalue of the linearised equations
double step_length(const Domain& d, Index j, const Mat3& f_hat, double isotropic_length) {
  const double smallest = smallest_stretch(f_hat);
  const auto jj = static_cast<std::size_t>(j);
  if (d.settings.step_estimate == StepEstimate::eigenvalue)
    return d.kernel.step_bound.lengths[jj] * smallest;
  return std::min(isotropic_length, d.kernel.length[jj] * smallest);
}

// Stress update of particle j over `dt`; leaves w sigma F-hat^-T in d.fields.stress_gradient.
template <class Model>
Outcome particle_update(State& s, Domain& d, const Material& mat, const Model& model, Index j,
                        double dt) {
  const auto jj = static_cast<std::size_t>(j);
  Eigen::Map<Mat3> f_hat(d.fields.deformation.col(j).data());
  Eigen::Map<Mat3> p_j(d.fields.stress_gradient.col(j).data());
  if (d.kernel.isolated[jj] || d.fields.debris[jj]) {  // no strain measurable, no stress carried
    p_j.setZero();
    return {};
  }
  const ParticleKinematics pk = particle_kinematics(s, d, j, d.settings.objective ? 0.5 * dt : 0.0);
  if (!pk.invertible) return release_or_invert(d, j);
  f_hat = pk.deformation;
  const Mat3& f_inv = pk.inverse;
  const Mat3& l = pk.velocity_gradient;
  double la[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      la[a][b] = l(a, b);
  Kinematics k = kinematics_from_gradient(la);
  k.objective = d.settings.objective;

  // Eq. 26-27: rho^{n+1} = rho^n (1 - dt div v), V = m / rho. OSU 1, whose div v is that of
  // the mid-step configuration: the trapezoidal form rho^{n+1} (1 + dt/2 div v) =
  // rho^n (1 - dt/2 div v), second order where Eq. 26 is first (a spinning, ringing block
  // otherwise keeps a first-order energy error, objective_update_test.cpp).
  const double half = k.objective ? 0.5 * dt : 0.0;
  const double grow = 1.0 + half * k.trace;
  const double shrink = (1.0 - (dt - half) * k.trace) / grow;
  if (!(shrink > 0.0) || !(grow > 0.0)) return release_or_invert(d, j);
  const double volume = d.fields.volume[jj] / shrink;

  // Deviator and volumetric state, as at an FE integration point (point_kinematics.hpp).
  double* dev = d.fields.points.deviator.col(j).data();
  double* alpha =
      d.fields.points.back_stress.size() > 0 ? d.fields.points.back_stress.col(j).data() : nullptr;
  bool failed = false;
  const bool gradient = d.settings.stabilization == Stabilization::strain_gradient;
  double modified_shear = 0.0;
  const double dev_work =
      work_volume(k.objective, d.fields.volume[jj], volume) *
      deviatoric_point_update(
          mat, model, k, dt, d.fields.temperature[jj], d.fields.pressure[jj],
          PointState{dev, alpha, d.fields.points.plastic_strain[jj], d.fields.points.damage[jj]},
          failed, gradient ? &modified_shear : nullptr);
  if (failed) d.fields.failed[jj] = 1;
  const double length = d.kernel.length[jj] * std::cbrt(volume / d.kernel.renewal_volume[jj]);
  const PointVolumetrics vol = volumetric_point_update(
      mat, d.settings.bulk_viscosity, d.particles.initial_volume[jj], d.fields.volume[jj], volume,
      k.trace, dt, dev_work, length,
      VolumetricState{d.fields.pressure[jj], d.fields.eos_energy[jj], d.fields.temperature[jj],
                      d.fields.viscosity[jj], d.fields.internal_energy[jj]},
      k.objective);
  d.fields.volume[jj] = volume;
  bool zero_dev = vol.zero_deviator;
  if (d.fields
          .failed[jj]) {  // material failure (FS on MAT_003/024, JC damage): no shear, no tension
    zero_dev = true;
    d.fields.pressure[jj] = std::max(d.fields.pressure[jj], 0.0);
  }
  if (zero_dev)
    for (int c = 0; c < 6; ++c)
      dev[c] = 0.0;

  // w sigma F-hat^-T, w = V (times MSFAC on the surface): f_I = -sum_J (w sigma F^-T)_J grad phi.
  const double pq = d.fields.pressure[jj] + vol.viscosity;
  Mat3 sigma;
  sigma << dev[0] - pq, dev[3], dev[5], dev[3], dev[1] - pq, dev[4], dev[5], dev[4], dev[2] - pq;
  const double weight = volume * (d.particles.surface[jj] ? d.settings.surface_factor : 1.0);
  p_j = weight * sigma * f_inv.transpose();
  d.fields.mode_stiffness[jj] =
      d.particles.mass[jj] * vol.sound * vol.sound / (length * length);  // rho c^2 h
  double step = element_step(d.settings.bulk_viscosity, step_length(d, j, f_hat, length), vol.sound,
                             k.trace) /
                std::sqrt(d.kernel.mobility[jj]);
  if (gradient) {  // ITB 1: what the stabilisation pass needs, and its stiffer step
    GradientStabilization& g = d.fields.gradient;
    g.shear[jj] = modified_shear;
    g.bulk[jj] =
        std::max(vol.density * vol.wave_speed_squared - 4.0 / 3.0 * mat.shear_modulus, 0.0);
    step *= g.step_scale;
  }
  Outcome o{.step = step, .physical_step = step};
  scale_particle_mass(s, d, j, o);
  return o;
}

// Over several processes each pass saw its own rows: all take the smallest step with the lowest
// particle (as one process's ascending loop keeps it), the lowest inverted and non-finite
// particles, the sum of the releases (owned particles only) and whether any mass was added.
void agree_on_pass(const core::Communicator& comm, double& best, Index& controlling,
                   double& best_physical, Index& controlling_physical, Index& inverted,
                   Index& non_finite, long& released, int& mass_added) {
  const std::vector<double> mine = {best,
                                    static_cast<double>(controlling),
                                    best_physical,
                                    static_cast<double>(controlling_physical),
                                    static_cast<double>(inverted),
                                    static_cast<double>(non_finite),
                                    static_cast<double>(released),
                                    static_cast<double>(mass_added)};
  const std::vector<double> all = comm.all_gather(mine);
  auto lower = [](double value, double index, double& best_value, Index& best_index) {
    if (value < best_value ||
        (value == best_value && index >= 0.0 && (best_index < 0 || index < best_index))) {
      best_value = value;
      best_index = static_cast<Index>(index);
    }
  };
  best = best_physical = std::numeric_limits<double>::infinity();
  controlling = controlling_physical = -1;
  released = 0;
  mass_added = 0;
  for (std::size_t p = 0; p < all.size(); p += mine.size()) {
    lower(all[p], all[p + 1], best, controlling);
    lower(all[p + 2], all[p + 3], best_physical, controlling_physical);
    inverted = std::min(inverted, static_cast<Index>(all[p + 4]));
    non_finite = std::min(non_finite, static_cast<Index>(all[p + 5]));
    released += static_cast<long>(all[p + 6]);
    mass_added = std::max(mass_added, static_cast<int>(all[p + 7]));
  }
}

}  // namespace

ParticleKinematics particle_kinematics(const State& s, const Domain& d, Index j, double half_step) {
  const auto jj = static_cast<std::size_t>(j);
  const Eigen::Matrix3Xd& x = s.nodes.position;
  const Eigen::Matrix3Xd& v = s.nodes.velocity;
  const Index node_j = d.particles.nodes[jj];
  // F-hat and the reference velocity gradient from differences to particle j (sum grad phi = 0
  // makes them equal to Eq. 33's sums, with less round-off); both sums at once (pair_sums.hpp).
  double fs[9], ls[9];
  const Index* nodes = d.particles.nodes.data();
  const Index* neighbours = d.kernel.list.neighbours.data();
  pairs::row_gradients(
      x.data(), v.data(), x.col(node_j).data(), v.col(node_j).data(),
      d.kernel.shape.gradient.data(), d.kernel.list.offsets[jj], d.kernel.list.offsets[jj + 1],
      [&](Index p) { return nodes[neighbours[p]]; }, fs, ls);
  const Mat3 f = Eigen::Map<const Mat3>(fs), lr = Eigen::Map<const Mat3>(ls);
  ParticleKinematics k;
  k.deformation = f;
  k.invertible = f.determinant() > 0.0;
  if (k.invertible) {
    k.inverse = f.inverse();
    if (half_step > 0.0) {
      const Mat3 mid = f - half_step * lr;
      k.invertible = mid.determinant() > 0.0;
      if (k.invertible) k.velocity_gradient = lr * mid.inverse();
    } else {
      k.velocity_gradient = lr * k.inverse;
    }
  }
  return k;
}

ParticlePassResult particle_pass(State& s, Domain& d, double step, Eigen::Matrix3Xd& force) {
  const std::size_t domain = d.index;
  std::vector<std::uint8_t> renewed;  // the rows renewed at this cycle's check, if any
  if (d.kernel.steps_since_renewal >= d.settings.renewal_interval) {
    // Over several processes each first receives what the check reads of every particle, so
    // the check and the renewal run whole and alike everywhere (distribution.hpp).
    timed_exchange(s, domain, [&] { synchronise(s, domain, Scope::check); });
    const auto bonds_start = Clock::now();
    const long broke = break_bonds(s, d);
    d.times.bonds += seconds_since(bonds_start);
    const Index due = rows_to_renew(s, d, broke > 0, renewed);  // timed as neighbour search
    // A renewal over several processes owns the particles again (distribution.hpp); each then
    // receives what the particles it now reads carry from their previous owners.
    const parallel::ParticleShare* split = due > 0 ? s.ownership.split_part(domain) : nullptr;
    const std::vector<int> previous_owner = split ? split->owner : std::vector<int>{};
    if (due == d.count())
      renew_kernel(s, d);
    else if (due > 0)
      renew_kernel(s, d, renewed);
    else
      d.kernel.steps_since_renewal = 0;
    if (due == 0) renewed.clear();
    if (split) {
      timed_exchange(s, domain, [&] { migrate(s, domain, previous_owner, force); });
      ++s.ownership.generation;  // the halo follows the new rows and owners
    }
  }
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const ParticleSubset* stressed = share ? &share->stressed : nullptr;
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  if (d.settings.step_estimate == StepEstimate::eigenvalue) {
    const auto estimate_start = Clock::now();
    recalibrate_stiffness_length(s, d, renewed);
    d.times.step_estimate += seconds_since(estimate_start);
  }
  ++d.kernel.steps_since_renewal;
  auto start = Clock::now();
  const Material& mat = s.materials[static_cast<std::size_t>(d.material)];
  const Index n = d.count();
  double best = std::numeric_limits<double>::infinity();
  Index controlling = -1;
  double best_physical = std::numeric_limits<double>::infinity();
  Index controlling_physical = -1;
  Index inverted = std::numeric_limits<Index>::max();
  Index non_finite = std::numeric_limits<Index>::max();
  long released = 0;
  int mass_added = 0;
  const bool control = d.settings.mode_control > 0.0;
  if (s.mass_scaling_dt > 0.0) mass_factors(d);
  const std::size_t rows = members(stressed, n);
  // The material's deviatoric model, visited once for the whole pass.
  std::visit(
      [&](const auto& model) {
#pragma omp parallel if (rows > 512) reduction(+ : released) reduction(max : mass_added)
        {
          double local_best = std::numeric_limits<double>::infinity();
          Index local_controlling = -1;
          double local_physical = std::numeric_limits<double>::infinity();
          Index local_controlling_physical = -1;
          Index local_inverted = std::numeric_limits<Index>::max();
          Index local_non_finite = std::numeric_limits<Index>::max();
#pragma omp for schedule(static, 128) nowait
          for (std::size_t m = 0; m < rows; ++m) {
            const Index j = member(stressed, m);
            const Outcome o = particle_update(s, d, mat, model, j, step);
            d.fields.step[static_cast<std::size_t>(j)] = std::isfinite(o.step) ? o.step : 0.0;
            if (control) mode_control_update(s, d, j);
            if (o.released && (!share || share->owned.flag[static_cast<std::size_t>(j)]))
              ++released;
            if (o.mass_added) mass_added = 1;
            if (o.inverted) {
              local_inverted = std::min(local_inverted, j);
            } else if (std::isnan(o.step)) {
              local_non_finite = std::min(local_non_finite, j);
            } else if (o.step < local_best) {  // ascending j per thread: ties keep the lowest
              local_best = o.step;
              local_controlling = j;
            }
            if (o.physical_step < local_physical) {
              local_physical = o.physical_step;
              local_controlling_physical = j;
            }
          }
#pragma omp critical
          {
            if (local_best < best || (local_best == best && local_controlling >= 0 &&
                                      (controlling < 0 || local_controlling < controlling))) {
              best = local_best;
              controlling = local_controlling;
            }
            if (local_physical < best_physical ||
                (local_physical == best_physical && local_controlling_physical >= 0 &&
                 (controlling_physical < 0 || local_controlling_physical < controlling_physical))) {
              best_physical = local_physical;
              controlling_physical = local_controlling_physical;
            }
            inverted = std::min(inverted, local_inverted);
            non_finite = std::min(non_finite, local_non_finite);
          }
        }
      },
      mat.model);
  // The agreement is where a process waits for the slower one: timed as exchange, so the
  // stress phase shows its own rows' work and an imbalance shows as waiting.
  const double exchanged_before = share ? share->exchange_seconds : 0.0;
  if (share)
    timed_exchange(s, domain, [&] {
      agree_on_pass(s.ownership.comm, best, controlling, best_physical, controlling_physical,
                    inverted, non_finite, released, mass_added);
    });
  d.diagnostics.released += released;
  if (mass_added) {
    grow_row_masses(d, owned);
    timed_exchange(s, domain, [&] { synchronise(s, domain, Scope::masses); });
    smooth_masses(s, d);
  }
  d.times.stress +=
      seconds_since(start) - (share ? share->exchange_seconds - exchanged_before : 0.0);
  if (d.settings.stabilization == Stabilization::strain_gradient) {
    start = Clock::now();
    strain_gradient_stabilization(s, d, force);
    d.times.stabilization += seconds_since(start);
  }
  start = Clock::now();

  // Internal forces, gathered per particle over the pairs (J, I) of its transpose, with the
  // mode-control force -(g_I - sum_J phi_I(X_J) g_J) = -(D^T g)_I (mode_control.cpp).
  const std::size_t forced = members(owned, n);
#pragma omp parallel for schedule(static, 256) if (forced > 512)
  for (std::size_t m = 0; m < forced; ++m) {
    const Index i = member(owned, m);
    const auto ii = static_cast<std::size_t>(i);
    Vec3 f = Vec3::Zero();
    if (control) {
      for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
        const auto tt = static_cast<std::size_t>(t);
        const Eigen::Map<const Mat3> p_j(
            d.fields.stress_gradient.col(d.kernel.transpose.rows[tt]).data());
        f.noalias() -= p_j * d.kernel.transpose.gradient.col(t);
        f += d.kernel.shape.value[static_cast<std::size_t>(d.kernel.transpose.pairs[tt])] *
             d.fields.mode_force.col(d.kernel.transpose.rows[tt]);
      }
      f -= d.fields.mode_force.col(i);
    } else {  // the same sum in two-wide registers (pair_sums.hpp)
      const Index* rows_of = d.kernel.transpose.rows.data();
      pairs::transpose_force(
          d.fields.stress_gradient.data(), d.kernel.transpose.gradient.data(),
          d.kernel.transpose.offsets[ii], d.kernel.transpose.offsets[ii + 1],
          [&](Index t) { return rows_of[t]; }, f.data());
    }
    force.col(d.particles.nodes[ii]) += f;
  }
  d.times.force += seconds_since(start);

  ParticlePassResult r;
  r.critical_step = best;
  r.controlling = controlling;
  d.kernel.step_bound.pass_step = best;
  d.kernel.step_bound.physical = best_physical;
  d.kernel.step_bound.physical_particle = controlling_physical;
  r.inverted = inverted == std::numeric_limits<Index>::max() ? -1 : inverted;
  r.non_finite = non_finite == std::numeric_limits<Index>::max() ? -1 : non_finite;
  return r;
}

}  // namespace mcdyna::solver::spg
