// Explicit FE solver: elastic-wave accuracy, energy and momentum conservation, thread
// independence, and the clean stop on an inverted element.
#include <omp.h>

#include <cmath>
#include <cstring>

#include "solver/energy.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

solver::Index node_at(const solver::State& s, double x, double y, double z) {
  for (solver::Index n = 0; n < s.nodes.count(); ++n)
    if ((s.nodes.initial.col(n) - solver::Vec3(x, y, z)).norm() < 1e-6) return n;
  return -1;
}

// Free-end displacement of the fixed-free rod: a triangle wave, amplitude |v0| L / c = 0.1,
// period 4 L / c = 40 (benchmarks.md §3).
double rod_free_end(double t) {
  const double v0 = -0.01;
  const double p = std::fmod(t, 40.0);
  const double g = p <= 10.0 ? p : (p <= 30.0 ? 20.0 - p : p - 40.0);
  return v0 * g;
}

// Relative L2 error of the free-end displacement over 0 <= t <= 80, sampled every cycle.
double rod_error(const std::string& deck) {
  TempDir dir;
  Simulation sim = prepare(dir, source_text(deck));
  const solver::Index tip = node_at(*sim.state, 10.0, 0.6, 0.6);
  REQUIRE(tip >= 0);
  double err = 0.0, norm = 0.0, last = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    const double dt = s.time - last;
    last = s.time;
    const double u = s.nodes.position(0, tip) - s.nodes.initial(0, tip);
    const double ua = rod_free_end(s.time);
    err += (u - ua) * (u - ua) * dt;
    norm += ua * ua * dt;
  };
  run(sim, hooks);
  CHECK(sim.result.reason == solver::StopReason::end_time);
  return std::sqrt(err / norm);
}

}  // namespace

TEST_CASE("elastic wave rod: free-end displacement converges to the analytic solution") {
  const double coarse = rod_error("decks/elastic_wave/rod_h0.2.k");
  const double fine = rod_error("decks/elastic_wave/rod_h0.1.k");
  MESSAGE("relative L2 error of u(L,t), 0 <= t <= 80: h = 0.2: ", coarse, ", h = 0.1: ", fine);
  // Measured 2026-11-22: 0.0146 and 0.0112. The floor is physical: v0 = -0.01 strains the rod
  // by 1 %, and the finite-strain solution drifts in phase from the linear analytic one (with
  // v0 = -0.001 and no bulk viscosity the h = 0.1 error is 0.004). Bounds: measured + ~25 %.
  CHECK(coarse < 0.018);
  CHECK(fine < 0.014);
  CHECK(fine < coarse);
}

TEST_CASE("undamped elastic vibration keeps the total energy within 0.5 %") {
  TempDir dir;
  // Free-free bar 4 x 1 x 1, stretched by a linear initial velocity field (no net momentum);
  // no bulk viscosity, so nothing is dissipated.
  std::string deck =
      "*KEYWORD\n*CONTROL_TERMINATION\n     200.0\n*CONTROL_BULK_VISCOSITY\n       0.0       0.0\n"
      "*PART\nbar\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
      "*MAT_ELASTIC\n         1       1.0     100.0       0.3\n" +
      box_mesh(8, 2, 2, 0.5) + "*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 8; ++i)
        deck += fmt::format("{:8d}{:16.8f}\n", 1 + i + 9 * (j + 3 * k), 0.01 * (i - 4) / 4.0);
  deck += "*END\n";
  Simulation sim = prepare(dir, deck);
  EnergyDrift drift;
  run(sim, drift.hooks());
  MESSAGE("largest |E_total / E_0 - 1| over ", sim.state->cycle, " cycles: ", drift.worst);
  CHECK(drift.initial > 0.0);
  CHECK(drift.worst < 0.005);
}

