// Discrete springs and dampers (solver/discrete/) against the closed-form oscillator: a 1 kg rigid
// cube on a spring from a fixed node, moving along x only (MAT_RIGID CON1 5, CON2 7), started
// at 1 m/s. The step is capped at 1 ms by LCTM (w dt = 0.01 at w = 10 rad/s), so central
// differences put the period within (w dt)^2 / 24 = 4e-6 and the peaks within (w dt)^2 / 8 =
// 1.3e-5 of the oscillator's; the tolerances below hold those with room for the sampling of
// the crossings.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "solver_support.hpp"

using namespace mcdyna;

namespace {

// `parts` adds the discrete parts, their sections, materials and elements from node 1 (fixed)
// to node 11 (the cube's corner); `end` is the end time.
std::string oscillator_deck(const std::string& parts, double end) {
  return fmt::format(
      "*KEYWORD\n*CONTROL_TERMINATION\n{}\n*CONTROL_TIMESTEP\n0,0.9,0,0,0,9\n"
      "*DEFINE_CURVE\n9\n0,1e-3\n100,1e-3\n"
      "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1\n*MAT_RIGID\n1,1000,1e9,0.3\n1,5,7\n"
      "*NODE\n1,0,-0.05,-0.05\n11,1,-0.05,-0.05\n12,1.1,-0.05,-0.05\n13,1.1,0.05,-0.05\n"
      "14,1,0.05,-0.05\n15,1,-0.05,0.05\n16,1.1,-0.05,0.05\n17,1.1,0.05,0.05\n18,1,0.05,0.05\n"
      "*ELEMENT_SOLID\n1,1,11,12,13,14,15,16,17,18\n*BOUNDARY_SPC_NODE\n1,0,1,1,1,0,0,0\n"
      "*INITIAL_VELOCITY_GENERATION\n1,2,0,1,0,0\n0,0,0,0,0,0\n{}*END\n",
      end, parts);
}

const std::string kSpring =
    "*PART\nspring\n2,2,2\n*SECTION_DISCRETE\n2\n*MAT_SPRING_ELASTIC\n2,100\n"
    "*ELEMENT_DISCRETE\n1,2,1,11\n";

struct Motion {
  std::vector<double> time, x;  ///< the cube's displacement along x, every cycle
  std::vector<double> energy;   ///< kinetic + internal (springs stored, dampers dissipated)
};

Motion run_oscillator(const std::string& deck) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, deck);
  Motion m;
  solver::RunHooks hooks;
  hooks.output_due = [](const solver::State&) { return true; };
  hooks.write = [&](const solver::State& s, const Eigen::Matrix3Xd& previous, bool) {
    const solver::EnergySummary e = solver::energy_summary(s, previous);
    m.time.push_back(s.time);
    m.x.push_back(s.rigid_bodies.front().center.x() - 1.05);
    m.energy.push_back(e.kinetic + e.internal);
  };
  test::run(sim, hooks);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  REQUIRE(m.time.size() > 100);
  return m;
}

// Times x crosses zero upwards, linearly interpolated.
std::vector<double> upward_crossings(const Motion& m) {
  std::vector<double> out;
  for (std::size_t i = 1; i < m.x.size(); ++i)
    if (m.x[i - 1] < 0.0 && m.x[i] >= 0.0)
      out.push_back(m.time[i - 1] -
                    m.x[i - 1] * (m.time[i] - m.time[i - 1]) / (m.x[i] - m.x[i - 1]));
  return out;
}

