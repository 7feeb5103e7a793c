// The command line as users run it: exit codes 0 / 1 / 2, LS-DYNA style i=, reports.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "cli/progress.hpp"
#include "test_support.hpp"

namespace {

using mcdyna::test::Run;
using mcdyna::test::run_mcdyna;

const std::string kDataDir = std::string(MCDYNA_SOURCE_DIR) + "/tests/data/";

}  // namespace

TEST_CASE("check: a clean deck exits 0 with summary and migration report") {
  // all_keywords.k holds every keyword the reader knows, not a model that runs (spot welds on
  // rigid bodies' nodes, a beam without a cross section): check compiles it as run would and
  // says so (exit 1), after the summary and the report.
  const Run r = run_mcdyna("check " + kDataDir + "all_keywords.k");
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("nodes            12") != std::string::npos);
  // The report counts the deck's keyword lines (the deck has no *INCLUDE): as many as it has.
  std::istringstream deck(mcdyna::test::read_text(kDataDir + "all_keywords.k"));
  int keywords = 0;
  for (std::string line; std::getline(deck, line);)
    keywords += !line.empty() && line[0] == '*';
  CHECK_MESSAGE(
      r.output.find(fmt::format("Migration report: {} keywords", keywords)) != std::string::npos,
      r.output);
  const Run clean =
      run_mcdyna("check " + std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k");
  CHECK(clean.exit_code == 0);
  CHECK_MESSAGE(clean.output.find("0 errors, 0 warnings - ready to run") != std::string::npos,
                clean.output);
}

TEST_CASE("deck errors exit 1, usage errors exit 2") {
  mcdyna::test::TempDir d;
  const auto bad = d.write("bad.k", "*NODE\n       1   garbage\n");
  const Run r = run_mcdyna("check " + bad.string());
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("bad.k:2:9-24: error: *NODE card node field X: expected a real number, got "
                      "\"garbage\"") != std::string::npos);
  CHECK(run_mcdyna("check").exit_code == 2);
  CHECK(run_mcdyna("frobnicate x.k").exit_code == 2);
  CHECK(run_mcdyna("check " + kDataDir + "all_keywords.k --no-such-flag").exit_code == 2);
  CHECK(run_mcdyna("x=1").exit_code == 2);
  // A missing deck is a usage error (running.md's table), for check and run alike.
  for (const char* command : {"check", "run"}) {
    const Run missing = run_mcdyna(std::string(command) + " /nonexistent/deck.k");
    CHECK(missing.exit_code == 2);
    CHECK(missing.output.find("deck /nonexistent/deck.k: no such file") != std::string::npos);
  }
  CHECK(run_mcdyna("run " + d.path().string()).output.find("is a directory") != std::string::npos);
  // The usage line names the program (CLI11 sees no argv[0] here).
  CHECK(run_mcdyna("--help").output.find("Usage: mcdyna [OPTIONS] SUBCOMMAND") !=
        std::string::npos);
  CHECK(run_mcdyna("run --help").output.find("Usage: mcdyna run [OPTIONS] deck") !=
        std::string::npos);
}

TEST_CASE("nothing to run: an empty deck and nodes without elements are deck errors") {
  mcdyna::test::TempDir d;
  const auto empty = d.write("empty.k", "");
  Run r = run_mcdyna("check " + empty.string());
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("the deck defines no nodes and no elements: nothing to run") !=
        std::string::npos);
  CHECK(r.output.find("ready to run") == std::string::npos);
  CHECK(run_mcdyna("run " + empty.string() + " --out " + (d.path() / "o").string()).exit_code == 1);
  const auto nodes = d.write(
      "nodes.k", "*CONTROL_TERMINATION\n1.0\n*NODE\n       1             0.0\n       2      1.0\n");
  r = run_mcdyna("run " + nodes.string() + " --out " + (d.path() / "o2").string());
  CHECK(r.exit_code == 1);  // was a "time step collapse" (exit 4)
  CHECK_MESSAGE(r.output.find("nodes.k:4: error: the deck defines 2 node(s) but no elements") !=
                    std::string::npos,
                r.output);
}

