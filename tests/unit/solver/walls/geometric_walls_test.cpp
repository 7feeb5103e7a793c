// Geometric rigid walls (solver/walls/) against closed forms: a 1 kg elastic cube (one
// hexahedron, 0.1 m, E 1 GPa: its own vibration far faster and smaller than the motions checked)
// on a flat wall with friction, set on a cylinder and on a sphere, driven into a prism, and
// carried by a moving wall. TSSFAC 0.6: a lone one-point hexahedron with free corners breathes
// above its step estimate (verification.md "Lone elements").
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "solver_support.hpp"

using namespace mcdyna;

namespace {

struct Track {
  std::vector<double> time, x, vx;  ///< the cube's mean x and vx
  std::vector<double> z_bottom;     ///< node 1's z (a bottom corner)
  std::vector<double> front;        ///< node 2's x (on the face x = cx + 0.05)
};

Track run_cube(const std::string& deck) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, deck);
  Track tr;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    double x = 0.0, vx = 0.0;
    for (solver::Index n = 0; n < 8; ++n) {
      x += s.nodes.position(0, n) / 8.0;
      vx += s.nodes.velocity(0, n) / 8.0;
    }
    tr.time.push_back(s.time);
    tr.x.push_back(x);
    tr.vx.push_back(vx);
    tr.z_bottom.push_back(s.nodes.position(2, 0));
    tr.front.push_back(s.nodes.position(0, 1));
  };
  test::run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  REQUIRE(tr.time.size() > 100);
  return tr;
}

// The flat wall z = 0 (normal +z), 10 x 10 from its tail at (-5, -5).
std::string flat_wall(double friction) {
  return fmt::format("0,0,0,0,1e20\n-5,-5,0,-5,-5,1,{}\n5,-5,0,10,10\n", friction);
}

}  // namespace

TEST_CASE("geometric flat wall: a block sliding under Coulomb friction stops at v0^2 / (2 mu g)") {
  // mu 0.2, g 10, v0 1 m/s: deceleration 2 m/s^2, at rest after 0.5 s, 0.25 m on.
  test::Cube c;
  c.vx = 1.0;
  c.gravity = 10.0;
  c.end = 0.7;
  const Track tr = run_cube(test::cube_deck(c, "*RIGIDWALL_GEOMETRIC_FLAT\n" + flat_wall(0.2)));
  double speed_at_quarter = 0.0, x_stopped = 0.0, creep = 0.0;
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    if (tr.time[i] <= 0.25) speed_at_quarter = tr.vx[i];
    if (tr.time[i] <= 0.55) x_stopped = tr.x[i];
    creep = std::max(creep, std::abs(tr.x[i] - x_stopped));
  }
  const double travel = tr.x.back() - tr.x.front();
  MESSAGE("travel ", travel, " m (0.25), speed at 0.25 s ", speed_at_quarter,
          " m/s (0.5), moved after 0.55 s ", creep, " m; bottom z ", tr.z_bottom.back());
  // The stop falls inside a step: v0 dt = 5e-5 m of 0.25 m (2e-4; measured -1.9e-4).
  CHECK(travel == doctest::Approx(0.25).epsilon(5e-4));
  CHECK(speed_at_quarter == doctest::Approx(0.5).epsilon(5e-4));
  // At rest from 0.5 s: sticking holds it (at 2 m/s^2 it would cover 0.01 m in 0.1 s).
  CHECK(creep < 1e-6);
  CHECK(std::abs(tr.z_bottom.back()) < 1e-9);
}

TEST_CASE("geometric cylinder and sphere walls: a block set on top of them stays there") {
  // The bottom corners (x, y = +-0.05) start on the surface: on a cylinder of radius 1 along y
  // at z = sqrt(1 - 0.05^2) = 0.998749, on a sphere at sqrt(1 - 2 0.05^2) = 0.997497. Gravity
  // (10 m/s^2 for 0.4 s: 0.8 m of fall without the wall) presses them on it; FRIC 1 (no sliding)
  // keeps them there, the cube's elastic settling (rho g L / E, 1e-8) aside.
  test::Cube c;
  c.gravity = 10.0;
  c.end = 0.4;
  for (const bool sphere : {false, true}) {
    const double surface = std::sqrt(1.0 - (sphere ? 0.005 : 0.0025));
    c.cz = surface;
    const Track tr = run_cube(test::cube_deck(
        c, sphere ? "*RIGIDWALL_GEOMETRIC_SPHERE\n0,0,0,0,1e20\n0,0,0,0,0,1,1.0\n1.0\n"
                  : "*RIGIDWALL_GEOMETRIC_CYLINDER\n0,0,0,0,1e20\n0,-5,0,0,5,0,1.0\n1.0,10,0\n"));
    const double lowest = *std::min_element(tr.z_bottom.begin(), tr.z_bottom.end());
    MESSAGE((sphere ? "sphere" : "cylinder"), ": bottom corner z at the end ",
            fmt::format("{:.9f}", tr.z_bottom.back()), ", lowest ", fmt::format("{:.9f}", lowest),
            " (", fmt::format("{:.9f}", surface), ")");
    CHECK(tr.z_bottom.back() == doctest::Approx(surface).epsilon(1e-7));
    CHECK(lowest == doctest::Approx(surface).epsilon(1e-7));
  }
}

