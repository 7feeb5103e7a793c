// Joins (issue 26): extra nodes, merged rigid bodies and nodal rigid bodies against closed-form
// answers.
#include <doctest/doctest.h>

#include <cmath>

#include "shell_decks.hpp"
#include "solver/rigid/joint_state.hpp"
#include "solver/rigid/welds.hpp"
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

namespace {

// A rigid plate pendulum (L 0.2 m, w 0.02 m, t 1 mm, steel; m, kg, s) hanging from a revolute
// joint about y through the origin to a held rigid block, swung by gravity from a small initial
// spin; a soft elastic shell elsewhere, held, sets the step (9e-5 s). Returns the period and
// the largest change of the energy (kinetic, springs, height) as a share of the swing's.
// The pendulum's deck: `joint` joins it to the support, `motion` starts it, `gravity` 9.81 or 0.
std::string pendulum_deck(const std::string& joint, const std::string& motion, double gravity) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n1.6\n"
         "*PART\npendulum\n1,1,1\n*PART\nsupport\n2,1,2\n*PART\nclock\n3,1,3\n"
         "*SECTION_SHELL\n1\n0.001,0.001,0.001,0.001\n"
         "*MAT_RIGID\n1,7850,210e9,0.3\n*MAT_RIGID\n2,7850,210e9,0.3\n1,7,7\n"
         "*MAT_ELASTIC\n3,1000,1e7,0.3\n"
         "*NODE\n1,-0.01,0,-0.2\n2,0,0,-0.2\n3,0.01,0,-0.2\n4,0.01,0,0\n5,0,0,0\n6,-0.01,0,0\n"
         "11,0,0.02,0.01\n12,0.01,0.02,0.01\n13,0.01,0.03,0.01\n14,0,0.03,0.01\n"
         "21,1,1,1\n22,1.01,1,1\n23,1.01,1.01,1\n24,1,1.01,1\n"
         "101,0,0,0\n102,0,0,0\n103,0,0.01,0\n104,0,0.01,0\n105,0.01,0,0\n106,0.01,0,0\n"
         "*ELEMENT_SHELL\n1,1,1,2,5,6\n2,1,2,3,4,5\n3,2,11,12,13,14\n4,3,21,22,23,24\n"
         "*CONSTRAINED_EXTRA_NODES_NODE\n1,101\n1,103\n1,105\n2,102\n2,104\n2,106\n"
         "*BOUNDARY_SPC_NODE\n21,0,1,1,1,1,1,1\n22,0,1,1,1,1,1,1\n23,0,1,1,1,1,1,1\n"
         "24,0,1,1,1,1,1,1\n" +
         joint + "*SET_PART_LIST\n1\n1\n*INITIAL_VELOCITY_GENERATION\n" + motion +
         fmt::format("*LOAD_BODY_Z\n1\n*DEFINE_CURVE\n1\n0,{0}\n10,{0}\n*END\n", gravity);
}

std::pair<double, double> pendulum(const std::string& joint) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, pendulum_deck(joint, "1,1,0.2\n0,0,0,0,1,0\n", 9.81));
  // The energy: kinetic, the joint springs', and the pendulum's height in gravity.
  std::vector<double> crossings, energy;
  double last_x = 0.0, last_t = 0.0, swing = 0.0;
  solver::RunHooks hooks;
  hooks.output_due = [](const solver::State&) { return true; };
  hooks.write = [&](const solver::State& s, const Eigen::Matrix3Xd& previous, bool) {
    const solver::EnergySummary e = solver::energy_summary(s, previous);
    const solver::RigidBody& b = s.rigid_bodies.front();
    energy.push_back(e.kinetic + e.internal + b.mass * 9.81 * b.center.z());
    swing = std::max(swing, e.kinetic);
  };
  hooks.progress = [&](const solver::State& s) {
    const double x = s.nodes.position(0, 1);  // node 2, the bottom centre
    if (last_t > 0.0 && x * last_x < 0.0)
      crossings.push_back(last_t - last_x * (s.time - last_t) / (x - last_x));
    last_x = x;
    last_t = s.time;
  };
  test::run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  REQUIRE(crossings.size() >= 3);
  double drift = 0.0;
  for (const double e : energy)
    drift = std::max(drift, std::abs(e - energy.front()) / swing);
  return {2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1),
          drift};
}

}  // namespace

