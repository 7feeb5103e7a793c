// Beams (issue 26): Hughes-Liu (ELFORM 1) and Belytschko-Schwer (ELFORM 2) against closed-form
// answers: a tip-loaded cantilever's deflection, its first-mode period, a bar drawn past yield,
// and the fully plastic moment of a rectangle.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

#include "shell_decks.hpp"
#include "solver/beams/beam_results.hpp"
#include "solver_support.hpp"

using namespace mcdyna;

namespace {

// Steel cantilever along x, 100 mm long (SI units), clamped at node 1: n beams with the section
// `width` (along s = y) x `depth` (along t = z), given by TS/TT (ELFORM 1, SHRF 5/6) or by A,
// ISS, ITT, SA = 5/6 A (ELFORM 2); orientation by the _ORIENTATION vector (0, 1, 0). `tail` is
// the rest of the deck (loads, velocities, damping).
constexpr double kLength = 0.1, kYoung = 210e9, kDensity = 7850.0, kPoisson = 0.3;

std::string cantilever(int n, int elform, double width, double depth, double end,
                       const std::string& material, const std::string& tail) {
  std::string s = fmt::format("*KEYWORD\n*CONTROL_TERMINATION\n{}\n*PART\nbeam\n1,1,1\n", end);
  const double area = width * depth;
  if (elform == 1)
    s += fmt::format("*SECTION_BEAM\n1,1,0.8333333333,2,0\n{},{},{},{}\n", width, width, depth,
                     depth);
  else
    s += fmt::format("*SECTION_BEAM\n1,2\n{:.10g},{:.10g},{:.10g},0,{:.10g}\n", area,
                     width * depth * depth * depth / 12.0, depth * width * width * width / 12.0,
                     area * 5.0 / 6.0);
  s += material + "*NODE\n";
  for (int i = 0; i <= n; ++i)
    s += fmt::format("{},{:.10g},0,0\n", i + 1, kLength * i / n);
  s += "*ELEMENT_BEAM_ORIENTATION\n";
  for (int i = 0; i < n; ++i)
    s += fmt::format("{:8d}{:8d}{:8d}{:8d}\n0,1,0\n", i + 1, 1, i + 1, i + 2);
  return s + "*BOUNDARY_SPC_NODE\n1,0,1,1,1,1,1,1\n" + tail + "*END\n";
}

const std::string kElastic = fmt::format("*MAT_ELASTIC\n1,{},{},{}\n", kDensity, kYoung, kPoisson);

// Tip deflection under a tip force P along z, settled by *DAMPING_GLOBAL near critical.
double tip_deflection(int n, int elform, double force) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir, cantilever(n, elform, 0.01, 0.001, 0.05, kElastic,
                      fmt::format("*LOAD_NODE_POINT\n{},3,1,{}\n*DEFINE_CURVE\n1\n0,1\n1,1\n"
                                  "*DAMPING_GLOBAL\n0,1000\n",
                                  n + 1, force)));
  test::run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  return sim.state->nodes.position(2, n);
}

}  // namespace

TEST_CASE("a tip-loaded cantilever: Belytschko-Schwer exact, Hughes-Liu as its one-point rule") {
  // Static tip deflection P L^3 / 3 E I + P L / (G SA) (Timoshenko) of the 10 x 1 mm strip
  // bent about s under P = 0.1 N: 1.90496e-4 m (0.19 % of L, so geometric effects stay below
  // 1e-4). The resultant beam's end moments are the exact Timoshenko stiffness: any mesh gives
  // it. The one-point Hughes-Liu beam is the linear Timoshenko element with reduced
  // integration, whose tip deflection is delta (1 - 1 / (4 n^2)) plus the shear term.
  const double inertia = 0.01 * 1e-9 / 12.0, area = 1e-5;
  const double shear = kYoung / (2.0 * (1.0 + kPoisson));
  const double bending = 0.1 * std::pow(kLength, 3) / (3.0 * kYoung * inertia);
  const double exact = bending + 0.1 * kLength / (shear * area * 5.0 / 6.0);
  for (const int n : {4, 10}) {
    const double bs = tip_deflection(n, 2, 0.1);
    MESSAGE("ELFORM 2, ", n, " elements: ", bs, " m, ", 100.0 * (bs / exact - 1.0), " %");
    CHECK(std::abs(bs / exact - 1.0) < 1e-4);
    const double hl = tip_deflection(n, 1, 0.1);
    const double discrete = bending * (1.0 - 1.0 / (4.0 * n * n)) + (exact - bending);
    MESSAGE("ELFORM 1, ", n, " elements: ", hl, " m, ", 100.0 * (hl / exact - 1.0),
            " % (the element's own answer ", discrete, ")");
    CHECK(std::abs(hl / discrete - 1.0) < 1e-4);
  }
}

