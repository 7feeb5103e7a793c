// The quasi-static check of a run's summary (io/inertia.hpp, issue 47): when a driven run looks
// quasi-static by its speeds, and when its inertia is then not small.
#include <doctest/doctest.h>

#include "io/inertia.hpp"

namespace mcdyna::test {

namespace {

// A plate driven by a tool at 0.4 % of its wave speed, inertia small by both measures: the FDS
// scene's figures at h 0.3, time scale 5 (screw flank 26 m/s, wave speed 6.5 km/s).
io::InertiaFigures quiet_process() {
  io::InertiaFigures f;
  f.tool_speed = 2.63e4;
  f.wave_speed = 6.47e6;
  f.inertia_number = 0.0057;
  f.inertia_part = 1;
  f.largest_kinetic_over_internal = 0.0032;
  return f;
}

}  // namespace

TEST_CASE("quasi-static check: a slow process with small inertia gives no warning") {
  const io::InertiaVerdict v = io::judge_inertia(quiet_process());
  CHECK(v.quasi_static_speeds);
  CHECK(v.reasons.empty());
}

TEST_CASE("quasi-static check: KE/IE or rho v^2 / yield above its bound warns, each named") {
  io::InertiaFigures f = quiet_process();
  f.largest_kinetic_over_internal = 1.01 * io::kKineticShare;
  io::InertiaVerdict v = io::judge_inertia(f);
  REQUIRE(v.reasons.size() == 1);
  CHECK(v.reasons[0].find("KE/IE") != std::string::npos);
  f.largest_kinetic_over_internal = 0.99 * io::kKineticShare;
  CHECK(io::judge_inertia(f).reasons.empty());

  f = quiet_process();
  f.inertia_number = 0.023;  // FDS h 0.3, time scale 10: stage-2 torque 6.2 % off
  v = io::judge_inertia(f);
  REQUIRE(v.reasons.size() == 1);
  CHECK(v.reasons[0].find("rho v^2 / yield of part 1") != std::string::npos);
  f.largest_kinetic_over_internal = 0.2;
  CHECK(io::judge_inertia(f).reasons.size() == 2);
}

TEST_CASE("quasi-static check: fast tools, impacts and undriven runs are not judged") {
  io::InertiaFigures f = quiet_process();
  f.inertia_number = 1.0;
  f.largest_kinetic_over_internal = 1.0;
  CHECK_FALSE(io::judge_inertia(f).reasons.empty());
  // The tool at the bound of the wave speed: a dynamic event.
  f.tool_speed = io::kQuasiStaticMach * f.wave_speed;
  CHECK_FALSE(io::judge_inertia(f).quasi_static_speeds);
  CHECK(io::judge_inertia(f).reasons.empty());
  // Deformable parts moving at t = 0: an impact.
  f = quiet_process();
  f.largest_kinetic_over_internal = 1.0;
  f.moving_at_start = true;
  CHECK(io::judge_inertia(f).reasons.empty());
  // Nothing driven.
  f.moving_at_start = false;
  f.tool_speed = 0.0;
  CHECK(io::judge_inertia(f).reasons.empty());
}

}  // namespace mcdyna::test
