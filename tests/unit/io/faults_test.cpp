// Faults a hostile user or a bad day brings (issue 22): a full disk, an output schedule that
// cannot step, an output directory that cannot be one. Each stops with its own exit code and a
// message naming the file, leaves every file on disk whole and never crashes or hangs.
#include <sys/mount.h>

#include <fstream>

#include <unistd.h>

#include "io/output_lock.hpp"
#include "output_support.hpp"

namespace mcdyna::test {

namespace {

namespace fs = std::filesystem;

// The cube of decks/cube writing a state every 0.1 us and glstat at every cycle (500 states of
// 6-8 kB, 750 glstat blocks of 1 kB): enough to fill a small disk.
std::string chatty_cube() {
  std::string deck = source_text("decks/cube/cube_drop.k");
  deck = with(deck, "*DATABASE_BINARY_D3PLOT\n    1.0E-6", "*DATABASE_BINARY_D3PLOT\n    1.0E-7");
  return with(deck, "*DATABASE_GLSTAT\n    1.0E-7", "*DATABASE_GLSTAT\n    1.0E-9");
}

// What a run that lost its disk leaves: exit 6 naming a file, a collection that lists only
// states that read back, histories that end with whole rows.
void check_stopped_whole(const Run& r, const fs::path& out) {
  CHECK_MESSAGE(r.exit_code == 6, r.output);
  CHECK(r.output.find("error termination: cannot write " + out.string()) != std::string::npos);
  CHECK(r.output.find("normal termination") == std::string::npos);
  if (fs::exists(out / "d3plot.pvd"))
    for (const std::string& state : collection(out / "d3plot.pvd"))
      CHECK(read_vtu(out / state)->GetNumberOfPoints() == 27);
  for (const char* csv : {"glstat.csv", "matsum.csv", "rwforc.csv"})
    if (fs::exists(out / csv) && fs::file_size(out / csv) > 0) check_csv_whole(out / csv);
}

}  // namespace

TEST_CASE("a full disk stops the run with exit 6, the files on disk whole (file size limit)") {
  // RLIMIT_FSIZE with SIGXFSZ ignored makes every write past the limit fail with EFBIG, as a full
  // disk fails with ENOSPC, on any machine (dash's ulimit -f counts 512-byte blocks).
  TempDir dir;
  const fs::path deck = dir.write("cube.k", chatty_cube());
  for (const int blocks : {16, 200, 800}) {
    CAPTURE(blocks);
    const fs::path out = dir.path() / fmt::format("out{}", blocks);
    const Run r = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q",
                             fmt::format("trap '' XFSZ; ulimit -f {}; timeout 60", blocks));
    check_stopped_whole(r, out);
  }
}

TEST_CASE("a full disk stops the run with exit 6, the files on disk whole (small tmpfs)") {
  TempDir dir;
  const fs::path deck = dir.write("cube.k", chatty_cube());
  for (const char* size : {"1m", "200k", "64k"}) {
    CAPTURE(size);
    const fs::path disk = dir.path() / size;
    fs::create_directories(disk);
    if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, (std::string("size=") + size).c_str()) != 0) {
      MESSAGE("no tmpfs here (mount needs root): covered by the file-size-limit case");
      return;
    }
    struct Unmount {
      const fs::path& at;
      ~Unmount() { ::umount(at.c_str()); }
    } unmount{disk};
    const Run r = run_mcdyna("run " + deck.string() + " --out " + (disk / "out").string() + " -q",
                             "timeout 60");
    check_stopped_whole(r, disk / "out");
  }
}