TEST_CASE("a beam cantilever's first-mode period converges to beam theory, energy kept") {
  // A 2 x 2 mm steel bar (L / h = 50) released with its first mode's velocities (tip 0.1 m/s).
  // Beam theory (Euler-Bernoulli): T = 2 pi L^2 / (1.8751^2 sqrt(E I / rho A)). The lumped
  // masses converge as h^2, to the Timoshenko beam: its shear and rotary inertia lengthen the
  // period by about (r / L)^2 beta^2 (1 + E / kappa G) / 2, 0.03 % here (0.20 % for a 5 x 5 mm
  // bar, which is what both formulations converge to with it: +0.228 % at 40 elements, the
  // discrete beam's own eigenvalue to 4 digits).
  const double side = 0.002;
  const double beam = 2.0 * M_PI * kLength * kLength / (test::kBetaL * test::kBetaL) /
                      std::sqrt(kYoung * side * side / (12.0 * kDensity));
  double last_error = 1.0;
  for (const int elform : {1, 2}) {
    for (const int n : {10, 40}) {
      std::string velocities = "*INITIAL_VELOCITY_NODE\n";
      const double tip = test::mode(1.0, false);
      for (int i = 1; i <= n; ++i) {
        const double x = static_cast<double>(i) / n;
        velocities +=
            fmt::format("{},0,0,{:.10g},0,{:.10g},0\n", i + 1, 0.1 * test::mode(x, false) / tip,
                        -0.1 * test::mode(x, true) / tip / kLength);
      }
      test::TempDir dir;
      test::Simulation sim =
          test::prepare(dir, cantilever(n, elform, side, side, 0.02, kElastic, velocities));
      std::vector<double> crossings;
      double last_z = 0.0, last_t = 0.0;
      test::EnergyDrift drift;
      solver::RunHooks hooks = drift.hooks();
      hooks.progress = [&](const solver::State& s) {
        const double z = s.nodes.position(2, n);
        if (last_t > 0.0 && z * last_z < 0.0)
          crossings.push_back(last_t - last_z * (s.time - last_t) / (z - last_z));
        last_z = z;
        last_t = s.time;
      };
      test::run(sim, hooks);
      REQUIRE(crossings.size() >= 3);
      const double period =
          2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
      const double error = period / beam - 1.0;
      MESSAGE("ELFORM ", elform, ", ", n, " elements: period ", period * 1e3, " ms, ",
              100.0 * error, " % on beam theory; energy drift ", drift.worst);
      CHECK(error > 0.0);  // lumped masses: the discrete beam is slower
      CHECK(error < (n == 10 ? 0.008 : 0.001));
      CHECK(drift.worst < 1e-4);
      if (n == 40) CHECK(error < last_error / 3.0);  // converging (h^2: a quarter)
      last_error = error;
    }
  }
}

