// *CONTROL_ACCURACY OSU 1: the second-order objective stress update (mid-step velocity gradient,
// Hughes-Winget rotation) for hexahedra and MC-SPG particles, on a free spinning elastic block.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>

#include "solver/energy.hpp"
#include "solver/material/point_kinematics.hpp"
#include "solver/spg/spg_solver.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

using solver::Index;
using solver::Vec3;

// A free elastic block (rho 1, E 100, nu 0.3, 6 x 5 x 4 of edge 1) moving, spinning at 0.6 rad
// per time unit about a tilted axis and sheared a little: 1.1 turns in 11.5 time units. No bulk
// viscosity and no PDAMP, so nothing should dissipate and the total energy should stay.
std::string spinning_block(bool particles, bool objective, double step) {
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n11.52\n*CONTROL_BULK_VISCOSITY\n0.0,0.0\n";
  if (objective) d += "*CONTROL_ACCURACY\n1\n";
  d += fmt::format("*CONTROL_TIMESTEP\n{},0.9\n", step);
  d += "*PART\nblock\n1,1,1\n";
  d += particles
           ? "*SECTION_SOLID_SPG\n1,47\n1.5,1.5,1.5,0,0,,15,0.0\n1,1.0E+11,1.0E+10,3,1.0,0,0,0\n"
           : "*SECTION_SOLID\n1,1\n";
  d += "*MAT_ELASTIC\n1,1.0,100.0,0.3\n" + box_mesh(6, 5, 4, 1.0) + "*END\n";
  return d;
}

void set_spin(solver::State& s) {
  const Vec3 v0(0.3, -0.2, 0.1), omega = 0.6 * Vec3(0.2, -0.3, 1.0).normalized();
  const Vec3 centre(3.0, 2.5, 2.0);
  for (Index n = 0; n < s.nodes.count(); ++n) {
    const Vec3 r = s.nodes.initial.col(n) - centre;
    s.nodes.velocity.col(n) = v0 + omega.cross(r) + Vec3(0.02 * r.y(), 0.0, 0.01 * r.x());
  }
}

// Largest |E_total / E_0 - 1| over the run at a fixed step.
double energy_drift(bool particles, bool objective, double step, long& cycles) {
  TempDir dir;
  Simulation sim = prepare(dir, spinning_block(particles, objective, step));
  set_spin(*sim.state);
  if (particles) solver::spg::initialise(*sim.state, solver::spg::domain_of(*sim.state, 0));
  sim.state->time_control.fixed_step = step;
  EnergyDrift drift;
  run(sim, drift.hooks());
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  cycles = sim.state->cycle;
  return drift.worst;
}

}  // namespace

TEST_CASE("Hughes-Winget rotation keeps the invariants, Jaumann to first order only") {
  const double s0[6] = {3.0, -1.0, 0.5, 0.7, -0.2, 0.4};
  const double w[3] = {0.3, -0.1, 0.2};
  double hw[6], ja[6];
  std::copy(s0, s0 + 6, hw);
  std::copy(s0, s0 + 6, ja);
  const double dt = 0.5;
  solver::hughes_winget_rotate(hw, w, dt);
  solver::jaumann_rotate(ja, w, dt);
  auto norm2 = [](const double* s) {
    return s[0] * s[0] + s[1] * s[1] + s[2] * s[2] +
           2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  };
  CHECK(hw[0] + hw[1] + hw[2] == doctest::Approx(s0[0] + s0[1] + s0[2]).epsilon(1e-14));
  CHECK(norm2(hw) == doctest::Approx(norm2(s0)).epsilon(1e-14));
  CHECK(std::abs(norm2(ja) / norm2(s0) - 1.0) > 1e-3);  // the Jaumann increment grows it
  // Both agree to first order in the rotation.
  double hw_small[6], ja_small[6];
  std::copy(s0, s0 + 6, hw_small);
  std::copy(s0, s0 + 6, ja_small);
  solver::hughes_winget_rotate(hw_small, w, 1e-4);
  solver::jaumann_rotate(ja_small, w, 1e-4);
  for (int i = 0; i < 6; ++i)
    CHECK(hw_small[i] == doctest::Approx(ja_small[i]).epsilon(1e-7));
}

