// Penalty contact: an elastic bar dropped on a rigid shell plate rebounds as on a rigid wall,
// with the contact impulse equal to its momentum change and little penetration; a block slides
// down an inclined rigid plane with the analytic Coulomb deceleration; two blocks colliding
// through a surface-to-surface contact keep the total momentum; MC-SPG particles as slave nodes.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>

#include "solver/contact/ties.hpp"
#include "solver/energy.hpp"
#include "solver/history_records.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

// A rigid steel shell plate (one segment, 1 mm thick) from (x0, y0) to (x1, y1) with its
// mid-surface at z = -0.5 - shift: the automatic contact's half thickness puts its top face at
// z = -shift. Nodes 9001-9004, part 9, fully constrained.
std::string rigid_plate(double x0, double y0, double x1, double y1, double shift = 0.0) {
  return "*PART\nplate\n9,9,9\n*SECTION_SHELL\n9\n1.0,1.0,1.0,1.0\n"
         "*MAT_RIGID\n9,7.85e-9,210000.0,0.3\n1,7,7\n" +
         fmt::format(
             "*NODE\n9001,{0},{1},{4}\n9002,{2},{1},{4}\n9003,{2},{3},{4}\n9004,{0},{3},{4}\n", x0,
             y0, x1, y1, -0.5 - shift) +
         "*ELEMENT_SHELL\n9001,9,9001,9002,9003,9004\n";
}

std::string header(double end_time) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n" + fmt::format("{:.4e}\n", end_time);
}

// Mass-weighted mean velocity and lowest z of the nodes [first, last).
struct Motion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double lowest = 1e30, mass = 0.0;
};

Motion motion(const solver::State& s, solver::Index first, solver::Index last) {
  Motion m;
  for (solver::Index n = first; n < last; ++n) {
    const double mn = s.nodes.mass[static_cast<std::size_t>(n)];
    m.velocity += mn * s.nodes.velocity.col(n);
    m.mass += mn;
    m.lowest = std::min(m.lowest, s.nodes.position(2, n));
  }
  m.velocity /= m.mass;
  return m;
}

// Steel bar 2 x 2 x 20 mm (2 x 2 x 20 one-point hexahedra), units mm, s, t, MPa, 0.01 mm above
// z = 0, falling at 5 m/s.
constexpr double kSpeed = 5000.0;
const std::string kBar =
    "*PART\nbar\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
    box_mesh(2, 2, 20, 1.0, 1, 1, 1, 0.01) + "*SET_PART_LIST\n1\n1\n" +
    fmt::format("*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,{}\n0,0,0\n", -kSpeed);
constexpr solver::Index kBarNodes = 3 * 3 * 21;

}  // namespace

TEST_CASE("contact: an elastic bar dropped on a rigid shell plate rebounds, impulse = momentum") {
  TempDir dir;
  // 1-D theory: contact for 2 L / c = 7.74 us (the bar's foot keeps tapping the plate a little
  // longer as it rings), rebound at the impact speed.
  const double c = std::sqrt(210000.0 / 7.85e-9), contact_time = 2.0 * 20.0 / c;
  const double end = 2e-6 + 1.5 * contact_time;
  Simulation sim = prepare(dir, header(end) + kBar + rigid_plate(-10, -10, 12, 12) +
                                    "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n0,0\n\n*END\n");
  REQUIRE(solver::contact::interfaces_of(*sim.state).size() == 1);
  const double mass = 80.0 * 7.85e-9;
  double impulse = 0.0, lowest = 0.0, first = -1.0, last = -1.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    const solver::contact::Interface& in = contact_interface(s, 0);
    // The force found at t^n acts over the mean step around t^n; the next step is the one the
    // solver will take, its size not known here, and it equals this one in this run.
    impulse += in.force_a.z() * s.step;
    lowest = std::min(lowest, motion(s, 0, kBarNodes).lowest);
    if (in.force_a.z() > 0.0) {
      if (first < 0.0) first = s.time;
      last = s.time;
    }
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const Motion after = motion(*sim.state, 0, kBarNodes);
  const solver::contact::Interface& in = contact_interface(*sim.state, 0);
  MESSAGE("rebound ", after.velocity.z(), " mm/s, impulse ", impulse, " (m dv ",
          mass * (after.velocity.z() + kSpeed), "), contact ", last - first, " s (2L/c ",
          contact_time, "), lowest z ", lowest, ", interface energy ", in.energy);
  // The contact is the only external force: its impulse is the bar's change of momentum (up
  // to the step-size variation the hook's sum does not see).
  CHECK(impulse == doctest::Approx(mass * (after.velocity.z() + kSpeed)).epsilon(1e-3).scale(0.0));
  // 1-D theory returns v0; a 2 x 2 mm bar keeps some energy in lateral and hourglass vibration
  // (measured on the rigid wall below: 0.944 v0).
  CHECK(after.velocity.z() > 0.93 * kSpeed);
  CHECK(after.velocity.z() < kSpeed);
  // Penetration: the penalty spring (0.1 K A^2 / V = 17,500 N/mm per node) under the impact
  // stress rho c v = 203 MPa lets the face in by ~0.01 mm, 1 % of the 1 mm element.
  CHECK(lowest > -0.02);
  // Elastic impact: the interface gives back what it stored (energy ratio of the run ~1).
  CHECK(std::abs(in.energy) < 1e-3 * 0.5 * mass * kSpeed * kSpeed);

  // The same bar on a rigid wall (constraint method) rebounds at nearly the same speed.
  Simulation wall = prepare(dir, header(end) + kBar + "*RIGIDWALL_PLANAR\n0\n0,0,0,0,0,1\n*END\n");
  run(wall);
  const double on_wall = motion(*wall.state, 0, kBarNodes).velocity.z();
  MESSAGE("rigid wall rebound ", on_wall);
  CHECK(after.velocity.z() == doctest::Approx(on_wall).epsilon(0.03).scale(0.0));
}