TEST_CASE("a Hughes-Liu bar drawn past yield carries the hardening curve's force") {
  // A 10 x 10 mm bar, 100 mm long, *MAT_PLASTIC_KINEMATIC (isotropic, BETA 1: sigma_y = 200 MPa,
  // E_tan = 2 GPa) pulled at 1 m/s at its free end. Uniaxial stress: past yield the axial force
  // is A (sigma_y + E_p eps_p) with E_p = E E_t / (E - E_t) and eps_p = eps - sigma / E; the
  // strain is the engineering-rate integral ln(L / L0). Compared at 2 % strain, the force
  // read from the element's resultant.
  const std::string material =
      fmt::format("*MAT_PLASTIC_KINEMATIC\n1,{},{},{},200e6,2e9,1.0\n", kDensity, kYoung, kPoisson);
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir,
      cantilever(4, 1, 0.01, 0.01, 0.002, material,
                 "*BOUNDARY_PRESCRIBED_MOTION_NODE\n5,1,0,2,1.0\n*DEFINE_CURVE\n2\n0,1\n1,1\n"));
  test::run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const solver::State& s = *sim.state;
  const double length = s.nodes.position(0, 4);
  const double strain = std::log(length / kLength);
  const double ep_modulus = kYoung * 2e9 / (kYoung - 2e9);
  // sigma = sigma_y + E_p (eps - sigma / E)  =>  sigma (1 + E_p / E) = sigma_y + E_p eps
  const double stress = (200e6 + ep_modulus * strain) / (1.0 + ep_modulus / kYoung);
  const solver::Beams& bm = *solver::beams_of(s);
  const double force = solver::beam_resultants(s, bm, bm.blocks[0], 0)[0];
  const double area = 1e-4 * std::exp(-strain);  // volume kept in the plastic flow, roughly
  MESSAGE("strain ", strain, ": force ", force, " N; uniaxial ", stress * 1e-4,
          " N on the initial area (", stress * area, " N on the current one)");
  // The beam's area stays its initial one (no thickness update), so the force is the
  // engineering value.
  CHECK(force == doctest::Approx(stress * 1e-4).epsilon(0.01));
  CHECK(bm.points.plastic_strain[0] > 0.01);
}

TEST_CASE("the fully plastic moment of a rectangle, to its section rule") {
  // A 10 x 10 mm cantilever of two elements, elastic-perfectly-plastic steel (sigma_y = 200 MPa),
  // its tip pushed along z at 1 m/s to 3 mm: the clamped element, which carries 3/4 of the root
  // moment at its point, forms the hinge, and its moment rises to the fully plastic value its
  // fibres can carry. Exact for the rectangle: sigma_y b h^2 / 4 = 50 N m; with QR 5 (4 x 4
  // Gauss through the depth) the fibres' rule gives sigma_y b h^2 (a w_a + b w_b) / 2 = 52.1 N m
  // (+4.3 %) for the Gauss points a = 0.340 and b = 0.861 (weights 0.652 and 0.348).
  const std::string material =
      fmt::format("*MAT_PLASTIC_KINEMATIC\n1,{},{},{},200e6,0,1.0\n", kDensity, kYoung, kPoisson);
  std::string deck =
      cantilever(2, 1, 0.01, 0.01, 0.003, material,
                 "*BOUNDARY_PRESCRIBED_MOTION_NODE\n3,3,0,2,1.0\n*DEFINE_CURVE\n2\n0,1\n1,1\n");
  deck.replace(deck.find("1,1,0.8333333333,2,0"), 20, "1,1,0.8333333333,5,0");
  test::TempDir dir;
  test::Simulation sim = test::prepare(dir, deck);
  test::run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  const solver::Beams& bm = *solver::beams_of(*sim.state);
  const auto r = solver::beam_resultants(*sim.state, bm, bm.blocks[0], 0);
  const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
  const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
  const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
  const double rule = 200e6 * 1e-4 * 0.005 * (a * wa + b * wb);
  MESSAGE("moment about s ", r[4], " N m; fibres' fully plastic ", rule, " N m; exact 50 N m");
  CHECK(std::abs(r[4]) == doctest::Approx(rule).epsilon(0.01));
}

TEST_CASE("beams: results are bitwise identical for 1 and 2 threads") {
  // 600 beams, above the pass's serial limit of 512, released with a bending and twisting
  // velocity field; Hughes-Liu on a plastic material (its fibres take the plastic model's
  // update path), the resultant beam elastic.
  const std::string material =
      fmt::format("*MAT_PLASTIC_KINEMATIC\n1,{},{},{},200e6,2e9,1.0\n", kDensity, kYoung, kPoisson);
  for (const int elform : {1, 2}) {
    CAPTURE(elform);
    std::string velocities = "*INITIAL_VELOCITY_NODE\n";
    for (int i = 1; i <= 600; ++i)
      velocities += fmt::format("{},0,{:.6g},{:.6g},{:.6g},0,0\n", i + 1, 2.0 * i / 600.0,
                                5.0 * i / 600.0, 300.0 * i / 600.0);
    const std::string deck =
        cantilever(600, elform, 0.002, 0.002, 2e-5, elform == 1 ? material : kElastic, velocities);
    const test::ThreadRuns r = test::run_on_one_and_two_threads(deck);
    CHECK(r.positions[0] == r.positions[1]);
    CHECK(r.spins[0] == r.spins[1]);
  }
}

