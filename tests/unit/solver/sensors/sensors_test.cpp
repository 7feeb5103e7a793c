// Sensors, switches and controls (solver/sensors/): a control's watch of its switches (TIMWIN,
// TDELAY, NREP), a rigid wall turned off by its own force sensor and a geometric wall turned on by
// the clock against the free fall's closed form, a contact switched off from the start, a run
// continued from a dump between two switches, and the deck errors. The closed-form run of a
// force sensor and a node sensor together is tests/regression/sensor_release.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "solver/sensors/sensors.hpp"
#include "solver_support.hpp"

using namespace mcdyna;
using solver::sensors::Control;
using solver::sensors::Switch;

TEST_CASE("sensor control: a switch trips after TIMWIN of its condition and acts TDELAY later") {
  Control c;
  c.switches = {0};
  const Switch w{1, -1, true, 0.0, /*window=*/0.3, /*delay=*/0.2};
  auto step = [&](bool condition, double t) { return advance(c, w, condition, t); };
  CHECK_FALSE(step(true, 1.0));   // holds from 1.0
  CHECK_FALSE(step(false, 1.1));  // broken: the window starts again
  CHECK_FALSE(step(true, 1.2));
  CHECK_FALSE(step(true, 1.4));  // 0.2 of 0.3
  CHECK_FALSE(step(true, 1.5));  // held 0.3: trips, acts at 1.7
  CHECK(c.status.changes_at == doctest::Approx(1.7));
  CHECK_FALSE(step(false, 1.6));  // tripped: the delay runs whatever the condition does
  CHECK(c.status.on);
  CHECK(step(false, 1.7));
  CHECK_FALSE(c.status.on);
  CHECK_FALSE(c.watching());  // one switch, no repeat: done
}

TEST_CASE("sensor control: NREP repeats the switch sequence, -1 without end") {
  Control c;
  c.switches = {0, 1};
  c.repeats = 1;
  const Switch w{1, -1, true, 0.0, 0.0, 0.0};
  int changes = 0;
  for (int k = 0; k < 10 && c.watching(); ++k)
    changes += advance(c, w, true, k);
  CHECK(changes == 4);  // SWIT1 SWIT2, then once more
  CHECK(c.status.on);   // off, on, off, on
  c.repeats = -1;
  CHECK(c.watching());
  CHECK(c.current() == 0);
}

namespace {

// The walls' tests' cube (solver_support.hpp), its bottom at z = 0, falling under g = 10 m/s^2;
// `more`: the walls and sensors.
std::string falling_cube(const std::string& more, double end = 0.4) {
  test::Cube c;
  c.gravity = 10.0;
  c.end = end;
  return test::cube_deck(c, more);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

struct Fall {
  std::vector<double> time, bottom;
};

Fall run_fall(const std::string& deck) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, deck);
  Fall f;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    f.time.push_back(s.time);
    f.bottom.push_back(s.nodes.position(2, 0));
  };
  test::run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  return f;
}

}  // namespace

TEST_CASE("sensor control: a planar wall turned off by its force sensor lets the cube fall") {
  // The wall carries the cube's weight, 10 N, from the first cycle; switch 1 (force magnitude
  // above 5 N) trips once that has held for TIMWIN 0.1 s, and the wall is off from the next
  // cycle: free fall from t_off = 0.1 s (within two steps of 4.87e-5 s), z = -5 (t - t_off)^2.
  const std::string sensors =
      "*RIGIDWALL_PLANAR_ID\n1\n0\n0,0,0,0,0,1\n"
      "*SENSOR_DEFINE_FORCE\n3,RWALL,1,M\n*SENSOR_SWITCH\n4,SENSOR,3,GT,5.0,0,0.1\n"
      "*SENSOR_CONTROL\n5,RWALL,1\nON,4\n";
  const Fall f = run_fall(falling_cube(sensors));
  double worst = 0.0;
  for (std::size_t k = 0; k < f.time.size(); ++k) {
    const double t = f.time[k];
    const double expected = t <= 0.1 ? 0.0 : -5.0 * (t - 0.1) * (t - 0.1);
    worst = std::max(worst, std::abs(f.bottom[k] - expected));
  }
  MESSAGE("largest |z - closed form| ", worst, " m; at the end ", f.bottom.back());
  // Two steps late at most (the trip is seen at a cycle's end, the wall acts through that
  // cycle): 10 m/s^2 x 0.3 s x 2 x 4.87e-5 s = 2.9e-4 m; the cube's own vibration under its
  // weight is 1e-7 m.
  CHECK(worst < 2.9e-4);
  CHECK(f.bottom.back() == doctest::Approx(-0.45).epsilon(2e-3));
}