TEST_CASE("revolute and spherical joints: a plate pendulum swings at its compound period") {
  // T = 2 pi sqrt(I_pivot / (m g d)) for small swings, I_pivot = m ((L^2 + w^2) / 12 + d^2),
  // d = L / 2: 0.73339 s. The swing here is 0.02 rad: the amplitude lengthens the period by
  // theta^2 / 16 = 2.5e-5, and the joint's spring (period 4 pi dt) by (dt omega_0 / 2)^2,
  // both well inside the 0.1 % asked.
  const double length = 0.2, width = 0.02, d = length / 2;
  const double period =
      2.0 * M_PI * std::sqrt(((length * length + width * width) / 12.0 + d * d) / (9.81 * d));
  for (const char* joint : {"*CONSTRAINED_JOINT_REVOLUTE\n101,102,103,104\n",
                            "*CONSTRAINED_JOINT_SPHERICAL\n101,102\n"}) {
    CAPTURE(joint);
    const auto [measured, drift] = pendulum(joint);
    MESSAGE(std::string(joint), "period ", measured, " s against ", period, " s (",
            100.0 * (measured / period - 1.0), " %), energy drift ", drift);
    CHECK(std::abs(measured / period - 1.0) < 1e-3);
    CHECK(drift < 1e-3);
  }
}

TEST_CASE(
    "cylindrical and translational joints free the slide, and the turn only when cylindrical") {
  // No gravity; the pendulum plate starts sliding along the joint's axis (y) at 1 m/s, and on
  // the cylindrical joint also turning about it at 2 rad/s (a start both joints allow, so that
  // no impact sets their undamped springs ringing). The springs have no axial part: the
  // plate's centre travels 1 m/s x t along y, and the cylindrical joint keeps the turn, while
  // both hold the pairs on the axis (to the springs' give).
  for (const bool cylindrical : {true, false}) {
    CAPTURE(cylindrical);
    const std::string joint = cylindrical
                                  ? "*CONSTRAINED_JOINT_CYLINDRICAL\n101,102,103,104\n"
                                  : "*CONSTRAINED_JOINT_TRANSLATIONAL\n101,102,103,104,105,106\n";
    const std::string motion =
        cylindrical ? "1,1,2.0,0,1.0,0\n0,0,0,0,1,0\n" : "1,1,0,0,1.0,0\n0,0,0,0,1,0\n";
    std::string text = pendulum_deck(joint, motion, 0.0);
    text.replace(text.find("1.6\n"), 4, "0.05\n");
    test::TempDir dir;
    test::Simulation run = test::prepare(dir, text);
    const solver::Vec3 start = run.state->rigid_bodies.front().center;
    double across = 0.0;  // of the pair (101, 102), normal to the axis
    solver::RunHooks hooks;
    hooks.progress = [&](const solver::State& s) {
      const solver::Vec3 d = s.nodes.position.col(15) - s.nodes.position.col(14);
      across = std::max(across, std::hypot(d.x(), d.z()));
    };
    test::run(run, hooks);
    REQUIRE(run.result.reason == solver::StopReason::end_time);
    const solver::RigidBody& b = run.state->rigid_bodies.front();
    const double slide = b.center.y() - start.y();
    MESSAGE("slide ", slide, " m in ", run.state->time, " s; spin about y ", b.omega.y(),
            " rad/s; pair 1 apart across the axis by at most ", across, " m");
    // The turn loads the pairs (centripetal), their give tilts the axis by ~2e-3 rad, and the
    // pull then has a share along y of that order squared.
    CHECK(slide == doctest::Approx(1.0 * run.state->time).epsilon(1e-5));
    CHECK(across < 1e-4);
    CHECK(b.omega.y() == doctest::Approx(cylindrical ? 2.0 : 0.0).epsilon(1e-3).scale(1.0));
  }
}

