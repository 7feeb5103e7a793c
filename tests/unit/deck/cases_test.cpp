// *CASE decks: a master case reads the main model and the subcases it lists (*CASE_BEGIN_n ..
// *CASE_END_n blocks and keywords marked CID=n); `mcdyna run` takes each case in turn into
// OUT/JOBID, or the one --case names.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "deck/cases.hpp"
#include "output_support.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

// The data lines of the deck's *TITLE keywords, in order.
std::vector<std::string> titles(const deck::Deck& d) {
  std::vector<std::string> out;
  for (const deck::KeywordBlock& b : d.blocks)
    if (b.name == "TITLE" && b.line_count() > 0) out.emplace_back(d.lines[b.first_line].text);
  return out;
}

const std::string kCases =
    "*KEYWORD\n"
    "*CASE\n       101 SLOW\nMEMORY=20M\n1\n"
    "*CASE\n102,FAST\n2 3\n"
    "*TITLE\nmain\n"
    "*TITLE CID=1\none\n"
    "*CASE_BEGIN_2\n*TITLE\ntwo\n*CASE_BEGIN_3\n*TITLE\ntwo and three\n*CASE_END_3\n"
    "*CASE_END_2\n"
    "*TITLE\nmain again\n*END\n";

}  // namespace

TEST_CASE("*CASE: each case reads the main model and the subcases it lists") {
  core::Diagnostics d;
  deck::Deck full = deck::read_deck_text(kCases, "cases.k", d);
  const std::vector<deck::Case> cases = deck::read_cases(full, d);
  REQUIRE_MESSAGE(!d.has_errors(), d.error_count());
  REQUIRE(cases.size() == 2);
  CHECK(cases[0].id == 101);
  CHECK(cases[0].job == "SLOW");
  CHECK(cases[0].commands == std::vector<std::string>{"MEMORY=20M"});
  CHECK(cases[0].subcases == std::vector<long>{1});
  CHECK(cases[1].id == 102);
  CHECK(cases[1].job == "FAST");
  CHECK(cases[1].subcases == std::vector<long>{2, 3});

  // The titles a selection keeps, from a fresh read of the deck.
  auto kept = [](const std::vector<long>* subcases) {
    core::Diagnostics quiet;
    deck::Deck d = deck::read_deck_text(kCases, "cases.k", quiet);
    if (subcases == nullptr) {
      deck::keep_main_model(d);
    } else {
      deck::Case c;
      c.subcases = *subcases;
      deck::keep_case(d, c);
    }
    return titles(d);
  };
  CHECK(kept(&cases[0].subcases) == std::vector<std::string>{"main", "one", "main again"});
  CHECK(kept(&cases[1].subcases) ==
        std::vector<std::string>{"main", "two", "two and three", "main again"});
  CHECK(kept(nullptr) == std::vector<std::string>{"main", "main again"});
  // A case listing only 3 does not read what is inside *CASE_BEGIN_2, 3's block included.
  const std::vector<long> only_three = {3};
  CHECK(kept(&only_three) == std::vector<std::string>{"main", "main again"});
}

TEST_CASE("*CASE: unbalanced blocks, a repeated CASEID and per-case parameters are errors") {
  auto errors = [](const std::string& text) {
    core::Diagnostics d;
    const deck::Deck deck = deck::read_deck_text(text, "bad.k", d);
    (void)deck::read_cases(deck, d);
    std::string all;
    for (const core::Diagnostic& m : d.all())
      all += m.message + "\n";
    return all;
  };
  CHECK(errors("*KEYWORD\n*CASE_BEGIN_1\n*TITLE\nx\n*END\n")
            .find("*CASE_BEGIN_1 is not closed by a *CASE_END_1") != std::string::npos);
  CHECK(errors("*KEYWORD\n*CASE_BEGIN_1\n*CASE_END_2\n*CASE_END_1\n*END\n")
            .find("*CASE_END_2 without a matching *CASE_BEGIN_2 (the open one is "
                  "*CASE_BEGIN_1)") != std::string::npos);
  CHECK(errors("*KEYWORD\n*CASE_BEGIN_x\n*END\n").find("\"X\" is not a subcase number") !=
        std::string::npos);
  CHECK(errors("*KEYWORD\n*CASE\n5 A\n*CASE\n5 B\n*END\n").find("*CASE 5 is defined twice") !=
        std::string::npos);
  CHECK(errors("*KEYWORD\n*CASE_BEGIN_1\n*PARAMETER\nR v 1.0\n*CASE_END_1\n*END\n")
            .find("a parameter per case is not supported") != std::string::npos);
}