TEST_CASE("contact: a node stays on the side of a thin two-sided shell it came from") {
  TempDir dir;
  // The bar on a rigid plate only 0.004 mm thick (automatic contact: touched 0.002 mm from its
  // mid-surface on either side) at the top face z = 0: the impact drives the foot ~0.01 mm in,
  // past the mid-surface. Held on the side it came from, the bar still rebounds.
  std::string plate =
      with(rigid_plate(-10, -10, 12, 12, -0.498), "1.0,1.0,1.0,1.0", "0.004,0.004,0.004,0.004");
  const double end = 2e-6 + 1.5 * 2.0 * 20.0 / std::sqrt(210000.0 / 7.85e-9);
  Simulation sim = prepare(dir, header(end) + kBar + plate +
                                    "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n0,0\n\n*END\n");
  CHECK(contact_interface(*sim.state, 0).passes[0].surface.half_thickness[0] == 0.002);
  double lowest = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    lowest = std::min(lowest, motion(s, 0, kBarNodes).lowest);
  };
  run(sim, hooks);
  const double rebound = motion(*sim.state, 0, kBarNodes).velocity.z();
  MESSAGE("thin plate: rebound ", rebound, ", lowest z ", lowest);
  CHECK(lowest < -0.002);  // it did pass the mid-surface
  CHECK(rebound > 0.93 * kSpeed);
}