TEST_CASE("geometric prism wall: a block driven into its face meets it on time, never crosses") {
  // The box spans x 1..2, y and z -1..1 from the tail (l along x, m along y, the normal along z);
  // the block's front face (x = 0.55) reaches x = 1 at 0.45 s. The front nodes stop there
  // (plastic), the rest of the elastic block rings against them and sends it back.
  test::Cube c;
  c.cx = 0.5;
  c.cz = -0.05;
  c.vx = 1.0;
  c.end = 0.8;
  const Track tr = run_cube(test::cube_deck(
      c, "*RIGIDWALL_GEOMETRIC_PRISM\n0,0,0,0,1e20\n1,-1,-1,1,-1,1,0\n2,-1,-1,1,2,2\n"));
  double contact = -1.0, furthest = 0.0, step = 0.0;
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    furthest = std::max(furthest, tr.front[i]);
    if (i > 0) step = std::max(step, tr.time[i] - tr.time[i - 1]);
    if (contact < 0.0 && tr.front[i] >= 1.0 - 1e-12) contact = tr.time[i];
  }
  MESSAGE("front face on x = 1 at ", contact, " s (0.45, step ", step, "); furthest ",
          fmt::format("{:.12f}", furthest), "; mean vx at the end ", tr.vx.back());
  CHECK(std::abs(contact - 0.45) <= step);
  CHECK(furthest <= 1.0 + 1e-12);
  CHECK(tr.vx.back() < 0.0);
}

TEST_CASE("geometric wall with _MOTION: a block on a rising wall rides it, node on wall") {
  // The flat wall at z = 0 rises at 0.5 m/s (OPT 0, a velocity curve; OPT 1 the displacement
  // curve 0.5 t): under gravity the block's bottom node stays on it, z = 0.5 t.
  test::Cube c;
  c.gravity = 10.0;
  c.end = 0.5;
  for (const std::string opt : {"0", "1"}) {
    const std::string curve =
        opt == "0" ? "*DEFINE_CURVE\n2\n0,0.5\n10,0.5\n" : "*DEFINE_CURVE\n2\n0,0\n10,5\n";
    const Track tr = run_cube(test::cube_deck(
        c, "*RIGIDWALL_GEOMETRIC_FLAT_MOTION\n" + flat_wall(0) + "2," + opt + ",0,0,1\n" + curve));
    MESSAGE("OPT ", opt, ": bottom z at ", tr.time.back(), " s: ", tr.z_bottom.back());
    CHECK(tr.z_bottom.back() == doctest::Approx(0.5 * tr.time.back()).epsilon(1e-6));
  }
}

TEST_CASE("geometric walls: a run continued from a dump ends with the same bytes") {
  // The sliding block (tests/regression/sliding_block), its wall moving: a dump at cycle 4,000 of
  // about 14,400, continued to the end, writes the histories of the run that went through.
  test::TempDir dir;
  std::string deck = test::source_text("tests/regression/sliding_block/sliding_block.k");
  const std::string wall = "*RIGIDWALL_GEOMETRIC_FLAT\n";
  REQUIRE(deck.find(wall) != std::string::npos);
  deck.replace(deck.find(wall), wall.size(), "*RIGIDWALL_GEOMETRIC_FLAT_MOTION\n");
  deck.replace(
      deck.find("*END"), 4,
      "         2         0       0.0       0.0       1.0\n*DEFINE_CURVE\n2\n0,0.01\n10,0.01\n"
      "*DATABASE_BINARY_D3DUMP\n      4000\n*END");
  const auto [through, resumed] = test::run_through_and_resumed(dir, dir.write("block.k", deck));
  for (const char* f : {"glstat.csv", "nodout.csv"})
    CHECK_MESSAGE(test::read_text(through / f) == test::read_text(resumed / f), f);
}

TEST_CASE("geometric flat wall: the cube drop on it writes the planar wall's histories") {
  // decks/cube/cube_drop.k with its infinite *RIGIDWALL_PLANAR written as the same plane in
  // *RIGIDWALL_GEOMETRIC_FLAT form: one constraint method, the same numbers, the same lines.
  test::TempDir dir;
  const std::string planar = test::source_text("decks/cube/cube_drop.k");
  const std::string wall =
      "*RIGIDWALL_PLANAR\n         0\n       0.0       0.0       0.0       0.0       0.0       "
      "1.0\n";
  REQUIRE(planar.find(wall) != std::string::npos);
  std::string geometric = planar;
  geometric.replace(geometric.find(wall), wall.size(),
                    "*RIGIDWALL_GEOMETRIC_FLAT\n0,0,0,0.0,1.0e20\n0,0,0,0,0,1,0\n1,0,0,0,0\n");
  for (const auto& [name, text] : {std::pair{"planar", planar}, {"geometric", geometric}}) {
    const test::Run r =
        test::run_mcdyna("run " + dir.write(std::string(name) + ".k", text).string() + " --out " +
                         (dir.path() / name).string() + " -q");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  }
  // rwforc.csv: a line per output with the wall's forces, not only its header.
  CHECK(test::read_text(dir.path() / "geometric" / "rwforc.csv").size() > 1000);
  for (const char* f : {"glstat.csv", "matsum.csv", "rwforc.csv", "rwforc"})
    CHECK_MESSAGE(
        test::read_text(dir.path() / "planar" / f) == test::read_text(dir.path() / "geometric" / f),
        f);
}