TEST_CASE("*CASE: run takes each case into OUT/JOBID, --case one of them") {
  TempDir dir;
  // A 1 mm steel cube moving at 1 m/s (case 1) or 2 m/s (case 2): kinetic energy m v^2 / 2.
  const std::string deck =
      "*KEYWORD\n*CASE\n1 SLOW\n1\n*CASE\n2 FAST\n2\n*TITLE\ncube\n*TITLE CID=2\nfast cube\n"
      "*CONTROL_TERMINATION\n1.0e-6\n*DATABASE_GLSTAT\n1.0e-7\n"
      "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n" +
      box_mesh(1, 1, 1, 1.0) +
      "*CASE_BEGIN_1\n*INITIAL_VELOCITY\n0\n1000.0,0,0\n*CASE_END_1\n"
      "*CASE_BEGIN_2\n*INITIAL_VELOCITY\n0\n2000.0,0,0\n*CASE_END_2\n*END\n";
  const auto path = dir.write("cases.k", deck);
  const Run all =
      run_mcdyna(fmt::format("run {} --out {} -q", path.string(), (dir.path() / "out").string()));
  REQUIRE_MESSAGE(all.exit_code == 0, all.output);
  CHECK(all.output.find("case 1 (SLOW)") != std::string::npos);
  CHECK(all.output.find("case 2 (FAST)") != std::string::npos);
  auto first_kinetic_energy = [](const std::filesystem::path& glstat) {
    const std::string text = read_text(glstat);
    const std::string second_line = text.substr(text.find('\n') + 1);
    const std::size_t a = second_line.find(',', second_line.find(',') + 1);
    return std::stod(second_line.substr(a + 1));
  };
  const double mass = 7.85e-9;
  CHECK(first_kinetic_energy(dir.path() / "out/SLOW/glstat.csv") ==
        doctest::Approx(0.5 * mass * 1000.0 * 1000.0).epsilon(1e-12).scale(0.0));
  CHECK(first_kinetic_energy(dir.path() / "out/FAST/glstat.csv") ==
        doctest::Approx(0.5 * mass * 2000.0 * 2000.0).epsilon(1e-12).scale(0.0));
  CHECK(read_text(dir.path() / "out/FAST/d3hsp").find("fast cube") != std::string::npos);
  CHECK(read_text(dir.path() / "out/SLOW/d3hsp").find("fast cube") == std::string::npos);

  const Run one = run_mcdyna(
      fmt::format("run {} --case 2 --out {} -q", path.string(), (dir.path() / "one").string()));
  REQUIRE_MESSAGE(one.exit_code == 0, one.output);
  CHECK(first_kinetic_energy(dir.path() / "one/glstat.csv") ==
        doctest::Approx(0.5 * mass * 2000.0 * 2000.0).epsilon(1e-12).scale(0.0));
  const Run missing = run_mcdyna(
      fmt::format("run {} --case 7 --out {} -q", path.string(), (dir.path() / "none").string()));
  CHECK(missing.exit_code == 1);
  CHECK(missing.output.find("--case 7: the deck defines the cases 1 (SLOW), 2 (FAST)") !=
        std::string::npos);
}

}  // namespace mcdyna::test