TEST_CASE("free rigid body spinning about a non-principal axis keeps its angular momentum") {
  TempDir dir;
  const std::string deck =
      "*KEYWORD\n*CONTROL_TERMINATION\n       2.0\n*CONTROL_TIMESTEP\n     0.001\n"
      "*PART\nbrick\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
      "*MAT_RIGID\n         1    7800.0     2.0E5       0.3\n" +
      box_mesh(4, 2, 1, 0.25) +
      "*INITIAL_VELOCITY_GENERATION\n         1         2      20.0       0.1       0.0       0.0\n"
      "       0.3       0.2       0.1       1.0       2.0       3.0\n*END\n";
  Simulation sim = prepare(dir, deck);
  REQUIRE(sim.state->rigid_bodies.size() == 1);
  const solver::RigidBody& b = sim.state->rigid_bodies[0];
  auto angular_momentum = [&] { return solver::Vec3(b.inertia() * b.omega); };
  const solver::Vec3 l0 = angular_momentum();
  const solver::Vec3 w0 = b.omega;
  run(sim);
  const double drift = (angular_momentum() - l0).norm() / l0.norm();
  MESSAGE("cycles ", sim.state->cycle, ", relative angular-momentum drift ", drift,
          ", omega turned by ", std::acos(b.omega.normalized().dot(w0.normalized())), " rad");
  CHECK(sim.state->cycle >= 1999);
  CHECK(drift < 1e-10);
  CHECK((b.omega - w0).norm() > 1e-3 * w0.norm());  // a non-principal spin must precess
}

TEST_CASE("results are bitwise identical for 1 and 2 threads") {
  auto simulate = [](int threads) {
    TempDir dir;
    std::string deck = source_text("decks/taylor_bar/taylor_coarse.k");
    const auto at = deck.find("*CONTROL_TERMINATION\n");
    deck.insert(deck.find('\n', at + 21), "       300");  // ENDCYC = 300
    Simulation sim = prepare(dir, deck);
    omp_set_num_threads(threads);
    run(sim);
    omp_set_num_threads(omp_get_num_procs());
    return sim;
  };
  const Simulation one = simulate(1), two = simulate(2);
  REQUIRE(one.state->cycle == 300);
  REQUIRE(two.state->cycle == 300);
  auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(a[0]) * a.size()) == 0;
  };
  const auto& p1 = one.state->nodes.position;
  const auto& p2 = two.state->nodes.position;
  CHECK(std::memcmp(p1.data(), p2.data(), sizeof(double) * p1.size()) == 0);
  const auto& d1 = solver::solids_of(*one.state).points.deviator;
  const auto& d2 = solver::solids_of(*two.state).points.deviator;
  CHECK(std::memcmp(d1.data(), d2.data(), sizeof(double) * d1.size()) == 0);
  CHECK(same(solver::solids_of(*one.state).internal_energy,
             solver::solids_of(*two.state).internal_energy));
  CHECK(one.state->time == two.state->time);
}

TEST_CASE("an inverted element stops the run and names the element, part and time") {
  TempDir dir;
  const std::string deck =
      "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*PART\ncube\n         7         1         1\n"
      "*SECTION_SOLID\n         1         1\n*MAT_ELASTIC\n         1       1.0     100.0       "
      "0.3\n" +
      box_mesh(1, 1, 1, 1.0, 1, 42, 7) +
      "*INITIAL_VELOCITY_NODE\n       8       0.0       0.0    -500.0\n*END\n";
  Simulation sim = prepare(dir, deck);
  run(sim);
  CHECK(sim.result.reason == solver::StopReason::inverted_element);
  CHECK(sim.result.message.find("solid element 42 (part 7)") != std::string::npos);
  CHECK(sim.result.message.find("t = ") != std::string::npos);
}

