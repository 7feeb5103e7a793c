// MC-SPG particle solver: conservation (paper Eqs. 21-31), consistency of the smoothed strain
// rate, stability against plain nodal integration, FE coupling by common nodes.
#include <doctest/doctest.h>

#include <omp.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "solver/energy.hpp"
#include "solver/material/point_kinematics.hpp"
#include "solver/spg/angular_budget.hpp"
#include "solver/spg/spg_solver.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

using solver::Index;
using solver::Vec3;
namespace spg = solver::spg;

// The nodal forces a cycle starts from, as the time loop holds them (solver/nodal_forces.hpp):
// none, for the particle passes called here one by one.
Eigen::Matrix3Xd zero_forces(const solver::State& s) {
  return Eigen::Matrix3Xd::Zero(3, s.nodes.count());
}

const char* kSpgSection =
    "*SECTION_SOLID_SPG\n1,47\n1.5,1.5,1.5,0,0,,15,0.0\n1,1.0E+11,1.0E+10,3,1.0,0,0,-0.001\n";

// An SPG box (part 1, elastic, rho 1, E 100, nu 0.3), optionally on an FE box (part 2) sharing
// the nodes of the plane z = nz_fe * h.
std::string spg_deck(int nx, int ny, int nz, int end_cycle, int nz_fe = 0) {
  std::string d = fmt::format(
      "*KEYWORD\n*CONTROL_TERMINATION\n1.0e9,{}\n*PART\nspg\n1,1,1\n{}"
      "*MAT_ELASTIC\n1,1.0,100.0,0.3\n",
      end_cycle, kSpgSection);
  if (nz_fe == 0) return d + box_mesh(nx, ny, nz, 1.0) + "*END\n";
  // FE layers below, SPG above; the SPG box's first node layer is the FE box's last.
  d += "*PART\nfe\n2,2,1\n*SECTION_SOLID\n2,1\n";
  d += box_mesh(nx, ny, nz_fe, 1.0, 1, 1, 2);
  const int first_spg_node = 1 + (nx + 1) * (ny + 1) * nz_fe;
  std::string spg = box_mesh(nx, ny, nz, 1.0, first_spg_node, 100000, 1, nz_fe);
  // Drop the *NODE lines of the shared layer (already defined by the FE box).
  std::string out;
  std::size_t pos = 0;
  int line = 0;
  const int shared_lines = (nx + 1) * (ny + 1);
  while (pos < spg.size()) {
    const std::size_t end = spg.find('\n', pos);
    const std::string l = spg.substr(pos, end - pos + 1);
    if (!(line >= 1 && line <= shared_lines)) out += l;
    ++line;
    pos = end + 1;
  }
  return d + out + "*END\n";
}

// Translation + spin + deterministic noise, as node velocities.
void set_velocity_field(solver::State& s) {
  const Vec3 v0(0.3, -0.2, 0.1), omega(0.05, -0.02, 0.04);
  std::uint64_t seed = 12345;
  auto noise = [&] {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
  };
  for (Index n = 0; n < s.nodes.count(); ++n) {
    const Vec3 x = s.nodes.initial.col(n);
    s.nodes.velocity.col(n) = v0 + omega.cross(x) + 0.02 * Vec3(noise(), noise(), noise());
  }
}

// The momentum the scheme conserves: m-hat u-hat for smoothed particles, node mass x velocity
// for every other node (FE nodes and pinned particles).
// Angular momentum about the origin of the SPG particles: sum m-hat x × u-hat, or with the
// smoothed masses and velocities, sum m x × u (the two sides of Eq. 24).
Vec3 angular(const solver::State& s, bool smoothed_form) {
  Vec3 l = Vec3::Zero();
  const spg::Domain& d = solver::spg::domain_of(s, 0);
  for (Index i = 0; i < d.count(); ++i) {
    const Index n = d.particles.nodes[static_cast<std::size_t>(i)];
    const Vec3 x = s.nodes.position.col(n);
    if (smoothed_form)
      l += d.kernel.smoothed_mass[static_cast<std::size_t>(i)] * x.cross(s.nodes.velocity.col(n));
    else
      l += d.particles.mass[static_cast<std::size_t>(i)] * x.cross(d.fields.unsmoothed.col(i));
  }
  return l;
}

