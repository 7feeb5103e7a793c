// Restart dumps (*DATABASE_BINARY_D3DUMP / RUNRSF, the running restart file of an interrupted run,
// `--restart` and r=): a run continued from a dump writes the same bits as one that never
// stopped, whatever the thread count, and a dump that does not belong to the deck is refused
// with a message.
#include <sys/stat.h>

#include <cstring>
#include <sstream>

#include "cli/restart_dump.hpp"
#include "cli/run_command.hpp"
#include "core/binary_archive.hpp"
#include "solver/run/restart.hpp"

#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

namespace fs = std::filesystem;

// glstat prints the wall time per zone cycle, which no two runs share; everything else in it
// is physics.
std::string without_timing(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (line.find("time per zone cycle") == std::string::npos) out += line + "\n";
  return out;
}

// Every output of `a` (VTK states and collection, ASCII histories, CSV) has a byte-identical
// twin in `b`; d3hsp (a log with timings), the dumps themselves (they carry wall times) and the
// run's lock (its process id, io/output_lock.hpp) aside.
void check_same_outputs(const fs::path& a, const fs::path& b) {
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    const std::string name = entry.path().filename().string();
    if (name == "d3hsp" || name == ".mcdyna.lock" || name.rfind("d3dump", 0) == 0 ||
        name.rfind("runrsf", 0) == 0)
      continue;
    REQUIRE_MESSAGE(fs::exists(b / name), name << " missing after the restart");
    std::string ta = read_text(entry.path()), tb = read_text(b / name);
    if (name == "glstat") {
      ta = without_timing(ta);
      tb = without_timing(tb);
    }
    CHECK_MESSAGE(ta == tb, name << " differs after the restart");
    ++compared;
  }
  CHECK(compared >= 5);
}

// The committed FDS demo cut to `cycles` cycles with `extra` keywords before *PART: a rigid
// screw driven by prescribed motion, penalty contact with friction, MC-SPG with bond failure
// and kernel renewals, an FE ring, JC + Gruneisen.
fs::path fds_deck(const TempDir& dir, int cycles, const std::string& extra) {
  std::string deck = source_text("decks/fds/fds_h0.3.k");
  deck = with(deck, "*CONTROL_TERMINATION\n1.2137E-03",
              "*CONTROL_TERMINATION\n1.2137E-03" + fmt::format("{:10d}", cycles));
  deck = with(deck, "*DATABASE_BINARY_D3PLOT\n1.2138E-05", "*DATABASE_BINARY_D3PLOT\n2.0E-06");
  deck = with(deck, "\n*PART\n", "\n" + extra + "*PART\n");
  return dir.write("fds.k", deck);
}

// Where each section of a dump lies (cli/restart_dump.cpp: after the 24-byte prologue, each
// section is its name as length + text, its payload size, its checksum, then the payload).
struct DumpSection {
  std::string name;
  std::size_t header = 0, payload = 0, size = 0;
};
std::vector<DumpSection> dump_sections(const std::string& bytes) {
  std::vector<DumpSection> out;
  std::size_t at = 24;
  auto word = [&](std::size_t offset) {
    std::uint64_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 8);
    return static_cast<std::size_t>(v);
  };
  while (at + 8 <= bytes.size()) {
    DumpSection sec;
    sec.header = at;
    const std::size_t length = word(at);
    sec.name = bytes.substr(at + 8, length);
    sec.size = word(at + 8 + length);
    sec.payload = at + 8 + length + 16;
    at = sec.payload + sec.size;
    out.push_back(sec);
  }
  return out;
}

std::string run_args(const fs::path& deck, const fs::path& out, const std::string& more = "") {
  return "run " + deck.string() + " --out " + out.string() + " -q " + more;
}

}  // namespace

TEST_CASE(
    "restart: the FDS scene continued from a d3dump is bit for bit the run that never stopped") {
  TempDir dir;
  const fs::path deck = fds_deck(dir, 300, "*DATABASE_BINARY_D3DUMP\n       150\n");
  const fs::path a = dir.path() / "a", b = dir.path() / "b";
  const Run straight = run_mcdyna(run_args(deck, a, "--threads 2"));
  REQUIRE_MESSAGE(straight.exit_code == 0, straight.output);
  REQUIRE(fs::exists(a / "d3dump01"));
  CHECK_FALSE(fs::exists(a / "d3dump02"));  // none at the end of the run (cycle 300)

  // Continue a copy from the first dump, on one thread.
  fs::copy(a, b);
  const Run resumed =
      run_mcdyna(run_args(deck, b, "--threads 1 --restart " + (b / "d3dump01").string()));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.output);
  check_same_outputs(a, b);
  CHECK(read_text(b / "d3hsp").find("Restart from") != std::string::npos);
  // The contact and the particles were working when the dump was taken.
  CHECK(read_text(a / "rcforc.csv").size() > 1000);
}