TEST_CASE("contact: a block slides down an inclined rigid plane at g (sin - mu cos)") {
  TempDir dir;
  // A 5 mm elastic cube on a plane inclined 30 degrees about y (everything turned), gravity
  // down -z, Coulomb friction 0.2, moving down-slope from the start so it slides throughout.
  const double angle = std::acos(-1.0) / 6.0, mu = 0.2, g = 9810.0;
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();  // e_x down-slope
  // Local frame: the plane z = 0 (rigid shell, mid-surface 0.5 below), slope down +x.
  std::string nodes = "*NODE\n";
  auto id = [](int i, int j, int k) { return 1 + i + 3 * (j + 3 * k); };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d x = turn * Eigen::Vector3d(2.5 * i, 2.5 * j, 2.5 * k);
        nodes += fmt::format("{},{:.12f},{:.12f},{:.12f}\n", id(i, j, k), x.x(), x.y(), x.z());
      }
  for (int c = 0; c < 4; ++c) {
    const double u = c == 1 || c == 2 ? 200.0 : -20.0, v = c >= 2 ? 25.0 : -20.0;
    const Eigen::Vector3d x = turn * Eigen::Vector3d(u, v, -0.5);
    nodes += fmt::format("{},{:.12f},{:.12f},{:.12f}\n", 9001 + c, x.x(), x.y(), x.z());
  }
  std::string elements = "*ELEMENT_SOLID\n";
  int e = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        elements += fmt::format("{},1,{},{},{},{},{},{},{},{}\n", e++, id(i, j, k), id(i + 1, j, k),
                                id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1));
  const Eigen::Vector3d down_slope = turn * Eigen::Vector3d::UnitX();
  const double v0 = 50.0, end = 0.02;
  const std::string deck =
      header(end) +
      "*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,1000.0,0.3\n" +
      "*PART\nplane\n9,9,9\n*SECTION_SHELL\n9\n1.0,1.0,1.0,1.0\n*MAT_RIGID\n9,7.85e-9,210000.0,0."
      "3\n"
      "1,7,7\n" +
      nodes + elements + "*ELEMENT_SHELL\n9001,9,9001,9002,9003,9004\n*SET_PART_LIST\n1\n1\n" +
      fmt::format("*INITIAL_VELOCITY_GENERATION\n1,1,0,{},{},{}\n0,0,0\n", v0 * down_slope.x(),
                  v0 * down_slope.y(), v0 * down_slope.z()) +
      fmt::format("*LOAD_BODY_Z\n1\n*DEFINE_CURVE\n1\n0,{0}\n1,{0}\n", g) +
      fmt::format("*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n{0},{0}\n\n*END\n", mu);
  Simulation sim = prepare(dir, deck);
  std::vector<std::pair<double, double>> history;  // (t, down-slope velocity)
  double deepest = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    history.emplace_back(s.time, motion(s, 0, 27).velocity.dot(down_slope));
    for (solver::Index n = 0; n < 27; ++n)  // distance above the plane (normal = turn e_z)
      deepest = std::min(deepest, (turn.transpose() * s.nodes.position.col(n)).z());
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  // Least-squares slope of v(t) after the first 2 ms (the block settles on its contact springs).
  double st = 0, sv = 0, stt = 0, stv = 0, count = 0;
  for (const auto& [t, v] : history)
    if (t > 0.002) {
      st += t, sv += v, stt += t * t, stv += t * v, ++count;
    }
  const double slope = (count * stv - st * sv) / (count * stt - st * st);
  const double expected = g * (std::sin(angle) - mu * std::cos(angle));
  MESSAGE("down-slope acceleration ", slope, " mm/s^2 (analytic ", expected, "), deepest ", deepest,
          " mm");
  // The normal force oscillates on the contact springs about m g cos; friction follows it while
  // sliding, so the mean deceleration is mu g cos. Measured within 0.5 %.
  CHECK(slope == doctest::Approx(expected).epsilon(0.01).scale(0.0));
  CHECK(deepest > -0.05 * 2.5);  // penetration under 5 % of the element
}

TEST_CASE("contact: surface to surface runs both ways and keeps the total momentum") {
  TempDir dir;
  // Two elastic cubes (1 mm, 2 x 2 x 2 elements) meeting head-on at 10 m/s each along z; part
  // 2 above part 1 with a 0.01 mm gap.
  const std::string deck = header(4e-6) +
                           "*PART\nlow\n1,1,1\n*PART\nhigh\n2,1,1\n*SECTION_SOLID\n1,1\n"
                           "*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
                           box_mesh(2, 2, 2, 0.5, 1, 1, 1, 0.0) +
                           box_mesh(2, 2, 2, 0.5, 101, 101, 2, 1.01) +
                           "*SET_PART_LIST\n1\n1\n*SET_PART_LIST\n2\n2\n"
                           "*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,10000\n0,0,0\n"
                           "*INITIAL_VELOCITY_GENERATION\n2,1,0,0,0,-10000\n0,0,0\n"
                           "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n0,0\n\n*END\n";
  Simulation sim = prepare(dir, deck);
  REQUIRE(solver::contact::interfaces_of(*sim.state).size() == 1);
  CHECK(contact_interface(*sim.state, 0).passes.size() == 2);
  double largest = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    largest = std::max(largest, std::abs(contact_interface(s, 0).force_a.z()));
    // Equal and opposite: the forces on the two sides balance to round-off.
    CHECK((contact_interface(s, 0).force_a + contact_interface(s, 0).force_b).norm() <=
          1e-12 * std::max(1.0, contact_interface(s, 0).force_a.norm()));
  };
  run(sim, hooks);
  const Motion low = motion(*sim.state, 0, 27), high = motion(*sim.state, 27, 54);
  MESSAGE("after: low ", low.velocity.z(), ", high ", high.velocity.z(), " mm/s; peak force ",
          largest);
  CHECK(largest > 0.0);
  CHECK(std::abs(low.mass * low.velocity.z() + high.mass * high.velocity.z()) <
        1e-12 * low.mass * 10000.0);
  CHECK(low.velocity.z() < 0.0);  // they bounced apart
  CHECK(high.velocity.z() > 0.0);
}