Vec3 conserved_momentum(const solver::State& s, double& scale) {
  Vec3 p = Vec3::Zero();
  scale = 0.0;
  for (Index n = 0; n < s.nodes.count(); ++n) {
    if (s.nodes.smoothed[static_cast<std::size_t>(n)]) continue;
    p += s.nodes.mass[static_cast<std::size_t>(n)] * s.nodes.velocity.col(n);
    scale += s.nodes.mass[static_cast<std::size_t>(n)] * s.nodes.velocity.col(n).norm();
  }
  for (const spg::Domain* dp : spg::domains_of(s))
    for (Index i = 0; i < dp->count(); ++i) {
      const spg::Domain& d = *dp;
      if (!s.nodes
               .smoothed[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(i)])])
        continue;
      p += d.particles.mass[static_cast<std::size_t>(i)] * d.fields.unsmoothed.col(i);
      scale += d.particles.mass[static_cast<std::size_t>(i)] * d.fields.unsmoothed.col(i).norm();
    }
  return p;
}

}  // namespace

TEST_CASE("MC-SPG free body: linear momentum kept to round-off over 1000 steps") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1000));
  set_velocity_field(*sim.state);
  solver::spg::domain_of(*sim.state, 0).settings.renewal_strain =
      0.0;  // renew at every SMSTEP check
  spg::initialise(*sim.state, solver::spg::domain_of(*sim.state, 0));
  double scale = 0.0;
  const Vec3 p0 = conserved_momentum(*sim.state, scale);
  // Eq. 24: in the reference configuration the smoothing keeps angular momentum exactly.
  spg::advance_velocities(*sim.state, solver::spg::domain_of(*sim.state, 0),
                          zero_forces(*sim.state), 0.0);
  const Vec3 l0 = angular(*sim.state, false);
  CHECK((angular(*sim.state, true) - l0).norm() <= 1e-12 * l0.norm());
  run(sim);
  CHECK(sim.result.reason == solver::StopReason::end_cycle);
  CHECK(sim.state->cycle == 1000);
  CHECK(solver::spg::domain_of(*sim.state, 0).diagnostics.renewals >
        60);  // SMSTEP 15: the kernel was renewed throughout
  double unused = 0.0;
  const Vec3 p1 = conserved_momentum(*sim.state, unused);
  MESSAGE("momentum drift ", (p1 - p0).norm() / scale);
  CHECK((p1 - p0).norm() <= 1e-12 * scale);
  // The stress field is far from trivial: the noise made the body ring.
  const solver::EnergySummary e = solver::energy_summary(*sim.state, sim.state->nodes.velocity);
  CHECK(e.internal > 1e-4 * e.kinetic);
  // Over time angular momentum is not kept to round-off: Eq. 30 applies each force about the
  // gathered position sum_I T_JI x_I, which is not x_J where the gather (Eq. 14) is only
  // zeroth-order consistent (the surface); the budget test below accounts for it term by term.
  // Measured on this body (spin 0.07 rad/time, 1000 steps): 1.3e-3 relative; translation +
  // noise alone: 2e-5.
  const double drift = (angular(*sim.state, false) - l0).norm() / l0.norm();
  MESSAGE("angular momentum drift ", drift);
  CHECK(drift < 2e-3);
}

// The angular-momentum budget of a free MC-SPG body (spg/angular_budget.hpp), recorded after
// every velocity update through the driver's hook, as `mcdyna run --spg-angular-budget` does.
struct BudgetHooks {
  spg::AngularBudget budget;
  [[nodiscard]] solver::RunHooks hooks() {
    solver::RunHooks h;
    h.velocities_advanced = [this](const solver::State& s, const solver::NodalForces& f,
                                   const solver::StepTimes& t) {
      budget.record(s, solver::spg::domain_of(s, 0), f.force, t.step, t.mean);
    };
    return h;
  }
};

TEST_CASE("MC-SPG angular momentum: the drift is the gather's first-moment defect, term by term") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1000));
  set_velocity_field(*sim.state);
  spg::initialise(*sim.state, solver::spg::domain_of(*sim.state, 0));
  BudgetHooks recorder;
  const spg::AngularBudget& budget = recorder.budget;
  double dt = 0.4 * solver::spg::domain_of(*sim.state, 0).kernel.step_bound.initial_critical;
  if (!(dt > 0.0)) dt = 0.02;
  sim.state->time_control.fixed_step = dt;
  run(sim, recorder.hooks());
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  REQUIRE_FALSE(budget.pinned);
  const Vec3 drift = budget.last - budget.first;
  const Vec3 explained = budget.sum_a + budget.sum_b;
  MESSAGE("dt ", dt, ": |L_end - L_0| / |L_0| ", drift.norm() / budget.first.norm(),
          "; A (moving with u) ", budget.sum_a.norm() / budget.first.norm(),
          ", B (forces about xbar) ", budget.sum_b.norm() / budget.first.norm(), ", left over ",
          (drift - explained).norm() / budget.first.norm(), ", DNI moment C ",
          budget.sum_c.norm() / budget.first.norm(), "; defect A + B - C over the scale ",
          budget.defect().norm() / budget.scale);
  // The drift is real (the surface rows' gather is not first-order consistent) ...
  CHECK(drift.norm() > 1e-5 * budget.first.norm());
  // ... and it is all A + B: the two terms account for it to round-off, and DNI adds no moment.
  CHECK((drift - explained).norm() <= 1e-12 * budget.scale);
  CHECK(budget.sum_c.norm() <= 1e-12 * budget.scale);
}