namespace {

// The eroding bar (solver_support.hpp) with histories; its elements erode between cycles 7 and
// 13: erosion, constraints and nodal motion in one deck. TSSFAC 0.02 gives it ~250 cycles.
std::string eroding_bar_run(const std::string& extra) {
  return eroding_bar(
      "*CONTROL_TERMINATION\n0.2\n*CONTROL_TIMESTEP\n0.0,0.02\n*DATABASE_BINARY_D3PLOT\n0.02\n"
      "*DATABASE_GLSTAT\n0.005\n*DATABASE_BNDOUT\n0.005\n*DATABASE_SPCFORC\n0.005\n"
      "*DATABASE_MATSUM\n0.005\n" +
      extra);
}

// The cycle and time of the last dump into `file`, from its d3hsp line.
struct DumpLine {
  long cycle = -1;
  double time = -1.0;
};
DumpLine dump_line(const fs::path& out, const std::string& file) {
  const std::string log = read_text(out / "d3hsp");
  const std::string key = (out / file).string() + " written at t = ";
  DumpLine d;
  for (auto at = log.find(key); at != std::string::npos; at = log.find(key, at + 1)) {
    d.time = std::stod(log.substr(at + key.size()));
    d.cycle = std::stol(log.substr(log.find("cycle ", at) + 6));
  }
  return d;
}

// glstat.csv's eroded internal energy (column 9) at the last row at or before `time`, and at
// the end.
std::pair<double, double> eroded_energy(const fs::path& out, double time) {
  std::istringstream in(read_text(out / "glstat.csv"));
  std::string line;
  std::getline(in, line);  // header
  double before = 0.0, last = 0.0;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');)
      v.push_back(std::stod(f));
    REQUIRE(v.size() > 8);
    if (v[0] <= time) before = v[8];
    last = v[8];
  }
  return {before, last};
}

// A 2 x 2 x 2 elastic block on its base, its top given a small velocity: rings and settles
// (the hourglass viscosity takes the energy), stable for as long as one likes; 3 us a cycle.
std::string ringing_block(long cycles) {
  std::string top;
  for (int id : {19, 20, 21, 22, 23, 24, 25, 26, 27})
    top += fmt::format("{},0.0,0.0,0.01\n", id);
  std::string base;
  for (int id = 1; id <= 9; ++id)
    base += fmt::format("{},0,1,1,1,0,0,0\n", id);
  return fmt::format("*KEYWORD\n*CONTROL_TERMINATION\n1.0e9,{}\n", cycles) +
         "*DATABASE_BINARY_D3PLOT\n5000.0\n*DATABASE_GLSTAT\n1000.0\n*DATABASE_SPCFORC\n1000.0\n"
         "*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,100.0,0.3\n" +
         box_mesh(2, 2, 2, 1.0) + "*BOUNDARY_SPC_NODE\n" + base + "*INITIAL_VELOCITY_NODE\n" + top +
         "*END\n";
}

}  // namespace