TEST_CASE("contact: MC-SPG particles as slave nodes bounce off a rigid plate") {
  TempDir dir;
  // An aluminium MC-SPG cube (4 x 4 x 4 mm, 0.5 mm nodal spacing) falling at 5 m/s.
  const std::string deck =
      header(1.2e-5) +
      "*PART\ncube\n1,1,1\n*SECTION_SOLID_SPG\n1,47\n1.5,1.5,1.5,0,0,,15\n"
      "1,,,3\n*MAT_ELASTIC\n1,2.7e-9,70000.0,0.33\n" +
      box_mesh(8, 8, 8, 0.5, 1, 1, 1, 0.01) + rigid_plate(-5, -5, 10, 10) +
      "*SET_PART_LIST\n1\n1\n*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,-5000\n0,0,0\n"
      "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n0,0\n\n*END\n";
  Simulation sim = prepare(dir, deck);
  REQUIRE(solver::spg::domains_of(*sim.state).size() == 1);
  const solver::Index particles = 9 * 9 * 9;
  CHECK(contact_interface(*sim.state, 0).passes[0].nodes.size() ==
        static_cast<std::size_t>(particles));
  double impulse = 0.0, lowest = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    impulse += contact_interface(s, 0).force_a.z() * s.step;
    for (solver::Index n = 0; n < particles; ++n)
      lowest = std::min(lowest, s.nodes.position(2, n));
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  // Momentum of the particles as MC-SPG carries it (unsmoothed velocities); the plate is fixed.
  const solver::EnergySummary k = solver::energy_summary(*sim.state, sim.state->nodes.velocity);
  const double mass = 64.0 * 2.7e-9;
  MESSAGE("SPG cube: momentum z ", k.momentum.z(), " (start ", -mass * 5000.0, "), impulse ",
          impulse, ", lowest ", lowest);
  CHECK(k.mass == doctest::Approx(mass + 15.0 * 15.0 * 7.85e-9).epsilon(1e-9).scale(0.0));
  CHECK(impulse == doctest::Approx(k.momentum.z() + mass * 5000.0).epsilon(2e-3).scale(0.0));
  CHECK(k.momentum.z() > 0.8 * mass * 5000.0);  // bounced back up, elastic
  CHECK(lowest > -0.05 * 0.5);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

namespace {

// An elastic 2 x 2 x 2 block at rest whose bottom starts 0.02 mm inside the plate's contact
// surface (z = 0).
std::string sunk_block(const std::string& control) {
  return header(2e-6) + control +
         "*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
         box_mesh(2, 2, 2, 1.0, 1, 1, 1, -0.02) + rigid_plate(-10, -10, 12, 12) +
         "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n0,0\n\n*END\n";
}

// Runs `sim` to its end and returns the largest contact force contact 1 applied.
double largest_contact_force(Simulation& sim) {
  double largest = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    largest = std::max(largest, contact_interface(s, 0).force_a.norm());
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  return largest;
}

double lowest_z(const solver::State& s) {
  double z = 1e30;
  for (solver::Index n = 0; n < 27; ++n)
    z = std::min(z, s.nodes.position(2, n));
  return z;
}

}  // namespace

TEST_CASE("contact: every node of a node-set side has a penalty, interior FE nodes too") {
  TempDir dir;
  // All 27 nodes of the block as the slave node set; node 14 is its centre, on no free face.
  std::string nodes = "*SET_NODE_LIST\n5\n";
  for (int n = 1; n <= 27; ++n)
    nodes += fmt::format("{}{}", n, n % 8 == 0 || n == 27 ? "\n" : ",");
  std::string deck = sunk_block("");
  deck = with(deck, "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n",
              nodes + "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n5,9,4,3\n");
  Simulation sim = prepare(dir, deck);
  const solver::contact::Pass& p = contact_interface(*sim.state, 0).passes.at(0);
  REQUIRE(p.nodes.size() == 27);
  for (const double k : p.stiffness)
    CHECK(k > 0.0);
  // SLSFAC x K V^(1/3) of its unit elements: 0.1 x 210000 / (3 (1 - 0.6)).
  const auto centre = std::find(p.nodes.begin(), p.nodes.end(), 13) - p.nodes.begin();
  CHECK(p.stiffness[static_cast<std::size_t>(centre)] ==
        doctest::Approx(0.1 * 210000.0 / 1.2).scale(0.0).epsilon(1e-12));
}

TEST_CASE("contact: a part as nodes-to-surface slave gives all its nodes, interior ones too") {
  TempDir dir;
  // 3 x 3 x 3 hexahedra: 64 nodes, 8 of them inside. Once the elements around an interior node
  // erode it meets the master surface, so it is a slave node from the start.
  const std::string deck =
      header(1e-7) +
      "*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
      box_mesh(3, 3, 3, 1.0, 1, 1, 1, 0.1) + rigid_plate(-10, -10, 12, 12) +
      "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n1,9,3,3\n0,0\n\n*END\n";
  Simulation n2s = prepare(dir, deck);
  CHECK(contact_interface(*n2s.state, 0).passes.at(0).nodes.size() == 64);
  // Surface to surface works on the free faces: 56 surface nodes.
  Simulation s2s = prepare(dir, with(deck, "*CONTACT_AUTOMATIC_NODES_TO_SURFACE",
                                     "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE"));
  CHECK(contact_interface(*s2s.state, 0).passes.at(0).nodes.size() == 56);
}

TEST_CASE("contact: initial penetrations are reported, moved out (IGNORE 0) or tracked (1)") {
  TempDir dir;
  // IGNORE 0 (default): the nine bottom nodes are moved onto the surface, initial position too,
  // and the block then stays at rest.
  dir.write("deck.k", sunk_block(""));
  const Run r = run_mcdyna("run deck.k --out out -q", "cd " + dir.path().string() + " && ");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("contact 1: 9 slave node(s) start inside the master surface, deepest 0.02 "
                      "at node ") != std::string::npos);
  CHECK(r.output.find("; 9 moved onto the surface") != std::string::npos);
  Simulation moved = prepare(dir, sunk_block(""));
  CHECK(lowest_z(*moved.state) == doctest::Approx(0.0).scale(1.0).epsilon(1e-12));
  CHECK(moved.state->nodes.initial(2, 0) == doctest::Approx(0.0).scale(1.0).epsilon(1e-12));
  // IGNORE 1: they stay where they are and contact pushes only beyond that depth: a block at
  // rest feels no force (the full penalty on 0.02 mm would throw it off the plate).
  for (const std::string& control :
       {std::string("*CONTROL_CONTACT\n0.1\n\n\n1\n"), std::string("")}) {
    Simulation sim = prepare(dir, sunk_block(control));
    const bool tracked = !control.empty();
    CHECK(lowest_z(*sim.state) == doctest::Approx(tracked ? -0.02 : 0.0).scale(1.0).epsilon(1e-12));
    const double largest = largest_contact_force(sim);
    MESSAGE((tracked ? "IGNORE 1" : "IGNORE 0"), ": largest contact force ", largest);
    CHECK(largest == 0.0);
    CHECK(std::abs(motion(*sim.state, 0, 27).velocity.z()) < 1e-9);
  }
}

}  // namespace mcdyna::test