double mean_period(const std::vector<double>& crossings) {
  REQUIRE(crossings.size() >= 2);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace

TEST_CASE("a linear spring and a mass oscillate at sqrt(k / m), with the energy kept") {
  const Motion m = run_oscillator(oscillator_deck(kSpring, 2.0));
  const double period = mean_period(upward_crossings(m));
  const double expected = 2.0 * std::numbers::pi * std::sqrt(1.0 / 100.0);  // 0.628319 s
  double amplitude = 0.0, drift = 0.0;
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    amplitude = std::max(amplitude, std::abs(m.x[i]));
    if (i > 0) drift = std::max(drift, std::abs(m.energy[i] / 0.5 - 1.0));
  }
  MESSAGE("period ", period, " s (", expected, "), amplitude ", amplitude,
          " m (0.1), energy drift ", drift);
  CHECK(period == doctest::Approx(expected).epsilon(1e-4));
  CHECK(amplitude == doctest::Approx(0.1).epsilon(1e-4));
  // For a linear spring the half-step kinetic form 1/2 m v^{n-1/2} v^{n+1/2} and the spring's
  // trapezoidal work balance exactly (measured 4e-14): round-off only.
  CHECK(drift < 1e-12);
}

TEST_CASE("a viscous damper beside the spring: the damped period and the log decrement") {
  // DC 2: zeta = c / (2 m w) = 0.1; T_d = T / sqrt(1 - zeta^2); successive peaks shrink by
  // exp(-2 pi zeta / sqrt(1 - zeta^2)) = 0.53182. The damper takes v^{n-1/2}: half a step late,
  // which stiffens the spring by c w^2 dt / 2 = 0.1 N/m (1e-3): the tolerances are 1e-3.
  const Motion m = run_oscillator(oscillator_deck(
      kSpring + "*PART\ndamper\n3,3,3\n*SECTION_DISCRETE\n3\n*MAT_DAMPER_VISCOUS\n3,2\n"
                "*ELEMENT_DISCRETE\n2,3,1,11\n",
      2.0));
  const double zeta = 0.1, root = std::sqrt(1.0 - zeta * zeta);
  const double period = mean_period(upward_crossings(m));
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < m.x.size(); ++i)
    if (m.x[i] > 0.0 && m.x[i] >= m.x[i - 1] && m.x[i] > m.x[i + 1]) peaks.push_back(m.x[i]);
  REQUIRE(peaks.size() >= 3);
  const double decrement = peaks[2] / peaks[1];
  double balance = 0.0;
  for (std::size_t i = 1; i < m.energy.size(); ++i)
    balance = std::max(balance, std::abs(m.energy[i] / 0.5 - 1.0));
  MESSAGE("damped period ", period, " s (", 2.0 * std::numbers::pi * 0.1 / root, "), peak ratio ",
          decrement, " (", std::exp(-2.0 * std::numbers::pi * zeta / root), "), energy balance ",
          balance);
  CHECK(period == doctest::Approx(2.0 * std::numbers::pi * 0.1 / root).epsilon(1e-3));
  CHECK(decrement ==
        doctest::Approx(std::exp(-2.0 * std::numbers::pi * zeta / root)).epsilon(1e-3));
  // Kinetic + spring + the damper's dissipated work stays the initial 0.5 J.
  CHECK(balance < 1e-3);
}

TEST_CASE("a nonlinear spring from a curve: stiffer in compression, the period of two halves") {
  // 100 N/m in tension, 400 N/m in compression: T = pi (sqrt(m / 100) + sqrt(m / 400)) =
  // 0.471239 s; the swing reaches 0.1 m in tension and 0.05 m in compression. The kink is
  // crossed inside a step twice a period: 1e-3.
  const Motion m = run_oscillator(oscillator_deck(
      "*PART\nspring\n2,2,2\n*SECTION_DISCRETE\n2\n*MAT_SPRING_NONLINEAR_ELASTIC\n2,7\n"
      "*DEFINE_CURVE\n7\n-1,-400\n0,0\n1,100\n*ELEMENT_DISCRETE\n1,2,1,11\n",
      2.0));
  const double period = mean_period(upward_crossings(m));
  double tension = 0.0, compression = 0.0;
  for (const double x : m.x) {
    tension = std::max(tension, x);
    compression = std::max(compression, -x);
  }
  MESSAGE("period ", period, " s (0.471239), tension ", tension, " m, compression ", compression,
          " m");
  CHECK(period == doctest::Approx(std::numbers::pi * (0.1 + 0.05)).epsilon(1e-3));
  CHECK(tension == doctest::Approx(0.1).epsilon(1e-3));
  CHECK(compression == doctest::Approx(0.05).epsilon(1e-3));
}