TEST_CASE("MC-SPG partial kernel renewal: only strained rows renewed, momentum and mass kept") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1000));
  set_velocity_field(*sim.state);
  spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
  d.settings.renewal_strain = 0.003;  // the noise strains some rows past this, not all
  spg::initialise(*sim.state, d);
  double scale = 0.0;
  const Vec3 p0 = conserved_momentum(*sim.state, scale);
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  const double share = static_cast<double>(d.diagnostics.renewed_rows - d.count()) /
                       (static_cast<double>(d.diagnostics.renewals - 1) * d.count());
  MESSAGE("renewals ", d.diagnostics.renewals, ", share of rows per renewal ", share);
  // Measured: 67 renewals, 46 % of the rows each after the first (each row in its own reference).
  CHECK(d.diagnostics.renewals > 10);
  CHECK(share > 0.05);
  CHECK(share < 0.95);
  double unused = 0.0;
  const Vec3 p1 = conserved_momentum(*sim.state, unused);
  MESSAGE("momentum drift ", (p1 - p0).norm() / scale);
  CHECK((p1 - p0).norm() <= 1e-12 * scale);
  const double mass = std::accumulate(d.particles.mass.begin(), d.particles.mass.end(), 0.0);
  CHECK(std::accumulate(d.kernel.smoothed_mass.begin(), d.kernel.smoothed_mass.end(), 0.0) ==
        doctest::Approx(mass).epsilon(1e-12).scale(0.0));
}

