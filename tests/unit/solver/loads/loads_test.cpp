// Point and pressure loads (issue 26): *LOAD_NODE, *LOAD_RIGID_BODY, *LOAD_SEGMENT against the
// motion of a free body under a constant load, and their work against its kinetic energy.
#include <doctest/doctest.h>

#include <cmath>

#include "solver/energy.hpp"
#include "solver_support.hpp"

using namespace mcdyna;

namespace {

// A free 1 x 1 mm plate (t 1 mm, steel; t, mm, s, MPa) in the x-y plane, elastic (part 1) or
// rigid (part 2), under `load` for 10 us (a second, unloaded plate sets the step): the centre's z
// travel, its z velocity, the kinetic energy and the external work at the end.
struct Free {
  double travel, speed, spin, kinetic, work, mass, time, damping, step;
};

Free free_plate(bool rigid, const std::string& load) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir, std::string("*KEYWORD\n*CONTROL_TERMINATION\n1e-5\n*PART\nplate\n1,1,") +
               (rigid ? "2" : "1") +
               "\n*SECTION_SHELL\n1\n1.0,1.0,1.0,1.0\n*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n"
               "*MAT_RIGID\n2,7.85e-9,210e3,0.3\n"
               "*PART\nclock\n3,1,1\n"  // sets the step when the plate is rigid
               "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n11,5,0,0\n12,6,0,0\n13,6,1,0\n"
               "14,5,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n2,3,11,12,13,14\n"
               "*SET_NODE_LIST\n1\n1,2,3,4\n*SET_SEGMENT\n1\n1,2,3,4\n"
               "*DEFINE_CURVE\n1\n0,1\n1,1\n" +
               load + "*END\n");
  Eigen::Matrix3Xd previous = sim.state->nodes.velocity;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) { previous = s.nodes.velocity; };
  test::run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const solver::State& s = *sim.state;
  Free f{};
  for (solver::Index n = 0; n < 4; ++n) {
    f.travel += 0.25 * (s.nodes.position(2, n) - s.nodes.initial(2, n));
    f.speed += 0.25 * s.nodes.velocity(2, n);
  }
  f.spin = rigid ? s.rigid_bodies.front().omega.z() : 0.0;
  const solver::EnergySummary e = solver::energy_summary(s, previous);
  f.kinetic = e.kinetic + e.internal + e.hourglass;
  f.work = e.external_work;
  f.damping = e.damping;
  f.mass = rigid ? s.rigid_bodies.front().mass : 7.85e-9;
  f.time = s.time;
  f.step = s.step;
  return f;
}

}  // namespace

TEST_CASE("point, rigid-body and pressure loads push a free plate as Newton says") {
  // 1 N in all along +z (the set's four nodes 0.25 N each; the body 1 N at its centre; the
  // pressure -1 MPa on the 1 mm^2 segment, whose normal is +z: a pull along +z) for t = 10 us:
  // a = F / m, z = a t^2 / 2, and the loads' work is the kinetic energy they gave.
  const double t = 1e-5, m = 7.85e-9, a = 1.0 / m;  // t: the deck's end
  struct Case {
    const char* name;
    bool rigid;
    std::string load;
  };
  for (const Case& c : {Case{"*LOAD_NODE_SET", false, "*LOAD_NODE_SET\n1,3,1,0.25\n"},
                        Case{"*LOAD_NODE_POINT", false,
                             "*LOAD_NODE_POINT\n1,3,1,0.25\n2,3,1,0.25\n3,3,1,0.25\n4,3,1,0.25\n"},
                        Case{"*LOAD_RIGID_BODY", true, "*LOAD_RIGID_BODY\n1,3,1,1.0\n"},
                        Case{"*LOAD_SEGMENT", false, "*LOAD_SEGMENT\n1,-1.0,0,1,2,3,4\n"},
                        Case{"*LOAD_SEGMENT_SET", false, "*LOAD_SEGMENT_SET\n1,1,-1.0\n"}}) {
    CAPTURE(c.name);
    const Free f = free_plate(c.rigid, c.load);
    MESSAGE(std::string(c.name), ": travel ", f.travel, " mm (", 0.5 * a * t * t, "), speed ",
            f.speed, " mm/s (", a * t, "), energy ", f.kinetic, " against work ", f.work);
    CHECK(f.mass == doctest::Approx(m).epsilon(1e-12));
    // Central differences move a constant force exactly: x = a t^2 / 2 at the end time (a step
    // or so past 10 us: the comparison uses the run's own time through the speed).
    CHECK(f.travel == doctest::Approx(0.5 * f.speed * f.speed / a).epsilon(1e-3));
    // v^{n+1/2} = a (t_n + dt/2): within a step (2 %) of a t at the end time.
    CHECK(f.speed == doctest::Approx(a * f.time).epsilon(0.02));
    CHECK(f.kinetic == doctest::Approx(f.work).epsilon(1e-3));
  }
}

TEST_CASE("a moment on a rigid body spins it at M t / I") {
  // 1 N mm about z on the rigid plate (I_zz = m (1 + 1) / 12 about its centre).
  const Free f = free_plate(true, "*LOAD_RIGID_BODY\n1,7,1,1.0\n");
  const double inertia = 7.85e-9 * 2.0 / 12.0;
  MESSAGE("spin ", f.spin, " rad/s against ", f.time / inertia, " at t = ", f.time);
  CHECK(f.spin == doctest::Approx(f.time / inertia).epsilon(0.02));
  CHECK(f.kinetic == doctest::Approx(f.work).epsilon(1e-3));
}

TEST_CASE("global damping slows a free plate as exp(-D t) and accounts for what it takes") {
  // Elastic and rigid plates moving at 1000 mm/s along z with *DAMPING_GLOBAL D = 2e4 /s for
  // 10 us: v = v0 exp(-D t) = 818.7 mm/s (to the explicit update's error, D dt / 2 of D t), and
  // the kinetic energy lost is the damping energy (to the same order). A 0.5 scale on z (STZ)
  // halves D.
  for (const bool rigid : {false, true}) {
    for (const double stz : {0.0, 0.5}) {
      CAPTURE(rigid);
      CAPTURE(stz);
      const Free f =
          free_plate(rigid, fmt::format("*DAMPING_GLOBAL\n0,2e4,{0},{0},{0}\n*SET_PART_LIST\n9\n1\n"
                                        "*INITIAL_VELOCITY_GENERATION\n9,1,0,0,0,1000\n0,0,0\n",
                                        stz));
      const double d = 2e4 * (stz == 0.0 ? 1.0 : stz);
      // The velocities are at the half step: t + dt / 2.
      const double expected = 1000.0 * std::exp(-d * (f.time + 0.5 * f.step));
      MESSAGE("rigid ", rigid, " STZ ", stz, ": speed ", f.speed, " mm/s against ", expected,
              "; kinetic ", f.kinetic, " + damping ", f.damping, " against ", 0.5 * f.mass * 1e6);
      CHECK(f.speed == doctest::Approx(expected).epsilon(5e-4));
      CHECK(f.kinetic + f.damping == doctest::Approx(0.5 * f.mass * 1e6).epsilon(2e-3));
    }
  }
}
