// Every public deck in tests/data/public-decks: read without crash or internal error, every
// keyword classified, and spot-checked values in several decks.
#include <doctest/doctest.h>

#include <cmath>
#include <map>

#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace mcdyna;

namespace {

const fs::path kCorpus = fs::path(MCDYNA_SOURCE_DIR) / "tests/data/public-decks";

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("corpus: every public deck is read, built and checked, every keyword is classified") {
  const auto files = corpus_files();
  REQUIRE(files.size() == 79);
  std::map<deck::Support, std::size_t> distinct_by_class;
  std::map<std::string, deck::Support> distinct;
  std::size_t clean = 0, keywords = 0;
  for (const fs::path& f : files) {
    CAPTURE(f.string());
    auto l = test::load_file(f, true);
    CHECK_MESSAGE(!l->has_message("internal error"), l->messages());
    for (const auto& u : l->built.keywords) {
      ++keywords;
      CHECK(!u.name.empty());
      CHECK((u.support == deck::Support::supported || !u.reason.empty()));
      distinct.emplace(u.name, u.support);
    }
    if (!l->diags.has_errors()) ++clean;
  }
  for (const auto& [name, s] : distinct)
    ++distinct_by_class[s];
  MESSAGE("corpus: ", files.size(), " decks, ", clean, " without deck errors, ", keywords,
          " keyword blocks, ", distinct.size(),
          " distinct keywords: ", distinct_by_class[deck::Support::supported], " supported, ",
          distinct_by_class[deck::Support::no_effect], " read without effect, ",
          distinct_by_class[deck::Support::output_only], " unsupported output, ",
          distinct_by_class[deck::Support::unsupported], " unsupported");
  CHECK(keywords > 1000);
}

TEST_CASE("corpus spot check: Taylor bar mesh node and element") {
  auto l = test::load_file(kCorpus / "ansys/pydyna/examples/keywords/Taylor_Bar/taylor_bar_mesh.k");
  const auto& m = l->model();
  REQUIRE(m.nodes.size() == 1122);
  REQUIRE(m.solids.size() == 768);
  CHECK(m.nodes[0].id == 1);
  CHECK(m.nodes[0].position[0] == 1.723924);
  CHECK(m.nodes[0].position[1] == 39.0625);
  CHECK(m.nodes[0].position[2] == -2.303499);
  const std::array<model::Id, 8> first{4, 13, 7, 12, 509, 500, 506, 501};
  CHECK(m.solids[0].nodes == first);
}

TEST_CASE("corpus spot check: material constants in the projectile deck") {
  auto l = test::load_file(kCorpus / "ansys/pydyna/tests/testfiles/run/case-keywords/projectile.k");
  const auto* mat = l->model().materials.empty() ? nullptr : &l->model().materials[1];
  REQUIRE(mat != nullptr);
  CHECK(mat->id == 2);
  CHECK(mat->density == 7.896);
  CHECK(mat->plastic_kinematic.youngs_modulus == 2.1);
  CHECK(mat->plastic_kinematic.poisson_ratio == 0.284);
  CHECK(mat->plastic_kinematic.yield_stress == 0.01);
  CHECK(mat->plastic_kinematic.hardening_mix == 1.0);
}

TEST_CASE("corpus spot check: parameters through includes, expressions and relative paths") {
  auto l = test::load_file(kCorpus /
                           "mjhmilla/Millard2024VEXATMuscleLSDYNA/example/MPP_R931/"
                           "umat43/active_passive_force_length/active_force_length_06/"
                           "active_force_length_06.k");
  CHECK_FALSE(l->has_message("not defined"));
  CHECK_FALSE(l->has_message("not found"));
  const auto& t = l->model().controls.termination;
  REQUIRE(t.has_value());
  CHECK(t->end_time == 2.0);  // ENDTIM = &timeE
  const auto* p = l->deck.parameters.lookup("PATHLEN0", 0);
  REQUIRE(p != nullptr);
  CHECK(p->number == doctest::Approx(1.0 * 0.0479621 * std::cos(0.1221730) + 0.0340783));
}

TEST_CASE("corpus: decks with known upstream defects are reported, not crashed on") {
  auto missing = test::load_file(kCorpus / "Umesh27/VEOL_GUI/input.k");
  CHECK(missing->has_message("include file \"mesh.k\" not found"));
  auto columns = test::load_file(kCorpus / "cxh-1123/LS-DYNA-ablation/test.k");
  CHECK(
      columns->has_message("*CONTROL_TERMINATION card 1 field ENDTIM: expected a real number, "
                           "got \"1.0E-\""));
}