TEST_CASE("what the beams cannot run is refused at its deck location") {
  // Releases, a resultant beam on a plastic material, a user integration rule, an orientation
  // node on the beam's line and an orientation node that does not exist.
  test::TempDir dir;
  const auto loaded =
      test::load_file(dir.write("deck.k",
                                "*KEYWORD\n*CONTROL_TERMINATION\n1e-3\n"
                                "*NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n4,0,1,0\n"
                                "*PART\nhl\n1,1,1\nbs\n2,2,2\n"
                                "*SECTION_BEAM\n1,1,1.0,2,2\n0.1,0.1,0.1,0.1\n"
                                "*SECTION_BEAM\n2,2\n0.01,1e-5,1e-5,0,0\n"
                                "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n"
                                "*MAT_PLASTIC_KINEMATIC\n2,7.85e-9,210e3,0.3,200,1000,1\n"
                                "*ELEMENT_BEAM\n"
                                "       1       1       1       2       4       0       3\n"
                                "       2       2       2       3       1\n"
                                "       3       1       1       2      99\n*END\n"),
                      true);
  const std::string text = loaded->messages();
  MESSAGE(text);
  CHECK(text.find("deck.k:25:49-56: error: *ELEMENT_BEAM: element 1: RR1 = 3: beam end releases "
                  "are not supported") != std::string::npos);
  CHECK(
      loaded->has_message("part 2: the Belytschko-Schwer resultant beam (ELFORM 2) runs "
                          "elastic materials only"));
  CHECK(loaded->has_message("part 1: CST 2 (user integration rule"));
  CHECK(
      loaded->has_message("beam element 3 refers to orientation node 99 (N3), which is not "
                          "defined"));
  // A deck clean of those, whose orientation node lies on the beam: refused when compiled.
  const auto line = test::load_file(
      dir.write("line.k",
                "*KEYWORD\n*CONTROL_TERMINATION\n1e-3\n*NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n"
                "*PART\nbs\n1,1,1\n*SECTION_BEAM\n1,2\n0.01,1e-5,1e-5,0,0\n"
                "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n*ELEMENT_BEAM\n1,1,1,2,3\n*END\n"),
      true);
  REQUIRE_MESSAGE(!line->diags.has_errors(), line->messages());
  core::Diagnostics d;
  CHECK(solver::compile(line->model(), d) == nullptr);
  std::string collinear;
  for (const core::Diagnostic& m : d.all())
    collinear += m.message + "\n";
  CHECK(collinear.find("beam element 1 of part 1: its orientation (node 3) lies along the beam") !=
        std::string::npos);
}

namespace {

// The lap joint of the spot-weld test (joins_test.cpp), t, mm, s: plate A (10 x 10 mm, 10 mm
// thick, three corners held) at z = 0, plate B (1 mm) at z = 1, joined from A's free corner
// (node 1) to the corner above it (node 5) by a spot-weld beam (ELFORM 9, a 2 mm round rod,
// *MAT_SPOTWELD `weld` card 1 after MID RO and card 2), node 5 pulled by 1e4 t N along
// `direction`. Returns when the weld eroded (-1: it held).
double beam_weld_fails_at(const std::string& weld, const std::string& direction, double end) {
  test::TempDir dir;
  test::Simulation sim = test::prepare(
      dir, fmt::format("*KEYWORD\n*CONTROL_TERMINATION\n{}\n", end) +
               "*PART\nA\n1,2,1\n*PART\nB\n2,1,1\n*PART\nweld\n3,3,2\n"
               "*SECTION_SHELL\n1,2\n1.0,1.0,1.0,1.0\n*SECTION_SHELL\n2,2\n10.0,10.0,10.0,10.0\n"
               "*SECTION_BEAM\n3,9,0.8333333333,2,1\n2.0,2.0\n"
               "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n*MAT_SPOTWELD\n2,7.85e-9," +
               weld +
               "*NODE\n1,0,0,0\n2,10,0,0\n3,10,10,0\n4,0,10,0\n5,0,0,1\n6,10,0,1\n7,10,10,1\n"
               "8,0,10,1\n9,5,5,0\n"
               "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n*ELEMENT_BEAM\n3,3,1,5,9\n"
               "*SET_NODE_LIST\n1\n2,3,4\n*BOUNDARY_SPC_SET\n1,0,1,1,1,1,1,1\n" +
               direction + "*DEFINE_CURVE\n1\n0,0\n1,10000\n*END\n");
  REQUIRE(solver::beams_of(*sim.state) != nullptr);
  REQUIRE(solver::beams_of(*sim.state)->count() == 1);
  double failed = -1.0;
  long cycles_since = 0;
  solver::RunHooks hooks;
  hooks.progress = [&](const solver::State& s) {
    if (failed < 0.0 && solver::beams_of(s)->eroded[0]) failed = s.time;
  };
  hooks.stop_requested = [&] { return failed >= 0.0 && ++cycles_since > 20; };
  test::run(sim, hooks);
  return failed;
}

}  // namespace