namespace {
// The mass-scaling check below, with the step estimate and stress update given.
void check_mass_scaling(spg::StepEstimate estimate, bool objective) {
  TempDir dir;
  auto configure = [&](Simulation& sim) {
    spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
    d.settings.step_estimate = estimate;
    d.settings.objective = objective;
  };
  // The natural step of the body, from one cycle of the same deck, and each particle's own step.
  Simulation probe = prepare(dir, spg_deck(7, 6, 5, 1));
  configure(probe);
  run(probe);
  const double natural = probe.state->step;
  const spg::Domain& pd = solver::spg::domain_of(*probe.state, 0);
  // Three times that step: row J asks for (3 natural / (TSSFAC step_J))^2 (9 for the particles
  // that set the step, less for those whose stiffness length is longer), and every particle
  // takes the largest factor asked by the rows it is in.
  const double tssfac = probe.state->time_control.scale_factor;
  double expected = 0.0;
  for (spg::Index k = 0; k < pd.count(); ++k) {
    double factor = 1.0;
    for (spg::Index t = pd.kernel.transpose.offsets[static_cast<std::size_t>(k)];
         t < pd.kernel.transpose.offsets[static_cast<std::size_t>(k) + 1]; ++t) {
      const auto j =
          static_cast<std::size_t>(pd.kernel.transpose.rows[static_cast<std::size_t>(t)]);
      const double ratio = 3.0 * natural / (tssfac * pd.fields.step[j]);
      if (ratio > 1.0) factor = std::max(factor, ratio * ratio);
    }
    expected += (factor - 1.0) * pd.particles.mass[static_cast<std::size_t>(k)];
  }
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 2));
  configure(sim);
  set_velocity_field(*sim.state);
  sim.state->mass_scaling_dt = 3.0 * natural;
  spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
  spg::initialise(*sim.state, d);
  const double physical = std::accumulate(d.particles.mass.begin(), d.particles.mass.end(), 0.0);
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  const double added = solver::total_added_mass(*sim.state);
  MESSAGE("added mass / physical mass ", added / physical, ", expected ", expected / physical);
  // At least what the first pass asked (2 % for the velocity field's bulk viscosity against the
  // probe); the second pass asks a little more where the new masses raised a row's mobility
  // (measured 8.06 against 8.0 with the nearest-neighbour step, 6.36 against 5.35 with
  // --spg-step eigen, where the particles' own steps differ).
  CHECK(added >= 0.98 * expected);
  CHECK(added / physical < 9.0);
  // The smoothed masses (Eq. 20) were rebuilt from the scaled particle masses.
  CHECK(std::accumulate(d.kernel.smoothed_mass.begin(), d.kernel.smoothed_mass.end(), 0.0) ==
        doctest::Approx(physical + added).epsilon(1e-12).scale(0.0));
  // The body rings stably at the target step for 1000 cycles, asking for a little more mass now
  // and then (added at the velocity a particle has, as LS-DYNA does, which changes momentum).
  double scale = 0.0;
  conserved_momentum(*sim.state, scale);
  const double vmax0 = largest_speed(*sim.state);
  sim.state->time_control.end_cycle = 1000;
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  // Held at the target; with the eigenvalue step a little above it (measured 1.023 x): the
  // first pass gave some rows more mass than the recalibrated lengths need.
  if (estimate == spg::StepEstimate::nearest_neighbour)
    CHECK(sim.state->step == doctest::Approx(3.0 * natural).epsilon(1e-9).scale(0.0));
  CHECK(sim.state->step >= 3.0 * natural * (1.0 - 1e-9));
  CHECK(sim.state->step < 1.05 * 3.0 * natural);
  const double vmax = largest_speed(*sim.state);
  MESSAGE("largest speed before / after 1000 steps ", vmax0, " / ", vmax,
          ", added mass / physical ", solver::total_added_mass(*sim.state) / physical);
  CHECK(vmax < 1.5 * vmax0);
  // Then with a target below the step the scaled body now has, nothing more is added: over 1000
  // more cycles momentum is kept to round-off with the scaled particle and smoothed masses (an
  // inconsistency between them would show in every cycle).
  sim.state->mass_scaling_dt = 0.5 * natural;
  const double added_before = solver::total_added_mass(*sim.state);
  double worst = 0.0;
  Vec3 last_p = conserved_momentum(*sim.state, scale);
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& st) {
    double unused = 0.0;
    const Vec3 p = conserved_momentum(st, unused);
    worst = std::max(worst, (p - last_p).norm());
    last_p = p;
  };
  sim.state->time_control.end_cycle = 2000;
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  CHECK(solver::total_added_mass(*sim.state) == added_before);
  MESSAGE("largest momentum change per cycle without additions ", worst / scale);
  CHECK(worst <= 1e-12 * scale);
  CHECK(largest_speed(*sim.state) < 1.5 * vmax0);
}
}  // namespace

TEST_CASE("MC-SPG mass scaling (DT2MS): rows take the mass that reaches the target, stably") {
  check_mass_scaling(spg::StepEstimate::nearest_neighbour, false);
}

// The eigenvalue step runs the particles at 0.85 of the linear critical step. With OSU 0 this
// spinning block (0.017 rad per step) then loses its stable step: the first-order rotation error
// strains it, and once no mass is added its critical step fell from 3.5 to 1.7 x the initial one
// within 650 cycles and a particle inverted at cycle 1782 (1649 with renewals); without the spin
// it held 3.61 for 2000 cycles, and with OSU 1 it holds 3.62-3.67 (measured in a probe).
TEST_CASE("MC-SPG mass scaling with --spg-step eigen and OSU 1: stable through all phases") {
  check_mass_scaling(spg::StepEstimate::eigenvalue, true);
}

// An interior particle I whose shape-function values at its neighbours nearly cancel, as in a
// torn, one-sided neighbourhood: its own value phi_I(X_I) is set so that its smoothed mass
// m_I = sum_K m-hat_K phi_I(X_K) (Eq. 20) is 0.11 m-hat_I, just above the share below which a
// particle is integrated plainly. The FDS plate blew up from such a particle (0.1 m-hat_I).
// Returns I.
Index tear_shape_function(solver::State& s, spg::Domain& d) {
  const Index centre = 4 + 8 * (3 + 7 * 3);
  const auto cc = static_cast<std::size_t>(centre);
  double others = 0.0;
  std::size_t self = 0;
  for (Index t = d.kernel.transpose.offsets[cc]; t < d.kernel.transpose.offsets[cc + 1]; ++t) {
    const auto tt = static_cast<std::size_t>(t);
    const auto k = static_cast<std::size_t>(d.kernel.transpose.rows[tt]);
    const auto pair = static_cast<std::size_t>(d.kernel.transpose.pairs[tt]);
    if (k == cc)
      self = pair;
    else
      others += d.particles.mass[k] * d.kernel.shape.value[pair];
  }
  d.kernel.shape.value[self] = (0.11 * d.particles.mass[cc] - others) / d.particles.mass[cc];
  spg::smooth_masses(s, d);
  return centre;
}