TEST_CASE("output schedule: a step far longer than the output interval does not loop") {
  // DT2MS holds the step at 0.9 x 2e-6 s; the d3plot interval 1e-21 s is below the resolution of
  // t (next + interval == next), so stepping the next output time never ended. Now every cycle
  // writes one state.
  TempDir dir;
  std::string deck = source_text("decks/cube/cube_drop.k");
  deck =
      with(deck, "       0.0       0.9\n", "       0.0       0.9       0.0       0.0    2.0E-6\n");
  deck = with(deck, "*DATABASE_BINARY_D3PLOT\n    1.0E-6", "*DATABASE_BINARY_D3PLOT\n   1.0E-21");
  const fs::path path = dir.write("cube.k", deck);
  const Run r =
      run_mcdyna("run " + path.string() + " --out " + (dir.path() / "o").string(), "timeout 60");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("DT = 1e-21 asks for 5e+16 outputs over ENDTIM = 5e-05") !=
        std::string::npos);
  const std::string d3hsp = read_text(dir.path() / "o" / "d3hsp");
  const auto at = d3hsp.rfind(", cycle ");
  REQUIRE(at != std::string::npos);
  const long cycles = std::stol(d3hsp.substr(at + 8));
  CHECK(cycles > 20);
  CHECK(collection(dir.path() / "o" / "d3plot.pvd").size() == static_cast<std::size_t>(cycles) + 1);
}

TEST_CASE("DT2MS not shorter than ENDTIM is a deck error, one leaving few steps a warning") {
  std::string deck = source_text("decks/cube/cube_drop.k");
  for (const char* dt2ms : {"1.0E6", "1.0E30", "-5.0E-5"}) {
    CAPTURE(dt2ms);
    auto l = load_text(with(deck, "       0.0       0.9\n",
                            fmt::format("       0.0       0.9       0.0       0.0{:>10}\n", dt2ms)),
                       true);
    CHECK_MESSAGE(
        l->has_message("is not shorter than ENDTIM = 5e-05: the run would be a single step"),
        l->messages());
    CHECK(l->messages().find("main.k:19:") != std::string::npos);
  }
  auto w = load_text(
      with(deck, "       0.0       0.9\n", "       0.0       0.9       0.0       0.0    1.0E-6\n"),
      true);
  CHECK_FALSE(w->diags.has_errors());
  CHECK(w->has_message("leaves fewer than 100 steps to ENDTIM"));
}

TEST_CASE("--out that cannot be a directory is a usage error (exit 2) with the reason") {
  TempDir dir;
  const fs::path deck = dir.write("cube.k", source_text("decks/cube/cube_drop.k"));
  const fs::path file = dir.write("a_file", "x");
  fs::create_symlink("/nonexistent/dir", dir.path() / "dangling");
  const std::pair<std::string, std::string> cases[] = {
      {file.string(), "Not a directory"},
      {"/dev/null", "Not a directory"},
      {(dir.path() / "dangling").string(), "File exists"},
      {"/proc/mcdyna_out", "No such file or directory"},
      {(dir.path() / std::string(300, 'x')).string(), "File name too long"}};
  for (const auto& [out, reason] : cases) {
    CAPTURE(out);
    const Run r = run_mcdyna("run " + deck.string() + " --out " + out + " -q");
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.output.find("mcdyna: error: --out: cannot create the output directory") !=
                      std::string::npos,
                  r.output);
    CHECK(r.output.find(reason) != std::string::npos);
    CHECK(r.output.find("internal error") == std::string::npos);
  }
}

TEST_CASE("a second run into a directory another run is writing is refused with its process") {
  // Two runs in one --out directory interleave their histories and rename each other's restart
  // dumps away ("cannot rename into place"); the second is now a usage error instead.
  TempDir dir;
  const fs::path deck = dir.write("cube.k", source_text("decks/cube/cube_drop.k"));
  const fs::path out = dir.path() / "out";
  fs::create_directories(out);
  {
    const io::OutputLock first(out);  // this process stands for the run already writing there
    REQUIRE(first.problem().empty());
    const Run r = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q");
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.output.find(fmt::format("mcdyna: error: --out: another mcdyna run (process "
                                            "{}) is writing to {}",
                                            ::getpid(), out.string())) != std::string::npos,
                  r.output);
    CHECK_FALSE(fs::exists(out / "glstat"));
  }
  // The lock goes with its holder: the same run now goes ahead.
  const Run r = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q");
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  CHECK(fs::exists(out / "glstat"));
}

}  // namespace mcdyna::test