TEST_CASE("discrete elements: what cannot run is refused with the element and the field") {
  test::TempDir dir;
  // An orientation vector (VID) and a failure deflection: refused where they are written.
  const auto vid = test::load_file(
      dir.write("vid.k", oscillator_deck("*PART\nspring\n2,2,2\n*SECTION_DISCRETE\n2,0,0,0,0,0.1\n"
                                         "*MAT_SPRING_ELASTIC\n2,100\n"
                                         "*ELEMENT_DISCRETE\n1,2,1,11,3\n",
                                         1.0)),
      true);
  CHECK(vid->has_message("VID"));
  CHECK(vid->has_message("FD"));
  // A spring on a solid section, and a solid part with a spring material.
  const auto kinds = test::load_file(
      dir.write("kinds.k", oscillator_deck("*PART\nspring\n2,1,2\n*MAT_SPRING_ELASTIC\n2,100\n"
                                           "*ELEMENT_DISCRETE\n1,2,1,11\n",
                                           1.0)),
      true);
  CHECK(
      kinds->has_message("part 2 has discrete elements but section 1 is not a *SECTION_DISCRETE"));
  // A free node without mass at one end: the solver cannot move it.
  const auto free =
      test::load_file(dir.write("free.k", oscillator_deck(kSpring + "*NODE\n2,-1,-0.05,-0.05\n"
                                                                    "*ELEMENT_DISCRETE\n3,2,2,11\n",
                                                          1.0)),
                      true);
  REQUIRE_MESSAGE(!free->diags.has_errors(), free->messages());
  core::Diagnostics d;
  CHECK(solver::compile(free->model(), d) == nullptr);
  std::string said;
  for (const core::Diagnostic& m : d.all())
    said += m.message + "\n";
  CHECK_MESSAGE(
      said.find("discrete element 3: node 2 has no mass and is not held") != std::string::npos,
      said);
}

TEST_CASE("discrete elements: a run continued from a dump ends with the same bytes") {
  test::TempDir dir;
  const std::string deck =
      oscillator_deck(kSpring + "*DATABASE_GLSTAT\n0.01\n*DATABASE_BINARY_D3DUMP\n400\n", 1.0);
  // Continued from the first dump (cycle 400 of 1,000).
  const auto [through, resumed] = test::run_through_and_resumed(dir, dir.write("osc.k", deck));
  CHECK(test::read_text(through / "glstat") == test::read_text(resumed / "glstat"));
}

TEST_CASE("glstat's number of elements counts the discrete elements as elements") {
  // The rigid cube's solid is not integrated (it only gives the body its mass); the spring and
  // the damper are: 2, as LS-DYNA counts the deformable elements it updates.
  test::TempDir dir;
  const std::string deck =
      oscillator_deck(kSpring +
                          "*PART\ndamper\n3,3,3\n*SECTION_DISCRETE\n3\n*MAT_DAMPER_VISCOUS\n3,2\n"
                          "*ELEMENT_DISCRETE\n2,3,1,11\n*DATABASE_GLSTAT\n0.01\n",
                      0.02);
  const test::Run r = test::run_mcdyna("run " + dir.write("osc.k", deck).string() + " --out " +
                                       (dir.path() / "out").string());
  REQUIRE(r.exit_code == 0);
  const std::string glstat = test::read_text(dir.path() / "out" / "glstat");
  CHECK_MESSAGE(
      glstat.find(" number of elements.............             2\n") != std::string::npos, glstat);
}
