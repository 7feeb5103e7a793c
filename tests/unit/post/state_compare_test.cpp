// `mcdyna compare A B` on two d3plot families (issue 49): states matched by time, nodes and
// elements by user ID, per part and field the largest and RMS difference and B's peak; exit 1
// outside --tol, 2 when the two cannot be compared.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cmath>

#include "io/d3plot/d3plot_reader.hpp"
#include "output_support.hpp"
#include "post/state_compare.hpp"

namespace mcdyna::test {

namespace {

namespace fs = std::filesystem;

// The cube drop with its initial speed `v0` (the deck's is -10000), run into DIR/NAME.
fs::path cube_run(const TempDir& dir, const std::string& name, const std::string& v0) {
  const std::string deck =
      with(source_text("decks/cube/cube_drop.k"), "R v0        -10000.0", "R v0        " + v0);
  const fs::path file = dir.write(name + ".k", deck), out = dir.path() / name;
  const Run r = run_mcdyna("run " + file.string() + " --out " + out.string() + " -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  return out;
}

const post::StateFieldDifference* row(const post::StateComparison& c, const std::string& field) {
  for (const post::StateFieldDifference& d : c.rows)
    if (d.field == field) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("compare d3plot: a run against itself differs nowhere, a faster drop by its speed") {
  TempDir dir;
  const fs::path a = cube_run(dir, "a", "-10000.0"), same = cube_run(dir, "same", "-10000.0"),
                 fast = cube_run(dir, "fast", "-11000.0");
  const io::d3plot::Reader ra(a), rsame(same), rfast(fast);
  const post::StateComparison c = post::compare_states(ra, rsame);
  CHECK(c.matched.size() == ra.states());
  CHECK(c.nodes == 27);
  CHECK(c.elements == 8);
  CHECK(c.only_a + c.only_b == 0);
  for (const post::StateFieldDifference& d : c.rows) {
    CAPTURE(d.field);
    CHECK(d.max == 0.0);
    CHECK(d.values > 0);
  }
  // 11000 against 10000: at t = 0 every node's velocity differs by 1000 (single precision), and
  // B's peak is at least the initial 10000.
  const post::StateComparison f = post::compare_states(rfast, ra);
  REQUIRE(f.matched.size() >= 2);
  const post::StateFieldDifference* v = row(f, "velocity");
  REQUIRE(v != nullptr);
  CHECK(v->max >= 1000.0 * (1.0 - 1e-6));
  CHECK(v->peak_b >= 10000.0 * (1.0 - 1e-6));
  CHECK(row(f, "displacement")->max > 0.0);
  CHECK(row(f, "stress")->max > 0.0);

  // The command: exit 0 within --tol, 1 outside, 2 for a family against a history.
  const Run within = run_mcdyna("compare " + a.string() + " " + same.string() + " --tol 0");
  CHECK_MESSAGE(within.exit_code == 0, within.output);
  CHECK(within.output.find("within tolerance") != std::string::npos);
  const Run outside = run_mcdyna("compare " + fast.string() + " " + a.string() + " --tol 0.01");
  CHECK_MESSAGE(outside.exit_code == 1, outside.output);
  CHECK(outside.output.find("OUTSIDE tolerance") != std::string::npos);
  CHECK(outside.output.find("velocity") != std::string::npos);
  const Run mixed = run_mcdyna("compare " + a.string() + " " + (a / "glstat").string());
  CHECK(mixed.exit_code == 2);
  CHECK(mixed.output.find("d3plot family compares with a d3plot family only") != std::string::npos);
}

TEST_CASE("compare d3plot: LS-DYNA's family against itself, every state matched, no difference") {
  const fs::path lsdyna = fs::path(MCDYNA_SOURCE_DIR) / "tests/data/lasso/d3plot_solid_int";
  const Run r = run_mcdyna("compare " + lsdyna.string() + " " + lsdyna.string() + " --tol 0");
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("matched 22 of 22 states") != std::string::npos);
  CHECK(r.output.find("106 nodes and 32 elements") != std::string::npos);
}

TEST_CASE("compare d3plot --diff-series: A - B on B's mesh, a VTK file per matched state") {
  TempDir dir;
  const fs::path a = cube_run(dir, "a", "-10000.0"), fast = cube_run(dir, "fast", "-11000.0");
  const fs::path series = dir.path() / "difference";
  const Run r = run_mcdyna("compare " + fast.string() + " " + a.string() + " --diff-series " +
                           series.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("difference series: " + (series / "difference.pvd").string()) !=
        std::string::npos);
  const std::vector<std::string> states = collection(series / "difference.pvd");
  REQUIRE(states.size() == io::d3plot::Reader(a).states());
  // At t = 0 the nodes differ by their initial speed only: A - B = -11000 - (-10000) in z.
  const auto first = read_vtu(series / states.front());
  CHECK(first->GetNumberOfPoints() == 27);
  CHECK(first->GetNumberOfCells() == 8);
  vtkDataArray* dv = first->GetPointData()->GetArray("velocity_difference");
  REQUIRE(dv != nullptr);
  for (vtkIdType n = 0; n < 27; ++n) {
    CHECK(dv->GetComponent(n, 0) == 0.0);
    CHECK(dv->GetComponent(n, 2) == -1000.0);
  }
  CHECK(first->GetCellData()->GetArray("stress_difference") != nullptr);
  CHECK(first->GetCellData()->GetArray("element_id")->GetComponent(0, 0) == 1.0);
  // Later the stresses differ.
  const auto last = read_vtu(series / states.back());
  vtkDataArray* ds = last->GetCellData()->GetArray("stress_difference");
  double largest = 0.0;
  for (vtkIdType e = 0; e < 8; ++e)
    for (int c = 0; c < 6; ++c)
      largest = std::max(largest, std::abs(ds->GetComponent(e, c)));
  CHECK(largest > 0.0);
  const Run history = run_mcdyna("compare " + (a / "glstat").string() + " " +
                                 (fast / "glstat").string() + " --diff-series " + series.string());
  CHECK(history.exit_code == 2);
  CHECK(history.output.find("--diff-series is for two d3plot families") != std::string::npos);
}

}  // namespace mcdyna::test