TEST_CASE("MC-SPG step: rows round a small smoothed mass get shorter steps and stay stable") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 2000));
  set_velocity_field(*sim.state);
  spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
  spg::initialise(*sim.state, d);
  // The initial arrangement is the reference of the bound: no row is shortened.
  for (const double m : d.kernel.mobility)
    CHECK(m == 1.0);
  Eigen::Matrix3Xd force = zero_forces(*sim.state);
  const double natural = spg::particle_pass(*sim.state, d, 0.0, force).critical_step;
  const Index centre = tear_shape_function(*sim.state, d);
  const auto cc = static_cast<std::size_t>(centre);
  REQUIRE(d.kernel.pinned[cc] == 0);
  REQUIRE(d.particles.mass[cc] / d.kernel.smoothed_mass[cc] == doctest::Approx(1.0 / 0.11));
  // Every row that holds I is shortened, and only rows near it.
  double largest = 1.0;
  for (Index i = 0; i < d.count(); ++i) {
    const auto ii = static_cast<std::size_t>(i);
    bool holds = false;
    for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p)
      holds = holds || d.kernel.list.neighbours[static_cast<std::size_t>(p)] == centre;
    if (holds) CHECK(d.kernel.mobility[ii] > 2.0);
    // Three spacings away (a row's neighbours, theirs, and the rows holding those) in any
    // axis, nothing changed: the x = 0 face.
    const Vec3 apart = sim.state->nodes.position.col(d.particles.nodes[ii]) -
                       sim.state->nodes.position.col(d.particles.nodes[cc]);
    if (apart.cwiseAbs().maxCoeff() > 3.5) CHECK(d.kernel.mobility[ii] == 1.0);
    largest = std::max(largest, d.kernel.mobility[ii]);
  }
  const double shortened = spg::particle_pass(*sim.state, d, 0.0, force).critical_step;
  MESSAGE("largest mobility ", largest, ", critical step before / after ", natural, " / ",
          shortened);
  CHECK(shortened < natural / std::sqrt(2.0));
  // At that step the body rings stably for 2000 cycles.
  const double vmax0 = largest_speed(*sim.state);
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
  MESSAGE("largest speed before / after ", vmax0, " / ", largest_speed(*sim.state));
  CHECK(largest_speed(*sim.state) < 1.5 * vmax0);
  // (Taken out, the factor is not needed here: the same torn block at the step of length / c
  // alone also rings stably for 2000 cycles, measured. The bound is conservative on a regular
  // lattice; the FDS plate, which stopped without it, had one-sided rows with large gradients.)
}

TEST_CASE("MC-SPG coupled to FE by common nodes: total momentum kept to round-off") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(6, 5, 4, 1000, 2));
  REQUIRE(solver::spg::domains_of(*sim.state).size() == 1);
  REQUIRE(solver::solids_of(*sim.state).count() == 6 * 5 * 2);
  set_velocity_field(*sim.state);
  spg::initialise(*sim.state, solver::spg::domain_of(*sim.state, 0));
  long shared = 0;
  for (const auto f : solver::spg::domain_of(*sim.state, 0).particles.shared)
    shared += f;
  CHECK(shared == 7 * 6);  // the common plane
  double scale = 0.0;
  const Vec3 p0 = conserved_momentum(*sim.state, scale);
  run(sim);
  CHECK(sim.result.reason == solver::StopReason::end_cycle);
  double unused = 0.0;
  const Vec3 p1 = conserved_momentum(*sim.state, unused);
  MESSAGE("momentum drift ", (p1 - p0).norm() / scale);
  CHECK((p1 - p0).norm() <= 1e-12 * scale);
}