TEST_CASE("OSU 1: a spinning free block keeps its energy to 0.1 %, second order in the step") {
  for (const bool particles : {false, true}) {
    CAPTURE(particles);
    long c0 = 0, c1 = 0;
    const double dt = 0.02;
    const double first_order = energy_drift(particles, false, dt, c0);
    double drift[3];
    for (int k = 0; k < 3; ++k)
      drift[k] = energy_drift(particles, true, dt / (1 << k), c1);
    MESSAGE(std::string(particles ? "MC-SPG" : "hexahedra"), ": |dE/E| OSU 0 ", first_order, " (",
            c0, " cycles); OSU 1 ", drift[0], ", at dt/2 ", drift[1], ", at dt/4 ", drift[2], " (",
            c1, " cycles)");
    // Measured (hexahedra / MC-SPG): OSU 0 8.1 % / 7.4 %, halving with the step: the
    // first-order rotation error of the end-of-step gradient and the Jaumann increment. OSU 1
    // (mid-step gradient, the stress turned half a step either side of its increment):
    // 9.1e-5 / 8.4e-5, then 2.1e-5 / 1.9e-5 at dt/2: a quarter per halving. A first-order
    // error halves (2); second order quarters it (4); 3 tells them apart.
    CHECK(drift[0] < 1e-3);
    CHECK(drift[0] < 0.01 * first_order);
    CHECK(drift[0] > 3.0 * drift[1]);
    CHECK(drift[1] > 3.0 * drift[2]);
  }
}

TEST_CASE("CONTROL_ACCURACY: OSU for all parts or the PIDOSU set, the other fields noted") {
  TempDir dir;
  // Two blocks: part 1 hexahedra, part 2 SPG particles above it (no shared nodes).
  const std::string parts =
      "*PART\nhex\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,100.0,0.3\n"
      "*PART\nspg\n2,2,1\n*SECTION_SOLID_SPG\n2,47\n1.5,1.5,1.5,0,0,,15,0.0\n"
      "1,1.0E+11,1.0E+10,3,1.0,0,0,0\n" +
      box_mesh(2, 2, 2, 1.0) + box_mesh(2, 2, 2, 1.0, 1001, 1001, 2, 5.0);
  auto compiled = [&](const std::string& controls, core::Diagnostics& d) {
    auto loaded = load_file(
        dir.write("deck.k", "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n" + controls + parts + "*END\n"),
        true);
    REQUIRE_MESSAGE(!loaded->diags.has_errors(), loaded->messages());
    return solver::compile(loaded->model(), d);
  };
  // (hexahedron block, SPG part) take the objective update
  auto objective = [&](const std::string& controls, core::Diagnostics& d) {
    const auto s = compiled(controls, d);
    return std::pair{solver::solids_of(*s).blocks.front().objective,
                     solver::spg::domain_of(*s, 0).settings.objective};
  };
  core::Diagnostics d;
  SUBCASE("no keyword: LS-DYNA's default OSU 0") {
    CHECK(objective("", d) == std::pair{false, false});
  }
  SUBCASE("OSU 1: every solid part and SPG part") {
    CHECK(objective("*CONTROL_ACCURACY\n1,4,0,1\n", d) == std::pair{true, true});
    CHECK(mentions(d, "INN 4"));
    CHECK(mentions(d, "IACC 1"));
  }
  SUBCASE("PIDOSU: only its parts, OSU ignored") {
    CHECK(objective("*CONTROL_ACCURACY\n0,1,7\n*SET_PART_LIST\n7\n2\n", d) ==
          std::pair{false, true});
  }
  SUBCASE("PIDOSU naming no set is an error") {
    compiled("*CONTROL_ACCURACY\n1,1,99\n", d);
    CHECK(d.has_errors());
    CHECK(mentions(d, "PIDOSU part set 99 is not defined"));
  }
}

}  // namespace mcdyna::test