TEST_CASE("a generalized joint stiffness turns elastically, then slips at its friction moment") {
  // The pendulum plate on its revolute joint (axis y), no gravity, turned by a moment about y
  // rising as 0.2 t N m (*LOAD_RIGID_BODY DOF 6) against a joint stiffness about the axis
  // (local x = global y, *DEFINE_COORDINATE_NODE on the joint's nodes): ES 1 N m/rad, FM 0.1
  // N m. Until t = 0.5 s the plate turns M / ES (its own period, 0.13 s, is short against the
  // ramp: the lag is M' / (ES w) = 4e-3 rad); then the friction slips and the plate speeds up
  // by (M - FM) / I: at 0.6 s, 0.001 / I = 2.38 rad/s, give or take the ringing left from the
  // elastic phase, M' / ES = 0.2 rad/s.
  const std::string stiffness =
      "*CONSTRAINED_JOINT_REVOLUTE\n101,102,103,104\n"
      "*DEFINE_COORDINATE_NODE\n1,101,103,105\n*DEFINE_COORDINATE_NODE\n2,102,104,106\n"
      "*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED\n1,1,2,1,2\n\n1.0,0.1\n"
      "*LOAD_RIGID_BODY\n1,6,7\n*DEFINE_CURVE\n7\n0,0\n10,2\n";
  const double length = 0.2, width = 0.02, d = length / 2;
  const double inertia =
      7850 * 0.001 * length * width * ((length * length + width * width) / 12 + d * d);
  for (const double end : {0.45, 0.6}) {
    std::string text = pendulum_deck(stiffness, "1,1,0\n0,0,0,0,1,0\n", 0.0);
    text.replace(text.find("1.6\n"), 4, fmt::format("{}\n", end));
    test::TempDir dir;
    test::Simulation sim = test::prepare(dir, text);
    REQUIRE(solver::joint_stiffnesses_of(*sim.state).size() == 1);
    double turned = 0.0;
    solver::RunHooks hooks;
    hooks.progress = [&](const solver::State& s) {
      turned = Eigen::AngleAxisd(s.rigid_bodies.front().rotation).angle() *
               Eigen::AngleAxisd(s.rigid_bodies.front().rotation).axis().y();
    };
    test::run(sim, hooks);
    REQUIRE(sim.result.reason == solver::StopReason::end_time);
    const double t = sim.state->time, spin = sim.state->rigid_bodies.front().omega.y();
    MESSAGE("t ", t, ": turned ", turned, " rad, spin ", spin, " rad/s");
    if (end < 0.5) {
      CHECK(turned == doctest::Approx(0.2 * t / 1.0).epsilon(0.05));
    } else {
      CHECK(spin == doctest::Approx(0.001 / inertia).epsilon(0.1));
    }
  }
}

namespace {

// Lap joint (t, mm, s units): plate A, a 10 x 10 mm steel shell 10 mm thick (stiff: its corner
// barely turns, so the weld stays along z) at z = 0 held at three corners, and plate B, 1 mm
// thick, at z = 1, joined by a spot weld from A's free corner (node 1) to
// the corner above it (node 5), node 5 pulled by 1e4 t N along `direction` (B's other corners
// free, so B's plate only rides along: pulling its far corners instead would spin it about
// the weld, which holds no drilling).
// `weld` is the weld's keyword and card (nodes 1 and 5 or set 9). Returns when it failed (-1:
// it held), node 5's height at the end, and the weld's normal and shear force when it failed.
struct LapJoint {
  double failed = -1.0, height = 0.0, normal = 0.0, shear = 0.0;
};
LapJoint pulled_lap_joint(const std::string& weld, const std::string& direction,
                          double end = 0.02) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir, "*KEYWORD\n*CONTROL_TERMINATION\n" + std::to_string(end) +
               "\n*PART\nA\n1,2,1\n*PART\nB\n2,1,1\n"
               "*SECTION_SHELL\n1,2\n1.0,1.0,1.0,1.0\n*SECTION_SHELL\n2,2\n10.0,10.0,10.0,10.0\n"
               "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n"
               "*NODE\n1,0,0,0\n2,10,0,0\n3,10,10,0\n4,0,10,0\n5,0,0,1\n6,10,0,1\n7,10,10,1\n"
               "8,0,10,1\n"
               "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n"
               "*SET_NODE_LIST\n1\n2,3,4\n*BOUNDARY_SPC_SET\n1,0,1,1,1,1,1,1\n"
               "*SET_NODE_LIST\n2\n5,6,7,8\n*SET_NODE_LIST\n9\n1,5\n" +
               direction + "*DEFINE_CURVE\n1\n0,0\n1,10000\n" + weld + "*END\n");
  REQUIRE(solver::welds_of(*sim.state).size() == 1);
  // Stopped 20 cycles after the weld lets go: then B's corner, pulled alone by the load on its
  // few grams, is no longer what the test is about.
  solver::RunHooks hooks;
  long cycles_since = 0;
  hooks.stop_requested = [&] {
    return solver::welds_of(*sim.state)[0].failed_at >= 0.0 && ++cycles_since > 20;
  };
  test::run(sim, hooks);
  REQUIRE((sim.result.reason == solver::StopReason::end_time || cycles_since > 20));
  const solver::WeldState& w = solver::welds_of(*sim.state)[0];
  return {w.failed_at, sim.state->nodes.position(2, 4), w.normal, w.shear};  // node 5: index 4
}

}  // namespace