TEST_CASE("MC-SPG smoothing: an affine velocity field gives the exact strain rate inside") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(9, 9, 9, 1));
  solver::State& s = *sim.state;
  Eigen::Matrix3d a;
  a << 0.1, -0.3, 0.2, 0.05, -0.2, 0.15, -0.1, 0.25, 0.3;
  const Vec3 v0(1.0, 2.0, -0.5);
  for (Index n = 0; n < s.nodes.count(); ++n)
    s.nodes.velocity.col(n) = v0 + a * s.nodes.initial.col(n);
  spg::Domain& d = solver::spg::domain_of(s, 0);
  d.settings.damping = 0.0;  // PDAMP acts on velocity differences; this checks Eq. 13 alone
  spg::initialise(s, d);
  REQUIRE(spg::advance_velocities(s, d, zero_forces(s), 0.0) == -1);  // smoothing only (Eq. 13)
  int checked = 0;
  double worst = 0.0, boundary_worst = 0.0;
  for (Index i = 0; i < d.count(); ++i) {
    const Vec3 x = d.particles.initial_position.col(i);
    // Complete support: the particle, its neighbours and theirs (the gather of Eq. 13 reaches
    // two kernel radii) all have full, symmetric neighbourhoods: 3 layers in from every face.
    const bool inside = (x.array() >= 3.0 - 1e-9).all() && (x.array() <= 6.0 + 1e-9).all();
    const double err = (spg::particle_kinematics(s, d, i).velocity_gradient - a).norm();
    if (inside) {
      worst = std::max(worst, err);
      ++checked;
    } else {
      boundary_worst = std::max(boundary_worst, err);
    }
  }
  CHECK(checked == 64);
  MESSAGE("interior ", worst, ", boundary ", boundary_worst);
  CHECK(worst <= 1e-12 * a.norm());
  // Near the surface the mass-weighted gather is only zeroth-order consistent (Eq. 14).
  CHECK(boundary_worst > 1e-6);
}

TEST_CASE("MC-SPG keeps the elastic wave smooth where plain nodal integration oscillates") {
  // The paper's motivating observation (§2): DNI (Eq. 5) develops spurious modes. Same deck,
  // coarse rod of the elastic-wave benchmark, to t = 80 (two wave periods), with the kernel
  // renewed at every SMSTEP check as under large deformation: the renewals take up the
  // particle-scale motion that nodal integration does not see. With the kernel kept in its
  // reference (the default at this 1 % strain) neither method oscillates: none 0.0035, mc 0.0019.
  const double norm[2] = {elastic_wave_oscillation(spg::Stabilization::none),
                          elastic_wave_oscillation(spg::Stabilization::momentum_consistent)};
  MESSAGE("oscillation norm: none ", norm[0], ", mc ", norm[1]);
  // Measured (2026-12-02): none 0.043, mc 0.0035 (12x).
  CHECK(norm[0] > 5.0 * norm[1]);
  CHECK(norm[1] < 0.01);
}

TEST_CASE("MC-SPG results are bitwise identical on 1 and 2 threads") {
  CHECK(same_bits_on_1_and_2_threads(spg_deck(10, 9, 8, 200),
                                     [](solver::State& s) { set_velocity_field(s); }));
}

TEST_CASE("MC-SPG bond failure: a notched bar pulled apart breaks into pieces, mass kept") {
  // decks/fracture/tension_spg_h1.k: 509 particles, FS 0.3 and STRETCH 1.1 (Eqs. 35-36).
  TempDir dir;
  Simulation sim = prepare(dir, source_text("decks/fracture/tension_spg_h1.k"));
  solver::State& s = *sim.state;
  const double mass0 = std::accumulate(solver::spg::domain_of(s, 0).particles.mass.begin(),
                                       solver::spg::domain_of(s, 0).particles.mass.end(), 0.0);
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const spg::Domain& d = solver::spg::domain_of(s, 0);
  const spg::Pieces pieces = spg::count_pieces(d.kernel.list);
  MESSAGE("broken bonds ", d.diagnostics.broken_bonds, ", pieces ", pieces.pieces, ", largest ",
          pieces.largest);
  // Measured: 118 bonds broken, 11 pieces (the two halves, the largest of 250 particles, and
  // fragments of the notch's middle layer); the largest piece is a half of the bar.
  CHECK(d.diagnostics.broken_bonds > 0);
  CHECK(pieces.pieces >= 2);
  CHECK(pieces.largest < d.count() * 3 / 5);
  // Particles are never deleted, and the smoothed masses of the last kernel, built without the
  // broken pairs, still sum to the particle masses (Eq. 21).
  CHECK(std::accumulate(d.particles.mass.begin(), d.particles.mass.end(), 0.0) == mass0);
  // Rows of degenerate (isolated) particles are zero, so their mass enters no m_I.
  double smoothed =
      std::accumulate(d.kernel.smoothed_mass.begin(), d.kernel.smoothed_mass.end(), 0.0);
  int isolated = 0;
  for (Index j = 0; j < d.count(); ++j)
    if (d.kernel.isolated[static_cast<std::size_t>(j)]) {
      smoothed += d.particles.mass[static_cast<std::size_t>(j)];
      ++isolated;
    }
  MESSAGE("isolated particles ", isolated);
  CHECK(smoothed == doctest::Approx(mass0).epsilon(1e-12).scale(0.0));
  // Broken bonds are out of every neighbour list (no healing).
  long stale = 0;
  for (Index i = 0; i < d.count(); ++i)
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(i)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
      const Index j = d.kernel.list.neighbours[static_cast<std::size_t>(p)];
      if (j != i && d.kernel.bonds.is_broken(i, j)) ++stale;
    }
  CHECK(stale == 0);
}

