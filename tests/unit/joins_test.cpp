// Joins (issue 26): extra nodes, merged rigid bodies and nodal rigid bodies against closed-form
// answers.
#include <doctest/doctest.h>

#include <cmath>

#include "shell_decks.hpp"
#include "solver_support.hpp"

using namespace mcdyna;

TEST_CASE("nodal rigid bodies weld a split cantilever into one: the period is the whole strip's") {
  // The 20 x 2 strip cut at its middle column, each pair of coincident nodes there joined by a
  // two-node *CONSTRAINED_NODAL_RIGID_BODY (a spot weld). A rigid joint of coincident nodes is
  // the shared node: the period must be the continuous strip's, 11.9779 ms (+0.08 % on beam
  // theory), to the accuracy the bodies' rotations carry the moment across the cut.
  const double beam =
      2.0 * M_PI * 0.01 / (test::kBetaL * test::kBetaL) / std::sqrt(210e9 * 1e-6 / (12 * 7850));
  double apart = 1.0;
  std::size_t bodies = 0;
  const auto [period, drift] = test::cantilever_period(
      test::cantilever(20, 2, 0.025, "", 2, 0.3, true), 20, [&](const test::Simulation& sim) {
        bodies = sim.state->rigid_bodies.size();
        // The welded pairs stay together (63 strip nodes, then the 3 copies of column 10).
        apart = 0.0;
        for (solver::Index j = 0; j < 3; ++j)
          apart = std::max(apart, (sim.state->nodes.position.col(63 + j) -
                                   sim.state->nodes.position.col(10 + 21 * j))
                                      .norm());
      });
  MESSAGE("welded strip: period ", period * 1e3, " ms, ", 100.0 * (period / beam - 1.0),
          " % on beam theory; energy drift ", drift, "; welded nodes apart ", apart, " m");
  CHECK(bodies == 3);
  CHECK(std::abs(period / 11.9779e-3 - 1.0) < 1e-3);
  CHECK(drift < 1e-5);
  CHECK(apart < 1e-12);
}

TEST_CASE("without its welds the split cantilever comes apart") {
  // The same deck with the nodal rigid bodies taken out: the copies are free, and the outer half
  // of the strip leaves the inner one (the check that the welds above are what holds it).
  std::string deck = test::cantilever(20, 2, 0.005, "", 2, 0.3, true);
  for (std::size_t at; (at = deck.find("*CONSTRAINED_NODAL_RIGID_BODY\n")) != std::string::npos;)
    deck.erase(at, deck.find('\n', deck.find('\n', at) + 1) - at + 1);
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, deck);
  REQUIRE(sim.state->rigid_bodies.empty());
  test::run(sim);
  double apart = 0.0;
  for (solver::Index j = 0; j < 3; ++j)
    apart = std::max(
        apart, (sim.state->nodes.position.col(63 + j) - sim.state->nodes.position.col(10 + 21 * j))
                   .norm());
  MESSAGE("unwelded: the cut opens by ", apart * 1e3, " mm in 5 ms");
  CHECK(apart > 1e-4);
}

TEST_CASE("merged rigid parts and extra nodes turn as one body about their common centre") {
  // Rigid plates 1 (1 x 1 at the origin) and 2 (1 x 1 at x = 3), plate 2 merged into lead 1;
  // node 9, on no element, is an extra node of part 2 with a 1 x 1 elastic shell (part 3,
  // whose other nodes are free) giving it mass. Part 1 spins about z at 10 rad/s
  // (*BOUNDARY_PRESCRIBED_MOTION_RIGID DOF 7) with its centre held (CMO 1, CON1 7), while the
  // flap's free corners tug at node 9. Every node of the body must sit at its initial offset
  // from the common centre of mass turned by 10 t (t, mm, s units).
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir,
      "*KEYWORD\n*CONTROL_TERMINATION\n0.05\n"
      "*PART\nlead\n1,1,1\n*PART\nconstrained\n2,1,1\n*PART\nflap\n3,1,2\n"
      "*SECTION_SHELL\n1\n1.0,1.0,1.0,1.0\n*MAT_RIGID\n1,7.85e-9,210e3,0.3\n1,7,0\n"
      "*MAT_ELASTIC\n2,7.85e-9,210e3,0.3\n"
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,3,0,0\n6,4,0,0\n7,4,1,0\n8,3,1,0\n"
      "9,4,2,0\n10,5,2,0\n11,5,3,0\n12,4,3,0\n"
      "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n3,3,9,10,11,12\n"
      "*CONSTRAINED_RIGID_BODIES\n1,2\n*CONSTRAINED_EXTRA_NODES_NODE\n2,9\n"
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,7,0,1,10.0\n*DEFINE_CURVE\n1\n0,1\n1,1\n*END\n");
  REQUIRE(sim.state->rigid_bodies.size() == 1);
  const solver::RigidBody& body = sim.state->rigid_bodies.front();
  CHECK(body.nodes.size() == 9);
  // Mass: the two plates (7.85e-9 x 1 mm^2 x 1 mm each) and node 9's quarter of the flap.
  CHECK(body.mass == doctest::Approx(2.0 * 7.85e-9 + 0.25 * 7.85e-9).epsilon(1e-12));
  const solver::Vec3 centre = body.initial_center;
  std::vector<solver::Vec3> start;
  for (solver::Index n = 0; n < 9; ++n)
    start.push_back(sim.state->nodes.initial.col(n));
  test::run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const double angle = 10.0 * sim.state->time;
  const Eigen::AngleAxisd turn(angle, solver::Vec3::UnitZ());
  double worst = 0.0;
  for (solver::Index n = 0; n < 9; ++n) {
    const solver::Vec3 expected = centre + turn * (start[static_cast<std::size_t>(n)] - centre);
    worst = std::max(worst, (solver::Vec3(sim.state->nodes.position.col(n)) - expected).norm());
  }
  MESSAGE("turned ", angle, " rad about the common centre (", centre.transpose(),
          "); worst node off by ", worst, " mm");
  CHECK(worst < 1e-9);
}

TEST_CASE("joins that name deformable parts or missing sets are errors at their line") {
  auto l = test::load_text(
      "*KEYWORD\n*CONTROL_TERMINATION\n1e-3\n*PART\nplate\n1,1,1\n*SECTION_SHELL\n1\n1.0\n"
      "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n"
      "*ELEMENT_SHELL\n1,1,1,2,3,4\n*CONSTRAINED_EXTRA_NODES_NODE\n1,2\n"
      "*CONSTRAINED_RIGID_BODIES\n1,5\n*CONSTRAINED_NODAL_RIGID_BODY\n1,0,9\n*END\n",
      true);
  MESSAGE(l->messages());
  CHECK(l->has_message(
      "*CONSTRAINED_EXTRA_NODES_NODE: part 1 is not rigid (its material 1 is not *MAT_RIGID)"));
  CHECK(l->has_message("*CONSTRAINED_RIGID_BODIES refers to part 5, which is not defined"));
  CHECK(l->has_message("*CONSTRAINED_NODAL_RIGID_BODY refers to node set 9, which is not defined"));
  CHECK(l->has_message("*CONSTRAINED_NODAL_RIGID_BODY: PID 1 is also a *PART"));
}