TEST_CASE(
    "restart: RUNRSF with NR 2 writes runrsf01 / runrsf02 in turn, an eroding bar continues "
    "exactly") {
  TempDir dir;
  const fs::path deck =
      dir.write("bar.k", eroding_bar_run("*DATABASE_BINARY_RUNRSF\n        40         2\n"
                                         "*DATABASE_BINARY_D3DUMP\n         5\n"));
  const fs::path a = dir.path() / "a", b = dir.path() / "b";
  const Run straight = run_mcdyna(run_args(deck, a));
  REQUIRE_MESSAGE(straight.exit_code == 0, straight.output);
  REQUIRE(fs::exists(a / "runrsf01"));
  REQUIRE(fs::exists(a / "runrsf02"));
  CHECK_FALSE(fs::exists(a / "runrsf"));
  const long c1 = dump_line(a, "runrsf01").cycle, c2 = dump_line(a, "runrsf02").cycle;
  MESSAGE("runrsf01 at cycle ", c1, ", runrsf02 at cycle ", c2);
  CHECK(c1 % 40 == 0);
  CHECK(c2 % 40 == 0);
  CHECK(std::abs(c1 - c2) == 40);  // the last two dumps, one in each file
  // From d3dump01 (cycle 5): the elements erode after it, in the continued run.
  const DumpLine first = dump_line(a, "d3dump01");
  CHECK(first.cycle == 5);
  const auto [before, end] = eroded_energy(a, first.time);
  CHECK(before == 0.0);
  CHECK(end > 0.0);
  fs::copy(a, b);
  const Run resumed = run_mcdyna(run_args(deck, b, "--restart " + (b / "d3dump01").string()));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.output);
  check_same_outputs(a, b);
  // The run summary's inertia figures cover the continuation only, and say from when.
  const std::string log = read_text(b / "d3hsp");
  const std::size_t restart = log.rfind("Restart from");
  REQUIRE(restart != std::string::npos);
  const std::string said = "a restarted run: the figures below are over its outputs from t = ";
  const std::size_t at = log.find(said, restart);
  REQUIRE_MESSAGE(at != std::string::npos, log.substr(restart));
  // Its first output after the dump (cycle 5): no earlier than the dump's time.
  CHECK(std::stod(log.substr(at + said.size())) >= first.time * (1.0 - 1e-4));
  CHECK(read_text(a / "d3hsp").find("a restarted run") == std::string::npos);
}

TEST_CASE(
    "restart: an interrupted run leaves runrsf and says how to continue, the continued run "
    "ends as if never stopped") {
  TempDir dir;
  // ~1 s of cycles (10 s under the sanitizers): the signal, sent once the time loop has
  // started (d3hsp has its "Time-step history" heading, flushed before the loop), lands mid-run
  // however slow the start-up.
  const fs::path deck = dir.write("block.k", ringing_block(300000));
  const fs::path a = dir.path() / "a", b = dir.path() / "b";
  const std::string log = (b / "d3hsp").string();
  const Run stopped = run_shell(std::string(MCDYNA_BINARY) + " " + run_args(deck, b) +
                                " & pid=$!; until grep -q \"Time-step history\" " + log +
                                " 2>/dev/null; do sleep 0.02; done; sleep 0.1; kill -INT $pid; "
                                "wait $pid");
  REQUIRE_MESSAGE(stopped.exit_code == 5, stopped.output);
  REQUIRE(fs::exists(b / "runrsf"));
  CHECK_MESSAGE(
      stopped.output.find("continue with: mcdyna run " + deck.string() + " --out " + b.string() +
                          " --restart " + (b / "runrsf").string()) != std::string::npos,
      stopped.output);
  const Run resumed = run_mcdyna(run_args(deck, b, "--restart " + (b / "runrsf").string()));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.output);
  const Run straight = run_mcdyna(run_args(deck, a));
  REQUIRE_MESSAGE(straight.exit_code == 0, straight.output);
  check_same_outputs(a, b);
}