TEST_CASE("MSC 1: low-energy-mode control keeps the layers beside a neck from pairing up") {
  // The notched bar of decks/fracture/tension_spg_h1.k without bond failure, to 0.25 ms: the
  // net section necks; the gaps between particle layers should vary smoothly beside it.
  const std::string deck =
      with(with(source_text("decks/fracture/tension_spg_h1.k"), " 4.000E-04", " 2.500E-04"),
           "         1       0.3       1.1", "         1   1.0E+11       1.1");
  auto alternation = [&](double control) {
    TempDir dir;
    Simulation sim = prepare(dir, deck);
    spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
    REQUIRE(d.settings.mode_control == spg::kModeControl);  // MSC 1 on the card
    d.settings.mode_control = control;
    run(sim);
    REQUIRE(sim.result.reason == solver::StopReason::end_time);
    // Away from the two gaps at the notch layer and their neighbours.
    const std::vector<double> g = layer_gaps(*sim.state, [](Index) { return true; });
    return deepest_extremum(g, g.size() / 2 - 2, g.size() / 2 + 1);
  };
  const double plain = alternation(0.0), controlled = alternation(spg::kModeControl);
  MESSAGE("layer-gap alternation (mm): MSC 0 ", plain, ", MSC 1 ", controlled);
  // Measured: 0.179 mm with MSC 0 (gaps 0.96 / 1.12 / 0.94 mm beside the neck), 0.010 mm with
  // MSC 1 (h = 1 mm). The first bound shows the pairing this guards against is there to see.
  CHECK(plain > 0.08);
  CHECK(controlled < 0.03);
}

TEST_CASE("MSC 1: mode-control forces vanish for affine motion and keep both momenta") {
  TempDir dir;
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1));
  solver::State& s = *sim.state;
  spg::Domain& d = solver::spg::domain_of(s, 0);
  d.settings.mode_control = spg::kModeControl;
  spg::initialise(s, d);
  Eigen::Matrix3Xd force = zero_forces(s);
  spg::particle_pass(s, d, 0.0, force);  // stiffnesses k_J from the stress update
  // A finite rotation, stretch and shear of the reference: every residual is round-off.
  Eigen::Matrix3d f = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  f = f * (Eigen::Matrix3d() << 1.3, 0.2, 0.0, 0.0, 0.8, 0.1, 0.0, 0.0, 1.1).finished();
  for (Index n = 0; n < s.nodes.count(); ++n)
    s.nodes.position.col(n) = f * s.nodes.initial.col(n) + Vec3(0.5, -1.0, 2.0);
  double affine = 0.0;
  for (Index j = 0; j < d.count(); ++j)
    affine = std::max(affine, spg::mode_residual(s, d, j).norm());
  MESSAGE("largest residual of an affine configuration ", affine);
  CHECK(affine < 1e-12);
  // A non-affine configuration: the forces -D^T g sum to zero and have no moment.
  std::uint64_t seed = 7;
  for (Index n = 0; n < s.nodes.count(); ++n) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    const double a = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
    s.nodes.position.col(n) += 0.05 * Vec3(a, -0.7 * a, 0.4 * a * a);
  }
  spg::mode_control_forces(s, d);
  Vec3 total = Vec3::Zero(), moment = Vec3::Zero();
  double scale = 0.0;
  for (Index i = 0; i < d.count(); ++i) {
    const auto ii = static_cast<std::size_t>(i);
    Vec3 f_i = -d.fields.mode_force.col(i);
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto tt = static_cast<std::size_t>(t);
      f_i += d.kernel.shape.value[static_cast<std::size_t>(d.kernel.transpose.pairs[tt])] *
             d.fields.mode_force.col(d.kernel.transpose.rows[tt]);
    }
    const Vec3 x = s.nodes.position.col(d.particles.nodes[ii]);
    total += f_i;
    moment += x.cross(f_i);
    scale += f_i.norm() * (1.0 + x.norm());
  }
  REQUIRE(scale > 0.0);
  MESSAGE("force sum ", total.norm() / scale, ", moment ", moment.norm() / scale);
  CHECK(total.norm() <= 1e-13 * scale);
  CHECK(moment.norm() <= 1e-13 * scale);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