TEST_CASE(
    "sensor control: a geometric wall off at first, turned on by the clock, catches the cube") {
  // The wall at z = -0.5, OFF at t = 0; a TIME switch turns it on at 0.2 s, before the cube's
  // bottom reaches it (at sqrt(0.1) = 0.316 s): it lands there and stays. Without the switch
  // (INITSTT OFF, no switch: a warning) the cube falls through to -5 x 0.6^2 = -1.8 m.
  const std::string wall =
      "*RIGIDWALL_GEOMETRIC_FLAT_ID\n2\n0,0,0,0,1e20\n-5,-5,-0.5,-5,-5,1,0\n5,-5,-0.5,10,10\n";
  const Fall caught =
      run_fall(falling_cube(wall + "*SENSOR_SWITCH\n6,TIME,0,GT,0.2\n*SENSOR_CONTROL\n7,RWALL,2\n"
                                   "OFF,6\n",
                            0.6));
  // It lands at 3.2 m/s and bounces on its own elastic rebound: never below the wall, and
  // about it at the end.
  const double lowest = *std::min_element(caught.bottom.begin(), caught.bottom.end());
  MESSAGE("caught: lowest ", lowest, " m, at the end ", caught.bottom.back(), " m");
  CHECK(lowest > -0.5 - 1e-3);
  CHECK(caught.bottom.back() == doctest::Approx(-0.5).epsilon(0.02));
  const Fall through = run_fall(falling_cube(wall + "*SENSOR_CONTROL\n7,RWALL,2\nOFF\n", 0.6));
  MESSAGE("through: at the end ", through.bottom.back(), " m");
  CHECK(through.bottom.back() == doctest::Approx(-1.8).epsilon(1e-3));
}

TEST_CASE("sensor control: a contact switched off from the start does nothing") {
  // The cube falls on a fixed cube below it (part 2, every node held): with the contact on it
  // lands; with the contact off for good it falls through, as without the contact.
  // It is wider (0.2 m), so that the falling corners land inside its top face.
  std::string below = "*NODE\n";
  int id = 9;
  for (const double z : {-0.1, 0.0})
    for (const auto& [x, y] : {std::pair{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}})
      below += fmt::format("{},{},{},{}\n", id++, x, y, z - 0.01);
  below +=
      "*PART\nbase\n2,1,1\n*ELEMENT_SOLID\n2,2,9,10,11,12,13,14,15,16\n"
      "*SET_NODE_LIST_GENERATE\n1\n9,16\n*BOUNDARY_SPC_SET\n1,0,1,1,1\n";
  const std::string contact = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n";
  const Fall landed = run_fall(falling_cube(below + contact));
  const Fall off = run_fall(falling_cube(below + contact + "*SENSOR_CONTROL\n1,CONTACT,1\nOFF\n"));
  const Fall without = run_fall(falling_cube(below));
  MESSAGE("contact on: at the end ", landed.bottom.back(), " m; off: ", off.bottom.back(), " m");
  CHECK(landed.bottom.back() > -0.02);
  CHECK(off.bottom.back() == doctest::Approx(-5.0 * 0.4 * 0.4).epsilon(1e-3));
  CHECK(off.bottom == without.bottom);
}

TEST_CASE("sensor control: a run continued from a dump between two switches ends the same") {
  // tests/regression/sensor_release: released at 0.2 s (cycle 1,300), driven again at 0.55 s
  // (cycle 3,596); dumped at cycle 2,000, while switch 2 waits.
  test::TempDir dir;
  std::string deck = test::source_text("tests/regression/sensor_release/sensor_release.k");
  deck.replace(deck.find("*END"), 4, "*DATABASE_BINARY_D3DUMP\n      2000\n*END");
  const auto [through, resumed] = test::run_through_and_resumed(dir, dir.write("push.k", deck));
  for (const char* f : {"glstat.csv", "nodout.csv", "bndout.csv"})
    CHECK_MESSAGE(test::read_text(through / f) == test::read_text(resumed / f), f);
  const test::Run r = test::run_mcdyna("run " + (dir.path() / "push.k").string() + " --out " +
                                       (dir.path() / "log").string());
  CHECK_MESSAGE(contains(r.output, "sensor control 1: PRESC-MOT 7 switched off at t = 2.00"),
                r.output);
}

TEST_CASE("sensor keywords: what cannot be run is an error at its field, in check as in run") {
  test::TempDir dir;
  const std::string base = test::source_text("tests/regression/sensor_release/sensor_release.k");
  auto check = [&](const std::string& from, const std::string& to, const std::string& expected) {
    const std::string deck = dir.write("bad.k", test::with(base, from, to)).string();
    const test::Run r = test::run_mcdyna("run " + deck + " --out " + (dir.path() / "out").string());
    CHECK(r.exit_code != 0);
    CHECK_MESSAGE(contains(r.output, expected), r.output);
    // `check` compiles the model as `run` does, so it finds the same error (exit 1, deck errors).
    const test::Run c = test::run_mcdyna("check " + deck);
    CHECK(c.exit_code == 1);
    CHECK_MESSAGE(contains(c.output, expected), c.output);
  };
  check("         1 PRESC-MOT         7         X", "         1    AIRBAG         7         X",
        "bad.k:91:11-20: error: *SENSOR_DEFINE_FORCE: FTYPE AIRBAG is not supported");
  check("         1 PRESC-MOT         7         X", "         1 PRESC-MOT         7   XMOMENT",
        "VID XMOMENT is not supported");
  check("        20    SENSOR         2        LT", "        20    SENSOR         9        LT",
        "*SENSOR_SWITCH 20 refers to sensor 9, which is not defined");
  // The solver finds the controlled entity: a motion with no such ID is named at the control.
  check("         1 PRESC-MOT         7\n", "         1 PRESC-MOT         8\n",
        "*SENSOR_CONTROL 1: there is no PRESC-MOT 8 to switch");
}