TEST_CASE(
    "restart: a dump of another deck, options, format or build, a truncated dump or another file "
    "are refused") {
  TempDir dir;
  const fs::path deck =
      dir.write("bar.k", eroding_bar_run("*DATABASE_BINARY_D3DUMP\n        40\n"));
  const fs::path out = dir.path() / "out";
  REQUIRE(run_mcdyna(run_args(deck, out)).exit_code == 0);
  REQUIRE(fs::exists(out / "d3dump01"));

  // The same deck with another end time: the fingerprint differs.
  const fs::path other = dir.write(
      "other.k", with(read_text(deck), "*CONTROL_TERMINATION\n0.2", "*CONTROL_TERMINATION\n0.3"));
  Run r =
      run_mcdyna(run_args(other, dir.path() / "o1", "--restart " + (out / "d3dump01").string()));
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(r.output.find("written from another deck") != std::string::npos, r.output);
  // Other physics options than the run that wrote it.
  r = run_mcdyna(run_args(deck, dir.path() / "o2",
                          "--spg-stabilization none --restart " + (out / "d3dump01").string()));
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("other --spg-* options") != std::string::npos);

  // Cut in half.
  const std::string bytes = read_text(out / "d3dump01");
  dir.write("half", bytes.substr(0, bytes.size() / 2));
  r = run_mcdyna(run_args(deck, dir.path() / "o3", "--restart " + (dir.path() / "half").string()));
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(r.output.find("ends early (truncated file?)") != std::string::npos, r.output);
  // Another format version, and another build's solver state: the dump opens with 20 bytes of
  // magic and the 4-byte version, then the header section (its name, size and checksum, then
  // the length and text of the struct-size list). Another build writes a valid checksum.
  std::string other_version = bytes;
  other_version[20] = 99;
  dir.write("version", other_version);
  r = run_mcdyna(
      run_args(deck, dir.path() / "o6", "--restart " + (dir.path() / "version").string()));
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(r.output.find("dump format 99") != std::string::npos, r.output);
  const std::vector<DumpSection> sections = dump_sections(bytes);
  REQUIRE(sections.front().name == "header");
  std::string other_build = bytes;
  const std::size_t layout_text = sections.front().payload + 8;
  REQUIRE(other_build[layout_text] >= '1');
  REQUIRE(other_build[layout_text] <= '9');
  other_build[layout_text] = other_build[layout_text] == '9' ? '1' : '9';
  const std::uint64_t sum = core::checksum(
      std::string_view(other_build).substr(sections.front().payload, sections.front().size));
  std::memcpy(other_build.data() + sections.front().payload - 8, &sum, 8);
  dir.write("build", other_build);
  r = run_mcdyna(run_args(deck, dir.path() / "o7", "--restart " + (dir.path() / "build").string()));
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(
      r.output.find("written by an mcdyna build whose solver state differs") != std::string::npos,
      r.output);
  // Not a dump at all.
  r = run_mcdyna(run_args(deck, dir.path() / "o4", "--restart " + deck.string()));
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("not an mcdyna restart dump") != std::string::npos);
  // Missing; and LS-DYNA's r= without i=.
  r = run_mcdyna(run_args(deck, dir.path() / "o5", "--restart " + (dir.path() / "none").string()));
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("cannot read the restart dump") != std::string::npos);
  r = run_mcdyna("r=" + (out / "d3dump01").string());
  CHECK(r.exit_code != 0);
  CHECK(r.output.find("r=DUMP needs i=DECK too") != std::string::npos);
}

TEST_CASE("restart: a flipped bit in any section of a dump is refused, naming the section") {
  TempDir dir;
  const std::string text = eroding_bar_run("*DATABASE_BINARY_D3DUMP\n        40\n");
  const fs::path deck = dir.write("bar.k", text);
  const fs::path out = dir.path() / "out";
  REQUIRE(run_mcdyna(run_args(deck, out)).exit_code == 0);
  const std::string bytes = read_text(out / "d3dump01");
  const std::vector<DumpSection> sections = dump_sections(bytes);
  // The header and the resume point, the state's sections (the nodes, each block with a state,
  // the clock), the outputs and the end.
  std::vector<std::string> names;
  for (const DumpSection& sec : sections)
    names.push_back(sec.name);
  CHECK(names == std::vector<std::string>{"header", "resume point", "nodes", "hexahedra",
                                          "nodal constraints", "prescribed nodal motions",
                                          "time and energies", "outputs", "end of dump"});
  CHECK(sections.back().name == "end of dump");
  CHECK(sections.back().payload == bytes.size());

  // Read in this process (as `run --restart` does) over the state compiled from the same deck.
  Simulation sim = prepare(dir, read_text(deck));
  const std::string print = cli::run_fingerprint(sim.loaded->deck.files, cli::RunOptions{});
  const fs::path damaged = dir.path() / "damaged";
  auto refusal = [&](std::size_t offset, int bit) -> std::string {
    std::string b = bytes;
    b[offset] = static_cast<char>(b[offset] ^ (1 << bit));
    dir.write("damaged", b);
    try {
      cli::read_dump(damaged, print, *sim.state);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "accepted";
  };
  REQUIRE(refusal(0, 0).find("not an mcdyna restart dump") != std::string::npos);
  int refused = 0;
  for (const DumpSection& sec : sections) {
    CAPTURE(sec.name);
    // The section's bytes: first, middle and last byte, low and high bits.
    for (const std::size_t at :
         {sec.payload, sec.payload + sec.size / 2, sec.payload + sec.size - 1}) {
      if (sec.size == 0) break;
      for (const int bit : {0, 7}) {
        const std::string m = refusal(at, bit);
        CHECK_MESSAGE(m.find("section '" + sec.name + "' is damaged") != std::string::npos, m);
        ++refused;
      }
    }
    // Its name, size and checksum: refused too (the message may name the next section).
    for (const std::size_t at :
         {sec.header + 8, sec.payload - 16, sec.payload - 9, sec.payload - 1}) {
      const std::string m = refusal(at, 6);
      CHECK_MESSAGE(m != "accepted", at);
      CHECK(m.find("restart dump") != std::string::npos);
      ++refused;
    }
  }
  MESSAGE(refused, " damaged copies refused, in ", sections.size(), " sections");
  // Bytes after the end, and the whole process on one damaged copy: exit 1 with the message.
  dir.write("longer", bytes + "x");
  CHECK_THROWS_WITH_AS(cli::read_dump(dir.path() / "longer", print, *sim.state),
                       doctest::Contains("1 bytes after its end"), std::runtime_error);
  std::string b = bytes;
  b[sections[4].payload + sections[4].size / 2] ^= 0x10;
  dir.write("damaged", b);
  const Run r = run_mcdyna(run_args(deck, dir.path() / "o1", "--restart " + damaged.string()));
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(r.output.find("section '" + sections[4].name + "' is damaged") != std::string::npos,
                r.output);
}

TEST_CASE("restart: --restart on a FIFO or a directory is refused at once, not read") {
  TempDir dir;
  const fs::path deck = dir.write("bar.k", eroding_bar_run(""));
  const fs::path fifo = dir.path() / "fifo";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  // A read of a FIFO blocks until a writer comes; the timeout turns a block into exit 124.
  Run r = run_mcdyna(run_args(deck, dir.path() / "o1", "--restart " + fifo.string()), "timeout 20");
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(r.output.find("not a regular file") != std::string::npos, r.output);
  r = run_mcdyna(run_args(deck, dir.path() / "o2", "--restart " + dir.path().string()),
                 "timeout 20");
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("not a regular file") != std::string::npos);
}