namespace mcdyna::test {

namespace {

// Three elastic cubes (1 mm, 2 x 2 x 2 elements) in a column along z, 0.01 mm apart: the bottom
// one rising and the top one falling at 10 m/s onto the middle one at rest. Contacts 1-2 and
// 2-3 (surface to surface), after `transducers` in the deck.
std::string cube_column(const std::string& transducers) {
  return header(4e-6) +
         "*PART\nlow\n1,1,1\n*PART\nmiddle\n2,1,1\n*PART\nhigh\n3,1,1\n*SECTION_SOLID\n1,1\n"
         "*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
         box_mesh(2, 2, 2, 0.5, 1, 1, 1, 0.0) + box_mesh(2, 2, 2, 0.5, 101, 101, 2, 1.01) +
         box_mesh(2, 2, 2, 0.5, 201, 201, 3, 2.02) +
         "*SET_PART_LIST\n1\n1\n*SET_PART_LIST\n3\n3\n"
         "*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,10000\n0,0,0\n"
         "*INITIAL_VELOCITY_GENERATION\n3,1,0,0,0,-10000\n0,0,0\n" +
         transducers +
         "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n0,0\n\n"
         "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n2,3,3,3\n0,0\n\n*END\n";
}

}  // namespace

TEST_CASE("contact: a force transducer reports the other contacts' forces and applies none") {
  TempDir dir;
  // Transducer 1 on the middle cube alone; transducer 2 between the middle and the top cube.
  Simulation sim = prepare(dir, cube_column("*CONTACT_FORCE_TRANSDUCER_PENALTY\n2,0,3\n\n\n"
                                            "*CONTACT_FORCE_TRANSDUCER_PENALTY\n2,3,3,3\n\n\n"));
  const std::vector<const solver::contact::Interface*> c =
      solver::contact::interfaces_of(*sim.state);
  REQUIRE(c.size() == 4);
  CHECK(c[0]->id == 1);  // numbered in deck order, as rcforc lists them
  CHECK(c[3]->id == 4);
  CHECK(c[0]->passes.empty());
  // rcforc's lines come in the deck's order though the transducers' blocks run after the
  // contacts' (history_records.hpp).
  std::vector<model::Id> listed;
  for (const solver::ContactRecord& r : solver::history_records(*sim.state).contacts)
    listed.push_back(r.id);
  CHECK(listed == std::vector<model::Id>{1, 2, 3, 4});
  double peak_low = 0.0, peak_high = 0.0;
  long cycles_checked = 0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    const auto& all = contact_interface(s, 0);
    const auto& pair = contact_interface(s, 1);
    const auto& low = contact_interface(s, 2);
    const auto& high = contact_interface(s, 3);
    peak_low = std::max(peak_low, low.force_b.norm());
    peak_high = std::max(peak_high, high.force_a.norm());
    // On the middle cube: what contact 3 puts on its B side and contact 4 on its A side.
    const Eigen::Vector3d expected = low.force_b + high.force_a;
    const double scale = std::max({1.0, low.force_b.norm(), high.force_a.norm()});
    CHECK((all.force_a - expected).norm() <= 1e-12 * scale);
    CHECK(all.force_b.norm() == 0.0);  // no side B: nothing on the master line
    // Between the middle and the top cube: contact 4's own resultants, the same sums.
    CHECK(pair.force_a == high.force_a);
    CHECK(pair.force_b == high.force_b);
    CHECK(pair.moment_a == high.moment_a);
    CHECK(pair.energy == 0.0);
    if (high.force_a.norm() > 0.0) CHECK(pair.mass_in_contact > 0.0);
    ++cycles_checked;
  };
  run(sim, hooks);
  MESSAGE("peak forces: bottom contact ", peak_low, ", top contact ", peak_high, " N over ",
          cycles_checked, " cycles");
  CHECK(peak_low > 0.0);
  CHECK(peak_high > 0.0);
  CHECK(cycles_checked > 10);