TEST_CASE("*MAT_NULL with an EOS: a water column struck by a piston carries rho c v") {
  // A 1 x 1 x 40 mm column of water (t, mm, s: rho 1e-9, *EOS_LINEAR_POLYNOMIAL C1 = 2200 MPa,
  // so c = sqrt(C1 / rho) = 1.483e6 mm/s), held laterally, its base fixed, its top driven down
  // at v = 1000 mm/s. Behind the front the pressure is the acoustic rho c v = 1.483 MPa and the
  // front has travelled c t: at 15 us, 22 mm down from the top. The null material carries no
  // shear: the deviator stays zero.
  std::string deck =
      "*KEYWORD\n*CONTROL_TERMINATION\n1.5e-5\n*PART\nwater\n1,1,1,1\n*SECTION_SOLID\n1,1\n"
      "*MAT_NULL\n1,1e-9\n*EOS_LINEAR_POLYNOMIAL\n1,0,2200.0\n" +
      box_mesh(1, 1, 40, 1.0);
  deck +=
      "*SET_NODE_LIST_GENERATE\n1\n1,164\n*BOUNDARY_SPC_SET\n1,0,1,1,0,0,0,0\n"
      "*SET_NODE_LIST_GENERATE\n2\n1,4\n*BOUNDARY_SPC_SET\n2,0,0,0,1,0,0,0\n"
      "*SET_NODE_LIST_GENERATE\n3\n161,164\n*BOUNDARY_PRESCRIBED_MOTION_SET\n3,3,0,9,-1000.0\n"
      "*DEFINE_CURVE\n9\n0,1\n1,1\n*END\n";
  TempDir dir;
  Simulation sim = prepare(dir, deck);
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const solver::Solids& so = solver::solids_of(*sim.state);
  const double acoustic = 1e-9 * std::sqrt(2200.0 / 1e-9) * 1000.0;
  // Elements 36-40 are the top 5 mm (well behind the front), 1-10 the bottom (not reached).
  double behind = 0.0;
  for (int e = 35; e < 40; ++e)
    behind += so.pressure[static_cast<std::size_t>(e)] / 5.0;
  MESSAGE("pressure behind the front ", behind, " MPa against rho c v = ", acoustic);
  CHECK(std::abs(behind / acoustic - 1.0) < 0.03);
  for (int e = 0; e < 10; ++e)
    CHECK(std::abs(so.pressure[static_cast<std::size_t>(e)]) < 1e-3 * acoustic);
  CHECK(so.points.deviator.cwiseAbs().maxCoeff() == 0.0);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

namespace {

// One element alone (a 1 mm steel square shell or cube, no support), ringing from a tiny
// diagonal push, at TSSFAC `scale` for 1 ms (some 6,000-9,000 cycles).
Simulation lone_element(const TempDir& dir, bool shell, double scale) {
  const std::string section =
      shell ? "*SECTION_SHELL\n1,2\n1.0,1.0,1.0,1.0\n" : "*SECTION_SOLID\n1,1\n";
  const std::string mesh =
      shell ? "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n"
            : box_mesh(1, 1, 1, 1.0);
  return prepare(dir, "*KEYWORD\n*CONTROL_TERMINATION\n1e-3\n*CONTROL_TIMESTEP\n0," +
                          std::to_string(scale) + "\n*PART\nlone\n1,1,1\n" + section +
                          "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n" + mesh +
                          "*INITIAL_VELOCITY_NODE\n1,-1e-6,-1e-6,0\n3,1e-6,1e-6,0\n*END\n");
}

}  // namespace

TEST_CASE("a lone element blown up by too long a step stops the run instead of growing on") {
  // The dilatation of an unsupported element outruns the element's step estimate L / c: for the
  // square shell omega = 2 c sqrt(1 + nu) / L (critical TSSFAC 1 / sqrt(1.3) = 0.877), for the
  // one-point cube 2 c sqrt((1 + nu) / (1 - nu)) / L (0.734 of the estimate without bulk
  // viscosity). Just above, the element swells without inverting: the run used to end
  // "normally" with a step of 0.3 s; it stops once the element is 10^4 times its size.
  struct Case {
    bool shell;
    double stable, unstable;
  };
  for (const Case c : {Case{true, 0.875, 0.880}, Case{false, 0.72, 0.74}}) {
    TempDir a, b;
    Simulation below = lone_element(a, c.shell, c.stable);
    run(below);
    CHECK(below.result.reason == solver::StopReason::end_time);
    Simulation above = lone_element(b, c.shell, c.unstable);
    // The run says so before it starts.
    core::Diagnostics said;
    CHECK(solver::compile(above.loaded->model(), said) != nullptr);
    std::string warnings;
    for (const core::Diagnostic& m : said.all())
      warnings += m.message + "\n";
    CHECK(warnings.find(c.shell ? "shell element(s) stand alone"
                                : "hexahedra are one element across") != std::string::npos);
    run(above);
    MESSAGE((c.shell ? "shell" : "solid"), " at TSSFAC ", c.unstable, ": ", above.result.message);
    CHECK(above.result.reason != solver::StopReason::end_time);
    const bool named = above.result.message.find("element 1 (part 1)") != std::string::npos;
    CHECK(named);
  }
}

}  // namespace mcdyna::test