TEST_CASE("restart: LS-DYNA's i= r= continues in the working directory") {
  TempDir dir;
  dir.write("bar.k", eroding_bar_run("*DATABASE_BINARY_D3DUMP\n        40\n"));
  const std::string cd = "cd " + dir.path().string() + " &&";
  REQUIRE(run_mcdyna("i=bar.k", cd).exit_code == 0);
  const std::string glstat = read_text(dir.path() / "glstat.csv");
  const Run r = run_mcdyna("i=bar.k r=d3dump01", cd);
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(read_text(dir.path() / "glstat.csv") == glstat);
  CHECK(read_text(dir.path() / "d3hsp").find("Restart from d3dump01") != std::string::npos);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("sense switches in the time loop: each acts at the cycle it is read") {
  // The loop polls the switches at the top of every cycle; here sw2, sw4, sw3 and sw1 come at
  // cycles 3, 7, 11 and 15 of the eroding bar (28 cycles), and the hooks record what the loop
  // did.
  TempDir dir;
  Simulation sim = prepare(dir, eroding_bar("*CONTROL_TERMINATION\n1.0\n"));
  solver::RunHooks hooks;
  std::vector<long> status_at, state_at, written_at, dumps_at, requested_at;
  hooks.sense_switches = [&] {
    solver::SenseSwitches sw;
    const long c = sim.state->cycle;
    sw.status = c == 3;
    sw.state = c == 7;
    sw.dump = c == 11;
    sw.stop = c == 15;
    return sw;
  };
  hooks.status = [&](const solver::State& s) { status_at.push_back(s.cycle); };
  hooks.request_state = [&] { state_at.push_back(sim.state->cycle); };
  hooks.output_due = [](const solver::State&) { return false; };  // no scheduled outputs
  hooks.write = [&](const solver::State& s, const Eigen::Matrix3Xd&, bool) {
    written_at.push_back(s.cycle);
  };
  hooks.dump_due = [&](const solver::State& s, bool interrupted, bool requested) {
    if (requested) requested_at.push_back(s.cycle);
    return requested || interrupted;
  };
  hooks.dump = [&](const solver::State& s, const solver::ResumePoint&) {
    dumps_at.push_back(s.cycle);
  };
  run(sim, hooks);
  CHECK(sim.result.reason == solver::StopReason::interrupted);
  CHECK(sim.state->cycle == 15);
  CHECK(status_at == std::vector<long>{3});
  CHECK(state_at == std::vector<long>{7});
  CHECK(written_at == std::vector<long>{7, 15});  // sw4's state, then the final one at sw1
  CHECK(requested_at == std::vector<long>{11, 15});
  CHECK(dumps_at == std::vector<long>{11, 15});
}

}  // namespace mcdyna::test