  // The transducers change nothing: the same deck without them ends at the same bits.
  TempDir plain_dir;
  Simulation plain = prepare(plain_dir, cube_column(""));
  run(plain);
  CHECK(plain.state->cycle == sim.state->cycle);
  CHECK(plain.state->nodes.position == sim.state->nodes.position);
  CHECK(plain.state->nodes.velocity == sim.state->nodes.velocity);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("contact SOFT 2: the bar on the rigid plate, its stiffness from masses and the step") {
  TempDir dir;
  // The bar of the first test with segment-based stiffness: k = 0.5 SLSFAC m / dt^2 for a face
  // node of mass m on the rigid plate. Each face node carries the impact stress rho c v on its
  // share of the face, whose mass is rho h / 2 per unit area (h = 1 mm): the face sits in by
  // d = rho c v dt^2 / (0.05 rho h / 2) = 2 c v dt^2 / (0.05 h) while the bar presses.
  const double c = std::sqrt(210000.0 / 7.85e-9), contact_time = 2.0 * 20.0 / c;
  const double end = 2e-6 + 3.0 * contact_time;
  Simulation sim = prepare(dir, header(end) + kBar + rigid_plate(-10, -10, 12, 12) +
                                    "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,9,3,3\n0,0\n\n"
                                    "2\n*END\n");
  REQUIRE(solver::contact::interfaces_of(*sim.state).size() == 1);
  CHECK(contact_interface(*sim.state, 0).segment_based);
  const double mass = 80.0 * 7.85e-9;
  double impulse = 0.0, lowest = 0.0, step = 0.0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    impulse += contact_interface(s, 0).force_a.z() * s.step;
    lowest = std::min(lowest, motion(s, 0, kBarNodes).lowest);
    step = s.step;
  };
  run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const Motion after = motion(*sim.state, 0, kBarNodes);
  const double pressed = 2.0 * c * kSpeed * step * step / (0.05 * 1.0);
  MESSAGE("SOFT 2: rebound ", after.velocity.z(), " mm/s, impulse ", impulse, " (m dv ",
          mass * (after.velocity.z() + kSpeed), "), deepest ", -lowest, " mm against ", pressed,
          " mm pressed, interface energy ", contact_interface(*sim.state, 0).energy);
  CHECK(impulse == doctest::Approx(mass * (after.velocity.z() + kSpeed)).epsilon(1e-3).scale(0.0));
  CHECK(after.velocity.z() > 0.9 * kSpeed);
  CHECK(after.velocity.z() < kSpeed);
  // A load that comes on at once takes an undamped spring to at most twice its static deflection.
  CHECK(-lowest > 0.5 * pressed);
  CHECK(-lowest < 2.0 * pressed);
}