TEST_CASE("spot-weld beams fail at the resultants, the time or the strain *MAT_SPOTWELD names") {
  // Pulled slowly (the joint's own period is some 0.1 ms against the 10 ms ramp), the weld
  // carries F = 1e4 t: NRR 100 N fails it at 10 ms, NRS = NRT = 200 N at 20 ms (the weld's s
  // axis points to node 9, 45 degrees off the pull: its two shear terms add up to (F/200)^2),
  // and both
  // (F/100)^2 + (F/200)^2 = 1 at F = 89.44 N, 8.944 ms. The weld is stiff and elastic here
  // (SIGY 1e4 MPa); the shear's lever to the weld's end enters only a moment term, none here.
  const std::string strong = "210e3,0.3,1e4,0\n";
  const std::string normal = "*LOAD_NODE_POINT\n5,3,1,1.0\n";
  const std::string shear = "*LOAD_NODE_POINT\n5,1,1,1.0\n";
  const double combined = 1.0 / std::sqrt(1e-4 + 2.5e-5) / 1e4;
  struct Case {
    std::string what, weld, load;
    double expected;
  };
  for (const Case& c :
       {Case{"axial", strong + "0,100.0\n", normal, 0.01},
        Case{"shear", strong + "0,0,200.0,200.0\n", shear, 0.02},
        Case{"both", strong + "0,100.0,200.0,200.0\n", normal + shear, combined},
        Case{"TFAIL", "210e3,0.3,1e4,0,0,5e-3\n", normal, 5e-3},
        // SIGY 50 MPa, EH 1000 MPa on 3.1416 mm^2: every fibre reaches EFAIL 0.1 when
        // F = A (SIGY + EH EFAIL) = 471.2 N (47.12 ms; the elastic strain is left out of EH's
        // plastic strain).
        Case{"EFAIL", "210e3,0.3,50.0,1000.0\n0.1\n", normal, M_PI * (50.0 + 100.0) / 1e4}}) {
    const double failed = beam_weld_fails_at(c.weld, c.load, c.expected * 1.05);
    MESSAGE(c.what, ": the weld failed at ", failed * 1e3, " ms against ", c.expected * 1e3,
            " ms (", 100.0 * (failed / c.expected - 1.0), " %)");
    CHECK(std::abs(failed / c.expected - 1.0) < 0.01);
  }
  // Pushed together it holds: the axial term counts tension only.
  CHECK(beam_weld_fails_at(strong + "0,100.0\n", "*LOAD_NODE_POINT\n5,3,1,-1.0\n", 0.012) < 0.0);
}

TEST_CASE("the spot-weld beam and *MAT_SPOTWELD go together") {
  test::TempDir dir;
  const auto loaded = test::load_file(
      dir.write("deck.k",
                "*KEYWORD\n*CONTROL_TERMINATION\n1e-3\n*NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n4,0,1,0\n"
                "*PART\nweld on elastic\n1,9,1\n*PART\nspotweld on Hughes-Liu\n2,1,2\n"
                "*SECTION_BEAM\n9,9,1.0,2,1\n1.0\n*SECTION_BEAM\n1,1,1.0,2,1\n1.0\n"
                "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n*MAT_SPOTWELD\n2,7.85e-9,210e3,0.3,300\n"
                "*ELEMENT_BEAM\n1,1,1,2,4\n2,2,2,3,4\n*END\n"),
      true);
  CHECK(loaded->has_message("part 1: the spot-weld beam (ELFORM 9) needs *MAT_SPOTWELD"));
  CHECK(loaded->has_message("part 2: *MAT_SPOTWELD runs on spot-weld beams (ELFORM 9) only"));
}
