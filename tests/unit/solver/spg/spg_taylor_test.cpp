// The coarse MC-SPG Taylor bar over its first 10 us, as a CI-length regression test of the
// whole particle solver on a hard case (JC + EOS, 227 m/s impact on a rigid wall): energy
// balance, agreement with the hexahedral FE model of the same bar, and the layers on the axis
// at the impact end compressing smoothly. The full runs are in manual/verification.md.
#include <doctest/doctest.h>

#include <cmath>

#include "solver/energy.hpp"
#include "solver/spg/spg_solver.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

using solver::Index;
namespace spg = solver::spg;

std::string first_10_us(const std::string& deck) {
  return with(source_text(deck), "\n 8.000E-05\n", "\n 1.000E-05\n");
}

// Shortening of the bar: initial length minus the highest current z.
double shortening(const solver::State& s) {
  return s.nodes.initial.row(2).maxCoeff() - s.nodes.position.row(2).maxCoeff();
}

struct SpgRun {
  double shortening = 0.0, energy_ratio = 0.0, axis_pairing = 0.0;
};

SpgRun run_spg(double mode_control) {
  TempDir dir;
  Simulation sim = prepare(dir, first_10_us("decks/taylor_bar/taylor_spg_coarse.k"));
  REQUIRE(solver::spg::domains_of(*sim.state).size() == 1);
  solver::spg::domain_of(*sim.state, 0).settings.mode_control = mode_control;
  // Energies as glstat has them: total at each state over the first total plus external work.
  double first = 0.0, ratio = 0.0;
  bool started = false;
  solver::RunHooks hooks;
  hooks.output_due = [](const solver::State& s) { return s.cycle == 0; };  // and the final state
  hooks.write = [&](const solver::State& s, const Eigen::Matrix3Xd& previous, bool) {
    const solver::EnergySummary e = solver::energy_summary(s, previous);
    if (!started) first = e.total;
    started = true;
    ratio = e.total / (first + e.external_work);
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const solver::State& s = *sim.state;
  const spg::Domain& d = solver::spg::domain_of(s, 0);
  // The particles on the axis, by layer from the wall: the first 16 gaps (to 7.8 mm).
  std::vector<double> g = layer_gaps(s, [&](Index i) {
    return std::hypot(d.particles.initial_position(0, i), d.particles.initial_position(1, i)) <
           1e-6;
  });
  REQUIRE(g.size() > 16);
  g.resize(16);
  return {shortening(s), ratio, deepest_extremum(g)};
}

}  // namespace

TEST_CASE("MC-SPG Taylor bar, first 10 us: energy kept, FE shortening, smooth axis") {
  TempDir dir;
  Simulation fe = prepare(dir, first_10_us("decks/taylor_bar/taylor_coarse.k"));
  run(fe);
  REQUIRE(fe.result.reason == solver::StopReason::end_time);
  const double fe_shortening = shortening(*fe.state);
  const SpgRun paper = run_spg(0.0), controlled = run_spg(spg::kModeControl);
  MESSAGE("shortening FE ", fe_shortening, " mm, MC-SPG ", paper.shortening,
          " mm (MSC 1: ", controlled.shortening, "); energy ratio ", paper.energy_ratio, " (",
          controlled.energy_ratio, "); axis pairing ", paper.axis_pairing, " mm (",
          controlled.axis_pairing, ")");
  // Measured (mesh-frame supports): FE 3.4944 mm, MC-SPG 3.5006 mm (+0.18 %), MSC 1 3.5029 mm;
  // energy ratio 1.00023 and 1.00009. At 80 us the full coarse runs end 0.4 % longer (MSC 1)
  // and 2.2 % shorter (MSC 0) than FE's 16.06 mm, 0.8 % and 4.6 % of the shortening; this
  // early, 2 % of it bounds the difference.
  CHECK(std::abs(paper.shortening - fe_shortening) < 0.02 * fe_shortening);
  CHECK(std::abs(controlled.shortening - fe_shortening) < 0.02 * fe_shortening);
  CHECK(std::abs(paper.energy_ratio - 1.0) < 1e-3);
  CHECK(std::abs(controlled.energy_ratio - 1.0) < 1e-3);
  // No long-short alternation of the axis gaps with either (measured 0 and 0); with every row
  // renewed at 0.1 strain also under compression, MSC 0 showed 0.073 mm (gaps 0.18 / 0.30 /
  // 0.23 mm) and MSC 1 none.
  CHECK(paper.axis_pairing < 0.01);
  CHECK(controlled.axis_pairing < 0.01);
}

}  // namespace mcdyna::test