TEST_CASE("contact SOFT 2: both ways, initial penetrations kept as the baseline") {
  // The block sunk 0.02 mm into the rigid plate, as a nodes-to-surface contact with SOFT 2:
  // segment-based contact checks both sides' segments (two passes), and does not move the
  // nodes out: the initial depth is the baseline, and the block at rest feels no force.
  TempDir dir;
  std::string deck = sunk_block("");
  deck.replace(deck.find("0,0\n\n*END"), 10, "0,0\n\n2\n*END");
  Simulation sim = prepare(dir, deck);
  REQUIRE(solver::contact::interfaces_of(*sim.state).size() == 1);
  CHECK(contact_interface(*sim.state, 0).passes.size() == 2);
  CHECK(lowest_z(*sim.state) == doctest::Approx(-0.02).scale(1.0).epsilon(1e-12));
  CHECK(largest_contact_force(sim) == 0.0);
  CHECK(std::abs(motion(*sim.state, 0, 27).velocity.z()) < 1e-9);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("contact SOFT 2 holds a steel bar on foam where the standard penalty lets it in") {
  // A steel bar (2 x 2 x 10 one-millimetre hexahedra) falls at 5 m/s onto a foam block (E
  // 10 MPa, rho 0.1 g/cm^3, 10 x 10 x 2 elements, bottom fixed). The standard penalty takes
  // the smaller of the two sides' stiffnesses, the foam's, and the bar's foot sinks through
  // the foam's face; SOFT 2's spring comes from the masses and the step and holds it.
  auto sunk = [](int soft) {
    TempDir dir;
    Simulation sim = prepare(
        dir, header(6e-5) +
                 "*PART\nfoam\n1,1,1\n*PART\nbar\n2,1,2\n*SECTION_SOLID\n1,1\n"
                 "*MAT_ELASTIC\n1,1e-10,10.0,0.3\n*MAT_ELASTIC\n2,7.85e-9,210000.0,0.3\n" +
                 box_mesh(10, 10, 2, 1.0, 1, 1, 1, -2.0) +
                 box_mesh(2, 2, 10, 1.0, 1001, 1001, 2, 0.01) +
                 "*SET_NODE_LIST_GENERATE\n1\n1,121\n*BOUNDARY_SPC_SET\n1,0,1,1,1,0,0,0\n"
                 "*SET_PART_LIST\n2\n2\n*INITIAL_VELOCITY_GENERATION\n2,1,0,0,0,-5000\n0,0,0\n"
                 "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n2,1,3,3\n0,0\n\n" +
                 std::to_string(soft) + "\n*END\n");
    // The bar's bottom centre (node 1005, at x = y = 1) and the foam's top node under it (255).
    auto index = [&](model::Id id) {
      const auto& ids = sim.state->nodes.ids;
      return static_cast<solver::Index>(std::find(ids.begin(), ids.end(), id) - ids.begin());
    };
    const solver::Index foot = index(1005), face = index(255);
    REQUIRE(sim.state->nodes.position(0, foot) == sim.state->nodes.position(0, face));
    double deepest = 0.0;
    solver::RunHooks hooks;
    hooks.progress = [&](const solver::State& s) {
      deepest = std::max(deepest, s.nodes.position(2, face) - s.nodes.position(2, foot));
    };
    run(sim, hooks);
    REQUIRE(sim.result.reason == solver::StopReason::end_time);
    return deepest;
  };
  const double standard = sunk(0), segment_based = sunk(2);
  MESSAGE("steel foot below the foam face: SOFT 0 ", standard, " mm, SOFT 2 ", segment_based,
          " mm (1 mm elements)");
  CHECK(standard > 0.1);        // over a tenth of the foam's element
  CHECK(segment_based < 0.02);  // within 2 % of it
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("tied contact: two meshes that do not match move as one bar") {
  // A 1 x 1 x 10 mm steel bar in two parts that meet at z = 5: below, 0.5 mm hexahedra (part 1);
  // above, 1/3 mm ones (part 2), whose bottom nodes mostly fall inside part 1's top faces. The
  // halves start apart at 1 m/s each. (Two elements across at least: a single column of
  // hexahedra breathes sideways like a lone cube, above its step estimate at TSSFAC 0.9.) Tied, the
  // bar rings as one free-free bar, its length oscillating with the period 2 L / c; untied, the
  // halves fly apart.
  auto bar = [](const std::string& tie) {
    return header(1.2e-5) +
           "*PART\nlow\n1,1,1\n*PART\nhigh\n2,1,1\n*SECTION_SOLID\n1,1\n"
           "*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
           box_mesh(2, 2, 10, 0.5, 1, 1, 1, 0.0) +
           box_mesh(3, 3, 15, 1.0 / 3.0, 1001, 1001, 2, 5.0) +
           "*SET_PART_LIST\n1\n1\n*SET_PART_LIST\n2\n2\n"
           "*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,-1000\n0,0,0\n"
           "*INITIAL_VELOCITY_GENERATION\n2,1,0,0,0,1000\n0,0,0\n" +
           tie + "*END\n";
  };
  // The period of the bar's length (its maxima), and the worst tie gap and momentum on the way.
  struct Ring {
    double period = 0.0, worst_gap = 0.0, worst_momentum = 0.0;
  };
  auto ring = [](Simulation& sim) {
    Ring out;
    double& worst_gap = out.worst_gap;
    double& worst_momentum = out.worst_momentum;
    std::vector<double> lengths, times;
    solver::RunHooks hooks;
    hooks.progress = [&](const solver::State& s) {
      for (const solver::Tie& t : solver::contact::ties_of(s)) {
        Eigen::Vector3d on = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < 4; ++k)
          on += t.weights[k] * s.nodes.position.col(t.masters[k]);
        worst_gap = std::max(worst_gap, (s.nodes.position.col(t.slave) - on).norm());
      }
      double p = 0.0, low = 1e30, high = -1e30;
      for (solver::Index n = 0; n < s.nodes.count(); ++n) {
        p += s.nodes.mass[static_cast<std::size_t>(n)] * s.nodes.velocity(2, n);
        low = std::min(low, s.nodes.position(2, n));
        high = std::max(high, s.nodes.position(2, n));
      }
      worst_momentum = std::max(worst_momentum, std::abs(p));
      lengths.push_back(high - low);
      times.push_back(s.time);
    };
    run(sim, hooks);
    REQUIRE_MESSAGE(sim.result.reason == solver::StopReason::end_time, sim.result.message);
    // The length's maxima, one per period.
    std::vector<double> peaks;
    for (std::size_t k = 1; k + 1 < lengths.size(); ++k)
      if (lengths[k] > lengths[k - 1] && lengths[k] >= lengths[k + 1]) peaks.push_back(times[k]);
    REQUIRE(peaks.size() >= 2);
    out.period = (peaks.back() - peaks.front()) / static_cast<double>(peaks.size() - 1);
    return out;
  };
  TempDir dir;
  Simulation sim = prepare(dir, bar("*CONTACT_TIED_SURFACE_TO_SURFACE\n2,1,3,3\n"));
  REQUIRE(solver::contact::ties_of(*sim.state).size() == 16);  // part 2's bottom nodes
  const Ring tied = ring(sim);
  const double period = tied.period, worst_gap = tied.worst_gap;
  const double worst_momentum = tied.worst_momentum;
  // The same bar as one conforming mesh of 0.5 mm hexahedra, the halves given the same velocities.
  Simulation one = prepare(
      dir, header(1.2e-5) +
               "*PART\nbar\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
               box_mesh(2, 2, 20, 0.5, 1, 1, 1, 0.0) +
               "*SET_NODE_LIST_GENERATE\n1\n1,90\n*SET_NODE_LIST_GENERATE\n2\n100,189\n"
               "*INITIAL_VELOCITY\n1\n0,0,-1000\n*INITIAL_VELOCITY\n2\n0,0,1000\n*END\n");
  const double conforming = ring(one).period;
  const double expected = 2.0 * 10.0 / std::sqrt(210000.0 / 7.85e-9);
  const double momentum_scale = 10.0 * 7.85e-9 * 1000.0;  // one half's momentum
  MESSAGE("tied bar: period ", period * 1e6, " us; one conforming mesh ", conforming * 1e6,
          " us; 2L/c ", expected * 1e6, " us; slaves off their surface by at most ", worst_gap,
          " mm; |momentum| ", worst_momentum / momentum_scale, " of a half's");
  CHECK(worst_gap < 1e-12);
  CHECK(worst_momentum < 1e-12 * momentum_scale);
  CHECK(std::abs(period / expected - 1.0) < 0.03);
  CHECK(std::abs(period / conforming - 1.0) < 0.01);

  // Untied, the halves part: the bar ends longer than it started by about 2 v t.
  Simulation free = prepare(dir, bar(""));
  run(free);
  double low = 1e30, high = -1e30;
  for (solver::Index n = 0; n < free.state->nodes.count(); ++n) {
    low = std::min(low, free.state->nodes.position(2, n));
    high = std::max(high, free.state->nodes.position(2, n));
  }
  CHECK(high - low > 10.0 + 0.9 * 2.0 * 1000.0 * 1.2e-5);
}

}  // namespace mcdyna::test
