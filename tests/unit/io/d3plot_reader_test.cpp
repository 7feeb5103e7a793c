// The project's own d3plot reader (issue 49) against families LS-DYNA wrote (tests/data/lasso:
// lasso-python's public samples, with the values Oasys META reads) and against mcdyna's own
// family and VTK series of the same run.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <array>
#include <cmath>

#include "io/d3plot/d3plot_reader.hpp"
#include "output_support.hpp"

namespace mcdyna::test {

namespace {

namespace fs = std::filesystem;
using io::d3plot::Reader;

fs::path sample(const std::string& name) {
  return fs::path(MCDYNA_SOURCE_DIR) / "tests" / "data" / "lasso" / name / "d3plot";
}

// Printed to 7 significant digits: equal within half a unit of the 7th.
bool same_7_digits(double got, double printed) {
  const double unit = std::pow(10.0, std::floor(std::log10(std::abs(printed))) - 6.0);
  return std::abs(got - printed) <= 0.5 * unit;
}

}  // namespace

TEST_CASE("d3plot reader: LS-DYNA's solid integration points as Oasys META reads them") {
  const Reader r(sample("d3plot_solid_int"));
  const io::d3plot::Control& c = r.control();
  CHECK(c.numnp == 106);
  CHECK(c.nel8 == 16);
  CHECK(c.nv3d == 64);  // 8 points of 6 stresses, plastic strain and one history word
  CHECK(c.nel4 == 16);
  CHECK(c.nmmat == 4);
  CHECK(c.extra == 64);
  CHECK(c.thermal_words() == 1);  // IT 10: the mass-scaling word per node
  CHECK(r.state_words() == 2983);
  REQUIRE(r.states() == 22);
  CHECK(r.time(0) == 0.0);
  CHECK(std::abs(r.time(21) - 0.1) < 1e-6);
  CHECK(r.node_ids().front() == 1);
  CHECK(r.node_ids().back() == 120);
  CHECK(r.solids().parts.front() == 2000);
  CHECK(r.shells().parts.front() == 3000);
  // The last state's first solid: sigma xx and plastic strain at its 8 points (lasso-python's
  // test data, "from META").
  const std::array<double, 8> sxx = {2.132084e02, 1.792203e02, 1.397527e02, 2.307352e02,
                                     2.132105e02, 1.792210e02, 1.397558e02, 2.307304e02};
  const std::array<double, 8> eps = {2.227418e-02, 2.576126e-03, 1.909884e-02, 3.695280e-02,
                                     2.227416e-02, 2.576110e-03, 1.909888e-02, 3.695256e-02};
  const io::d3plot::StateData last = r.state(21);
  for (std::size_t k = 0; k < 8; ++k) {
    CAPTURE(k);
    CHECK(same_7_digits(last.solids[8 * k], sxx[k]));
    CHECK(same_7_digits(last.solids[8 * k + 6], eps[k]));
  }
}

TEST_CASE("d3plot reader: a family's members in the order of their numbers, gaps allowed") {
  const Reader r(sample("order_d3plot"));
  REQUIRE(r.states() == 7);
  const std::array<double, 7> times = {1, 2, 10, 11, 12, 22, 100};
  for (std::size_t k = 0; k < 7; ++k)
    CHECK(r.time(k) == times[k]);
}

TEST_CASE("d3plot reader: mcdyna's family reads back as the VTK series and the deck have it") {
  TempDir dir;
  const fs::path deck = dir.write("cube.k", source_text("decks/cube/cube_drop.k"));
  const fs::path out = dir.path() / "out";
  const Run run = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q");
  REQUIRE_MESSAGE(run.exit_code == 0, run.output);
  const Reader r(out);
  const auto model = load_file(deck, true);
  const model::ModelDatabase& m = model->built.model;
  REQUIRE(r.node_ids().size() == m.nodes.size());
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    CHECK(r.node_ids()[n] == m.nodes[n].id);
  REQUIRE(r.solids().count() == m.solids.size());
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    CHECK(r.solids().ids[e] == m.solids[e].id);
    CHECK(r.solids().parts[e] == m.solids[e].part);
  }
  const std::vector<std::string> vtu = collection(out / "d3plot.pvd");
  REQUIRE(r.states() == vtu.size());
  for (std::size_t k = 0; k < vtu.size(); ++k) {
    CAPTURE(k);
    const auto grid = read_vtu(out / vtu[k]);
    const io::d3plot::StateData s = r.state(k);
    for (vtkIdType n = 0; n < grid->GetNumberOfPoints(); ++n)
      for (int c = 0; c < 3; ++c)
        CHECK(s.x[static_cast<std::size_t>(3 * n + c)] == static_cast<float>(grid->GetPoint(n)[c]));
    vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
    for (vtkIdType e = 0; e < grid->GetNumberOfCells(); ++e)
      for (int c = 0; c < 6; ++c)
        CHECK(s.solids[static_cast<std::size_t>(7 * e + c)] ==
              static_cast<float>(stress->GetComponent(e, c)));
    CHECK(std::count(s.solid_deleted.begin(), s.solid_deleted.end(), 1) == 0);
  }
}

TEST_CASE("d3plot reader: what is not a d3plot, or not read, is a clear error") {
  TempDir dir;
  const fs::path junk = dir.write("d3plot", std::string(300, 'x'));
  CHECK_THROWS_WITH_AS(Reader{junk}, doctest::Contains("no d3plot's"), io::d3plot::ReadError);
  const fs::path tiny = dir.write("d3plot_short", "abc");
  CHECK_THROWS_WITH_AS(Reader{tiny}, doctest::Contains("64 control words"), io::d3plot::ReadError);
  CHECK_THROWS_AS(Reader{dir.path() / "missing"}, io::d3plot::ReadError);
}

}  // namespace mcdyna::test