TEST_CASE("spot welds fail at the force their criterion names") {
  // B pulled along z (normal), x (shear) or both (1e4 t N along each); SN 100 N, SS 200 N,
  // N = M = 2. Slow against the joint's own vibration (its period is about 0.1 ms), the weld
  // carries the whole pull F = 1e4 t: it fails when F = SN (10 ms), F = SS (20 ms), or
  // (F / SN)^2 + (F / SS)^2 = 1, F = 89.44 N (8.944 ms).
  const std::string spotweld = "*CONSTRAINED_SPOTWELD\n1,5,100.0,200.0,2.0,2.0\n";
  const std::string normal = "*LOAD_NODE_POINT\n5,3,1,1.0\n";
  const std::string shear = "*LOAD_NODE_POINT\n5,1,1,1.0\n";
  struct Case {
    std::string what;
    std::string load;
    double expected;
  };
  const double combined = 1.0 / std::sqrt(1e-4 + 2.5e-5) / 1e4;
  for (const Case& c : {Case{"normal", normal, 0.01}, Case{"shear", shear, 0.02},
                        Case{"both", normal + shear, combined}}) {
    const LapJoint j = pulled_lap_joint(spotweld, c.load, c.expected + 3e-4);
    MESSAGE(c.what, ": failed at ", j.failed * 1e3, " ms against ", c.expected * 1e3, " ms (",
            100.0 * (j.failed / c.expected - 1.0), " %), normal ", j.normal, " N, shear ", j.shear,
            " N");
    CHECK(std::abs(j.failed / c.expected - 1.0) < 0.01);
  }
  // The same weld as a *CONSTRAINED_GENERALIZED_WELD_SPOT of set 9, and with a failure time.
  const LapJoint generalized = pulled_lap_joint(
      "*CONSTRAINED_GENERALIZED_WELD_SPOT\n9\n1e20,1e20,100.0,200.0,2.0,2.0\n", normal, 0.0103);
  CHECK(std::abs(generalized.failed / 0.01 - 1.0) < 0.01);
  CHECK(generalized.height > 1.05);  // B leaves once free: it was held at z = 1 before
  const LapJoint timed =
      pulled_lap_joint("*CONSTRAINED_SPOTWELD\n1,5,0,0,0,0,5e-3\n", normal, 5.3e-3);
  CHECK(std::abs(timed.failed / 5e-3 - 1.0) < 0.01);
  // Pushed together it holds (only tension counts in the normal term).
  const LapJoint pressed = pulled_lap_joint(spotweld, "*LOAD_NODE_POINT\n5,3,1,-1.0\n", 0.012);
  CHECK(pressed.failed < 0.0);
}

TEST_CASE("*PART_INERTIA gives a rigid part its mass, centre, inertia and velocity") {
  // A 1 x 1 mm rigid shell plate (t, mm, s) whose *PART_INERTIA says mass 2, centre at node 5
  // (off the plate), inertia diag(1, 2, 3) and velocity (1, 0, 0) mm/s; a moment of 6 N mm about z
  // (*LOAD_RIGID_BODY) spins it up at M / Izz = 2 rad/s^2 about its given centre, which moves at
  // 1 mm/s. After 0.5 s: centre (0.5, 0, 0) + node 5's place, omega 1 rad/s, angle 0.25 rad.
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir,
      "*KEYWORD\n*CONTROL_TERMINATION\n0.5\n*CONTROL_TIMESTEP\n1e-4\n"
      "*PART_INERTIA\nplate\n1,1,1\n0,0,0,2.0,0,5\n1.0,0,0,2.0,0,3.0\n1.0,0,0,0,0,0\n"
      "*SECTION_SHELL\n1\n1.0,1.0,1.0,1.0\n*MAT_RIGID\n1,7.85e-9,210e3,0.3\n"
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n"
      "*CONSTRAINED_EXTRA_NODES_NODE\n1,5\n"
      "*LOAD_RIGID_BODY\n1,7,1,6.0\n*DEFINE_CURVE\n1\n0,1\n1,1\n*END\n");
  REQUIRE(sim.state->rigid_bodies.size() == 1);
  const solver::RigidBody& b = sim.state->rigid_bodies[0];
  CHECK(b.mass == 2.0);
  CHECK(b.center.isApprox(Eigen::Vector3d(2, 0, 0)));
  CHECK(b.inertia0(2, 2) == 3.0);
  test::run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const double t = sim.state->time;
  MESSAGE("centre x ", b.center.x(), " (", 2.0 + t, "), omega ", b.omega.z(), " (", 2.0 * t,
          "), node 1 at ", sim.state->nodes.position.col(0).transpose());
  CHECK(std::abs(b.center.x() - (2.0 + t)) < 1e-9);
  CHECK(std::abs(b.omega.z() / (2.0 * t) - 1.0) < 1e-3);
  // Node 1 turned by t^2 about the centre: it started 2 mm behind it along -x.
  const double angle = t * t;
  const Eigen::Vector3d expected(2.0 + t - 2.0 * std::cos(angle), -2.0 * std::sin(angle), 0.0);
  CHECK((sim.state->nodes.position.col(0) - expected).norm() < 1e-3 * angle);
}