TEST_CASE("unsupported physics fails check unless --allow-unsupported, no-effect keywords pass") {
  mcdyna::test::TempDir d;
  const std::string body =
      "*INCLUDE\n" + std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k\n";
  const auto deck = d.write("deck.k",
                            "*KEYWORD\n*CONTROL_MPP_IO_NODUMP\n*DATABASE_ELOUT\n0.1\n"
                            "*AIRBAG_SIMPLE_AIRBAG_MODEL\n1,3,1\n" +
                                body);
  const Run strict = run_mcdyna("check " + deck.string());
  CHECK(strict.exit_code == 1);
  CHECK(strict.output.find("UNSUPPORTED        *AIRBAG_SIMPLE_AIRBAG_MODEL (deck.k: 5)") !=
        std::string::npos);
  CHECK(strict.output.find("read, no effect    *CONTROL_MPP_IO_NODUMP (deck.k: 2): MPP") !=
        std::string::npos);
  CHECK(strict.output.find("unsupported output *DATABASE_ELOUT") != std::string::npos);
  CHECK(strict.output.find("1 unsupported keyword changes the physics") != std::string::npos);
  CHECK(run_mcdyna("check --allow-unsupported " + deck.string()).exit_code == 0);
}

TEST_CASE("keywords: list and card layout") {
  const Run list = run_mcdyna("keywords");
  CHECK(list.exit_code == 0);
  CHECK(list.output.find("*MAT_JOHNSON_COOK *MAT_015") != std::string::npos);
  const Run jc = run_mcdyna("keywords MAT_015");
  CHECK(jc.exit_code == 0);
  CHECK(jc.output.find("51-60     TM") != std::string::npos);
  CHECK(run_mcdyna("keywords AIRBAG_SIMPLE_AIRBAG_MODEL").exit_code == 1);
  mcdyna::test::TempDir d;
  CHECK(run_mcdyna("keywords --markdown " + d.path().string()).exit_code == 0);
  CHECK(std::filesystem::exists(d.path() / "MAT_JOHNSON_COOK.md"));
  CHECK(std::filesystem::exists(d.path() / "README.md"));
  // manual/keywords/ is committed so the manual reads on its own: it must be what the schemas
  // generate now (regenerate with `cmake --build build --target keyword_docs`).
  const std::filesystem::path committed =
      std::filesystem::path(MCDYNA_SOURCE_DIR) / "manual/keywords";
  auto read = [](const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(d.path())) {
    ++files;
    const std::filesystem::path mine = committed / e.path().filename();
    const std::string stale =
        mine.string() + " is not what `mcdyna keywords --markdown` writes now";
    CHECK_MESSAGE(read(mine) == read(e.path()), stale);
  }
  int committed_files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(committed))
    ++committed_files;
  CHECK(committed_files == files);  // no page left over from a removed keyword
}

namespace mcdyna::test {

TEST_CASE("the shipped flow-drill-screw decks read clean") {
  for (const char* deck : {"decks/fds/fds_h0.3.k", "decks/fds/fds_h0.15.k"}) {
    const Run r = run_mcdyna(std::string("check -q ") + MCDYNA_SOURCE_DIR + "/" + deck);
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    CHECK_MESSAGE(r.output.find("0 errors, 0 warnings - ready to run") != std::string::npos,
                  r.output);
  }
}

}  // namespace mcdyna::test

TEST_CASE("progress: a refreshed line covers all of a longer one before it") {
  // "\r" returns to the start of the terminal line without clearing it: "ETA 16.2 ss" was the
  // end of "ETA 116.2 s" left standing.
  using mcdyna::cli::Progress;
  CHECK(Progress::refreshed("ETA 16.2 s", 11) == "\rETA 16.2 s ");
  CHECK(Progress::refreshed("ETA 116.2 s", 10) == "\rETA 116.2 s");
  CHECK(Progress::refreshed("x", 0) == "\rx");
}