// The largest eigenvalue of the linearised MC-SPG equations (frequency.cpp) is where the
// central-difference update of a free body goes unstable: below 2 / omega the ringing body stays
// bounded over 400 cycles, above it the highest mode grows by about 2.4 per cycle (omega dt =
// 2.2) and the run stops. The particle step the code takes is scaled to it (stiffness_length).
TEST_CASE("MC-SPG critical step: 2 / omega from power iteration is where a free body blows up") {
  TempDir dir;
  const double critical = check_blow_up_at_critical_step(
      spg_deck(7, 6, 5, 400), [](solver::State& s) { set_velocity_field(s); });
  // The step the code chooses with --spg-step eigen: TSSFAC x the particle steps scaled to
  // 2 / omega, less the bulk viscosity's linear share.
  Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1));
  solver::spg::domain_of(*sim.state, 0).settings.step_estimate = spg::StepEstimate::eigenvalue;
  run(sim);
  const double damped = solver::element_step(
      solver::spg::domain_of(*sim.state, 0).settings.bulk_viscosity, 1.0, 1.0, 0.0);
  CHECK(sim.state->step == doctest::Approx(0.9 * damped * critical).epsilon(1e-6));
}

}  // namespace mcdyna::test

namespace mcdyna::test {

namespace {
// Mirrors the neighbours of particle `centre` through it, so its F-hat (and some of theirs)
// has a negative determinant.
void invert_neighbourhood(solver::State& s, const spg::Domain& d, Index centre) {
  const auto cc = static_cast<std::size_t>(centre);
  const Vec3 x = s.nodes.position.col(d.particles.nodes[cc]);
  for (Index p = d.kernel.list.offsets[cc]; p < d.kernel.list.offsets[cc + 1]; ++p) {
    const Index node =
        d.particles
            .nodes[static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)])];
    s.nodes.position.col(node) = 2.0 * x - s.nodes.position.col(node);
  }
}
}  // namespace

TEST_CASE("MC-SPG inversion: stops the run naming the particle, or releases damaged debris") {
  TempDir dir;
  const Index centre = 4 + 8 * (3 + 7 * 3);
  SUBCASE("an intact particle whose neighbourhood inverts is an instability") {
    Simulation sim = prepare(dir, spg_deck(7, 6, 5, 1));
    spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
    spg::initialise(*sim.state, d);
    invert_neighbourhood(*sim.state, d, centre);
    Eigen::Matrix3Xd force = zero_forces(*sim.state);
    const spg::ParticlePassResult r = spg::particle_pass(*sim.state, d, 1e-3, force);
    CHECK(r.inverted >= 0);
    CHECK(r.critical_step > 0.0);  // the particles that did not invert still give a step
    CHECK(d.diagnostics.released == 0);
    run(sim);
    CHECK(sim.result.reason == solver::StopReason::inverted_element);
    MESSAGE(sim.result.message);
    CHECK(sim.result.message.find("non-positive Jacobian or volume at") != std::string::npos);
  }
  SUBCASE("a particle that has lost bonds is released as debris instead") {
    std::string deck = spg_deck(7, 6, 5, 1);
    Simulation sim = prepare(dir, deck);
    spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
    d.settings.bond_failure = true;
    spg::initialise(*sim.state, d);
    for (Index i = 0; i < d.count(); ++i)  // one broken bond each: damage > 0 everywhere
      d.kernel.bonds
          .broken[static_cast<std::size_t>(d.kernel.bonds.offsets[static_cast<std::size_t>(i)])] =
          1;
    invert_neighbourhood(*sim.state, d, centre);
    Eigen::Matrix3Xd force = zero_forces(*sim.state);
    const spg::ParticlePassResult r = spg::particle_pass(*sim.state, d, 1e-3, force);
    CHECK(r.inverted == -1);
    CHECK(d.fields.debris[static_cast<std::size_t>(centre)] == 1);
    CHECK(d.diagnostics.released > 0);
    CHECK(std::isfinite(r.critical_step));
    CHECK(r.critical_step > 0.0);
  }
}

}  // namespace mcdyna::test
