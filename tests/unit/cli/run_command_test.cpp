// `mcdyna run` as users run it: LS-DYNA style i=, the output files (read back with VTK's own
// reader), the exit codes of an unstable and of an interrupted run.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/sense_switch.hpp"
#include "core/communicator.hpp"
#include "io/history_table.hpp"
#include "output_support.hpp"
#include "post/history_compare.hpp"
#include "solver/solids/solids.hpp"

namespace mcdyna::test {

namespace {

// Our ASCII file and CSV of one kind, read back by `mcdyna compare`'s readers, give the same
// columns and the same curves to the digits the ASCII layout prints: `tolerance` is max|A-B| /
// peak|B| from those digits (values and times in %12.5E: ~1e-5; %13.4E: ~1e-4; bndout's t=%9.3E
// moves the time by up to 5e-4 relative).
void check_ascii_matches_csv(const std::filesystem::path& out, const std::string& name,
                             double tolerance, std::size_t min_columns) {
  const io::HistoryTable ascii = io::read_history(out / name);
  const io::HistoryTable csv = io::read_history(out / (name + ".csv"));
  CHECK(ascii.format == name);
  CHECK(ascii.rows() == csv.rows());
  const post::Comparison c = post::compare_histories(csv, ascii, {});
  CHECK_MESSAGE(c.columns.size() >= min_columns, name << ": " << c.columns.size() << " columns");
  for (const post::ColumnComparison& col : c.columns)
    CHECK_MESSAGE(col.relative_to_peak <= tolerance,
                  name << " " << col.name_a << ": " << col.relative_to_peak);
}

// A CSV history as rows of named fields (numbers; text fields such as `kind` as NaN, kept raw
// in `text`).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<std::string>> text;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE_MESSAGE(it != header.end(), "no column " << name);
    return static_cast<std::size_t>(it - header.begin());
  }
};

CsvTable read_csv(const std::filesystem::path& p) {
  CsvTable t;
  std::ifstream in(p);
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t c = l.find(','); c != std::string::npos; c = l.find(',', start = c + 1))
      out.push_back(l.substr(start, c - start));
    out.push_back(l.substr(start));
    return out;
  };
  REQUIRE(std::getline(in, line));
  t.header = split(line);
  while (std::getline(in, line)) {
    t.text.push_back(split(line));
    std::vector<double> row;
    for (const std::string& f : t.text.back()) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      row.push_back(end != f.c_str() && *end == '\0' ? v : std::nan(""));
    }
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace

TEST_CASE("threads wait passively unless the user chose a policy, and d3hsp says which") {
  // Spinning waits made 2 threads slower than 1 on a busy machine (cli/wait_policy.hpp).
  TempDir dir;
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k";
  auto policy_line = [&](const std::string& env, const std::string& out) {
    const Run r =
        run_mcdyna("run " + deck + " --threads 2 -q --out " + (dir.path() / out).string(), env);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string log = read_text(dir.path() / out / "d3hsp");
    const std::size_t at = log.find("threads: ");
    REQUIRE(at != std::string::npos);
    return log.substr(at, log.find('\n', at) - at);
  };
  CHECK(policy_line("env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT", "default") ==
        "threads: 2, OpenMP wait policy PASSIVE (OMP_WAIT_POLICY)");
  CHECK(policy_line("env -u GOMP_SPINCOUNT OMP_WAIT_POLICY=ACTIVE", "active") ==
        "threads: 2, OpenMP wait policy ACTIVE (OMP_WAIT_POLICY)");
  CHECK(policy_line("env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=1000", "spin") ==
        "threads: 2, OpenMP wait policy libgomp's default (spin, then sleep), GOMP_SPINCOUNT=1000");
}

TEST_CASE("an FDS deck as engineers write it checks clean and runs, all its contacts loaded") {
  // tests/data/fds_user_style (tools/decks/fds_user_style.py): *PARAMETER(_EXPRESSION),
  // *INCLUDE meshes, *CONTROL_ACCURACY OSU 1 INN 4, *CONTROL_MPP_DECOMPOSITION_PARTS_DISTRIBUTE,
  // a rigid screw of hexahedra, two stacked sheets (MC-SPG on FE) with a contact between them
  // and a rigid hold-down ring of shells.
  TempDir dir;
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/tests/data/fds_user_style/main.k";
  const Run check = run_mcdyna("check " + deck);
  CHECK_MESSAGE(check.exit_code == 0, check.output);
  CHECK(check.output.find("0 unsupported\n") != std::string::npos);
  CHECK(check.output.find("ready to run") != std::string::npos);
  const Run r = run_mcdyna("run " + deck + " -q --threads 2 --out " + dir.path().string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const std::string log = read_text(dir.path() / "d3hsp");
  CHECK(log.find("normal termination") != std::string::npos);
  CHECK(log.find("INN 4 (invariant node numbering) has no effect") != std::string::npos);
  // The FE sheet and the SPG sheet both take the objective update.
  std::size_t osu = 0;
  for (std::size_t at = log.find("(OSU 1)"); at != std::string::npos;
       at = log.find("(OSU 1)", at + 1))
    ++osu;
  CHECK(osu == 2);
  // The last rcforc row of each contact's slave side: screw on sheets, sheet on sheet, ring on
  // the top sheet all carry force (measured 18.6, 22.4 and 2.9 N in z).
  std::map<int, double> last_z;
  std::istringstream csv(read_text(dir.path() / "rcforc.csv"));
  std::string line;
  std::getline(csv, line);  // time,contact,side,x_force,y_force,z_force,...
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream row(line);
    for (std::string v; std::getline(row, v, ',');)
      f.push_back(v);
    if (f.size() > 5 && f[2] == "slave") last_z[std::stoi(f[1])] = std::stod(f[5]);
  }
  REQUIRE(last_z.size() == 3);
  for (const auto& [contact, fz] : last_z) {
    CAPTURE(contact);
    CHECK(std::abs(fz) > 0.1);
  }
}

TEST_CASE("LS-DYNA habit: mcdyna i=deck.k ncpu=2 runs the deck in the working directory") {
  TempDir dir;
  std::filesystem::copy_file(std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k",
                             dir.path() / "cube_drop.k");
  const Run r = run_mcdyna("i=cube_drop.k ncpu=2 memory=200m", "cd " + dir.path().string() + " &&");
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("normal termination") != std::string::npos);
  CHECK(r.output.find("Timing per phase") != std::string::npos);
  for (const char* f : {"d3hsp", "glstat", "glstat.csv", "d3plot.pvd"})
    CHECK_MESSAGE(std::filesystem::exists(dir.path() / f), f);
  CHECK(read_text(dir.path() / "d3hsp").find("2 thread") != std::string::npos);
  const auto states = collection(dir.path() / "d3plot.pvd");
  CHECK(states.size() == 51);  // t = 0, 1 us, ..., 50 us
  const auto first = read_vtu(dir.path() / states.front());
  const auto last = read_vtu(dir.path() / states.back());
  CHECK(last->GetNumberOfCells() == 8);
  CHECK(last->GetNumberOfPoints() == 27);
  REQUIRE(last->GetCellData()->GetArray("stress") != nullptr);
  // spg_state is -1 on FE cells (0-3 on SPG particles: smoothed, pinned, isolated, debris).
  vtkDataArray* spg_state = last->GetCellData()->GetArray("spg_state");
  REQUIRE(spg_state != nullptr);
  CHECK(spg_state->GetRange()[0] == -1.0);
  CHECK(spg_state->GetRange()[1] == -1.0);
  CHECK(last->GetCellData()->GetArray("stress")->GetNumberOfComponents() == 6);
  for (const char* a :
       {"von_mises", "effective_plastic_strain", "temperature", "part_id", "erosion_state"})
    CHECK_MESSAGE(last->GetCellData()->GetArray(a) != nullptr, a);
  // At t = 0 the cube moves at -10 m/s (-1e4 mm/s); at 50 us it has hit the wall (bottom at
  // z = 0.1 mm, reached at 10 us) and bounced back up.
  CHECK(first->GetPointData()->GetArray("velocity")->GetComponent(26, 2) ==
        doctest::Approx(-1.0e4).epsilon(1e-9));
  CHECK(last->GetPointData()->GetArray("velocity")->GetComponent(26, 2) > 0.0);
  check_csv_whole(dir.path() / "rwforc.csv");
  check_csv_whole(dir.path() / "glstat.csv");
  const std::string glstat = read_text(dir.path() / "glstat");
  CHECK(glstat.find(" kinetic energy.................") != std::string::npos);
  CHECK(glstat.find(" total energy / initial energy..") != std::string::npos);
}

// mpirun -np 2 before the decomposition over processes is in: one clear error from rank 0, no
// outputs, instead of two runs writing the same files (the second used to stop on the output
// lock, with a message about "another mcdyna run"). The launcher's environment is set by hand:
// the test does not need Open MPI.
// A build with MPI runs over several processes (tests/mpi, under a real mpiexec); a build without
// refuses, once, and writes nothing. The launcher's environment is all it can tell from.
TEST_CASE("started by mpirun over several processes without MPI built in: one clear error") {
  TempDir dir;
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k";
  const std::string out = (dir.path() / "out").string();
  if (!core::Communicator::built_with_mpi()) {
    const Run rank0 = run_mcdyna("run " + deck + " --out " + out,
                                 "OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0");
    CHECK(rank0.exit_code == 2);
    CHECK_MESSAGE(rank0.output.find("started as 2 processes (mpirun -np 2), but this build has "
                                    "no MPI") != std::string::npos,
                  rank0.output);
    const Run rank1 = run_mcdyna("run " + deck + " --out " + out, "PMI_SIZE=2 PMI_RANK=1");
    CHECK(rank1.exit_code == 2);
    CHECK_MESSAGE(rank1.output.find("error") == std::string::npos, rank1.output);
    CHECK_FALSE(std::filesystem::exists(dir.path() / "out" / "d3hsp"));
  }
  // One process under a launcher runs as without it, in either build.
  const Run single = run_mcdyna("run " + deck + " --out " + out + " -q",
                                "OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0");
  CHECK_MESSAGE(single.exit_code == 0, single.output);
}

TEST_CASE("LCDT and LCUR: output intervals from curves, every cycle where the curve is 0") {
  TempDir dir;
  std::string deck = read_text(std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = deck.find(from);
    REQUIRE(at != std::string::npos);
    deck.replace(at, from.size(), to);
  };
  // d3plot every 10 us, then every 2 us from 30 us; glstat every 10 us, then every cycle.
  replace("*DATABASE_BINARY_D3PLOT\n    1.0E-6\n",
          "*DATABASE_BINARY_D3PLOT\n    1.0E-6        99\n*DEFINE_CURVE\n99\n0.0, 1.0E-5\n"
          "2.99E-5, 1.0E-5\n3.0E-5, 2.0E-6\n1.0, 2.0E-6\n");
  replace("*DATABASE_GLSTAT\n    1.0E-7\n",
          "*DATABASE_GLSTAT\n    1.0E-7         1        98\n*DEFINE_CURVE\n98\n0.0, 1.0E-5\n"
          "3.99E-5, 1.0E-5\n4.0E-5, 0.0\n1.0, 0.0\n");
  const auto path = dir.write("curves.k", deck);
  const Run r = run_mcdyna("run " + path.string() + " --out " + (dir.path() / "out").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  // States at the first cycle at or past each output time: 0, 10, 20, 30 us, then 32 ... 50 us
  // (each a step of ~0.067 us late at most), and the last state.
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  CHECK(states.size() == 14);
  const CsvTable gl = read_csv(dir.path() / "out" / "glstat.csv");
  const std::size_t time = gl.column("time"), step = gl.column("time_step");
  REQUIRE(gl.rows.size() > 6);
  CHECK(gl.rows[1][time] == doctest::Approx(1.0e-5).epsilon(0.01));
  CHECK(gl.rows[4][time] == doctest::Approx(4.0e-5).epsilon(0.01));
  // From 40 us on, one row per cycle: consecutive times differ by the row's step.
  for (std::size_t k = 6; k < gl.rows.size(); ++k)
    CHECK(gl.rows[k][time] - gl.rows[k - 1][time] ==
          doctest::Approx(gl.rows[k][step]).epsilon(1e-6));
  CHECK(gl.rows.size() > 100);  // ~10 us of 0.067 us steps
}

TEST_CASE("d3plot shows where DT2MS scaled: node mass, added mass, each particle's step") {
  TempDir dir;
  // A 4^3 elastic MC-SPG block (rho 1, E 100: c ~ 10, steps ~ 0.05) with a DT2MS target of
  // 0.2 that every particle is below, so every row is scaled.
  const auto deck = dir.write(
      "scaled.k",
      "*KEYWORD\n*CONTROL_TERMINATION\n1.0e9,20\n*CONTROL_TIMESTEP\n0.0,0.9,0,0.0,-0.2\n"
      "*DATABASE_BINARY_D3PLOT\n100.0\n*DATABASE_GLSTAT\n100.0\n*PART\nspg\n1,1,1\n"
      "*SECTION_SOLID_SPG\n1,47\n1.5,1.5,1.5,0,0,,15,0.0\n1,1.0E+11,1.0E+10,3,1.0,0,0,-0.001\n"
      "*MAT_ELASTIC\n1,1.0,100.0,0.3\n" +
          box_mesh(4, 4, 4, 1.0) + "*END\n");
  const Run r = run_mcdyna("run " + deck.string() + " --out " + (dir.path() / "out").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(states.size() == 2);  // t = 0 and the end at cycle 20
  const auto last = read_vtu(dir.path() / "out" / states.back());
  vtkDataArray* mass = last->GetPointData()->GetArray("mass");
  vtkDataArray* added = last->GetPointData()->GetArray("added_mass");
  vtkDataArray* step = last->GetCellData()->GetArray("time_step");
  REQUIRE(mass != nullptr);
  REQUIRE(added != nullptr);
  REQUIRE(step != nullptr);
  double total = 0.0, total_added = 0.0;
  for (vtkIdType n = 0; n < last->GetNumberOfPoints(); ++n) {
    total += mass->GetComponent(n, 0);
    total_added += added->GetComponent(n, 0);
  }
  // The smoothed masses sum to the lumped ones (partition of unity, Eq. 20), added mass included.
  const CsvTable gl = read_csv(dir.path() / "out" / "glstat.csv");
  const double reported = gl.rows.back()[gl.column("added_mass")];
  CHECK(reported > 0.0);
  CHECK(total_added == doctest::Approx(reported).epsilon(1e-5));
  CHECK(total == doctest::Approx(64.0 + reported).epsilon(1e-5));
  // Every particle is at the target step |DT2MS| (the mass it was given brings it there).
  REQUIRE(last->GetNumberOfCells() == 125);
  for (vtkIdType c = 0; c < last->GetNumberOfCells(); ++c)
    CHECK(step->GetComponent(c, 0) >= 0.2 * (1.0 - 1e-5));
}

TEST_CASE("an unstable run exits 4, names the element and leaves readable outputs") {
  TempDir dir;
  const auto deck =
      dir.write("crush.k",
                "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*DATABASE_BINARY_D3PLOT\n       0.1\n"
                "*DATABASE_GLSTAT\n      0.01\n*PART\ncube\n         7         1         1\n"
                "*SECTION_SOLID\n         1         1\n*MAT_ELASTIC\n         1       1.0     "
                "100.0       0.3\n" +
                    box_mesh(1, 1, 1, 1.0, 1, 42, 7) +
                    "*INITIAL_VELOCITY_NODE\n       8       0.0       0.0    -500.0\n*END\n");
  const Run r = run_mcdyna("run " + deck.string() + " --out " + (dir.path() / "out").string());
  CHECK(r.exit_code == 4);
  CHECK(r.output.find("negative volume in solid element 42 (part 7) at t = ") != std::string::npos);
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(!states.empty());
  for (const auto& s : states)
    CHECK(read_vtu(dir.path() / "out" / s)->GetNumberOfPoints() == 8);
  check_csv_whole(dir.path() / "out" / "glstat.csv");
}

TEST_CASE("SIGINT stops the run with exit 5, a final state and whole files") {
  TempDir dir;
  std::string deck =
      read_text(std::string(MCDYNA_SOURCE_DIR) + "/decks/taylor_bar/taylor_coarse.k");
  const auto at = deck.find("*CONTROL_TERMINATION\n");
  deck.replace(at, deck.find('\n', at + 21) - at, "*CONTROL_TERMINATION\n       1.0");  // long
  const auto path = dir.write("long.k", deck);
  // The signal goes once the first state is on disk (up to a minute on a loaded machine), so
  // the run is in its time loop whatever the load.
  const std::string out = (dir.path() / "out").string();
  const Run r = run_shell("( " + std::string(MCDYNA_BINARY) + " run " + path.string() + " --out " +
                          out + " & p=$!; i=0; while [ ! -e " + out +
                          "/d3plot_0000.vtu ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); "
                          "done; sleep 0.5; kill -INT $p; wait $p )");
  CHECK_MESSAGE(r.exit_code == 5, r.output);
  CHECK(r.output.find("interrupted by signal") != std::string::npos);
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(states.size() >= 2);  // t = 0 and the final state at the interruption
  for (const auto& s : states)
    CHECK(read_vtu(dir.path() / "out" / s)->GetNumberOfCells() > 0);
  for (const char* f : {"glstat.csv", "matsum.csv", "rwforc.csv"})
    check_csv_whole(dir.path() / "out" / f);
  CHECK(read_text(dir.path() / "out" / "d3hsp").find("interrupted by signal") != std::string::npos);
}

TEST_CASE("sense switches: d3kil's text names sw1-sw4, an empty file stops, others are no switch") {
  using cli::SenseSwitchFile;
  solver::SenseSwitches sw;
  CHECK(SenseSwitchFile::parse("", sw));
  CHECK(sw.stop);
  CHECK(SenseSwitchFile::parse(" SW2\n", sw));
  CHECK((sw.status && !sw.stop && !sw.dump && !sw.state));
  CHECK(SenseSwitchFile::parse("sw3", sw));
  CHECK((sw.dump && !sw.stop));
  CHECK(SenseSwitchFile::parse("sw4 please", sw));
  CHECK(sw.state);
  CHECK_FALSE(SenseSwitchFile::parse("stop", sw));
  CHECK_FALSE(sw.any());
}

TEST_CASE("a d3kil present when the run starts: read, deleted, sw3 dumps, sw1 dumps and stops") {
  // The file is read at the first cycle (the reader looks at once, then every 0.2 s), so each
  // switch acts at cycle 0 whatever the machine's speed.
  TempDir dir;
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/decks/taylor_bar/taylor_coarse.k";
  auto run_with = [&](const char* name, const char* text) {
    const std::filesystem::path out = dir.path() / name;
    std::filesystem::create_directories(out);
    std::ofstream(out / "d3kil") << text;
    const Run r = run_mcdyna("run " + deck + " --out " + out.string() + " --cycles 50 --threads 1");
    CHECK_FALSE(std::filesystem::exists(out / "d3kil"));  // read and deleted, as LS-DYNA does
    return r;
  };
  const Run state = run_with("sw4", "sw4\n");
  CHECK_MESSAGE(state.exit_code == 0, state.output);
  // (At cycle 0 the schedule writes a state anyway: restart_test.cpp's time-loop test shows sw4
  // adding one between scheduled outputs.)
  CHECK(state.output.find("d3kil read: sense switch sw4") != std::string::npos);
  const Run dump = run_with("sw3", "sw3");
  CHECK_MESSAGE(dump.exit_code == 0, dump.output);
  CHECK(std::filesystem::exists(dir.path() / "sw3" / "d3dump01"));
  const Run status = run_with("sw2", "sw2");
  CHECK(status.output.find("sw2: cycle         0") != std::string::npos);
  const Run stop = run_with("sw1", "");
  CHECK_MESSAGE(stop.exit_code == 5, stop.output);
  CHECK(stop.output.find("stopped by sense switch sw1 (d3kil) at t = 0.000000e+00, cycle 0") !=
        std::string::npos);
  CHECK(std::filesystem::exists(dir.path() / "sw1" / "d3dump01"));
  const Run other = run_with("other", "halt");
  CHECK_MESSAGE(other.exit_code == 0, other.output);
  CHECK(other.output.find("d3kil: \"halt\" is no sense switch") != std::string::npos);
}

TEST_CASE("history files: nodout, bndout, spcforc and matsum carry the motion they describe") {
  TempDir dir;
  // An elastic cube standing on a z-only SPC, its top pushed down by a prescribed displacement
  // d = -0.01 t (VAD 2), and a separate rigid cube (mass 2) driven by the velocity ramp v = t.
  std::string deck =
      "*KEYWORD\n*TITLE\nhistories\n*CONTROL_TERMINATION\n0.5\n*CONTROL_TIMESTEP\n0.001\n"
      "*DATABASE_NODOUT\n0.05\n*DATABASE_SPCFORC\n0.05\n*DATABASE_BNDOUT\n0.05\n"
      "*DATABASE_MATSUM\n0.05\n*DATABASE_HISTORY_NODE\n25\n"
      "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,100.0,0.3\n"
      "*PART\nrigid\n2,1,2\n*MAT_RIGID\n2,2.0,100.0,0.3\n" +
      box_mesh(2, 2, 2, 0.5) + box_mesh(1, 1, 1, 1.0, 101, 101, 2, 5.0) +
      "*SET_NODE_LIST\n1\n1,2,3,4,5,6,7,8\n9\n*SET_NODE_LIST\n2\n19,20,21,22,23,24,25,26\n27\n"
      "*BOUNDARY_SPC_SET\n1,0,0,0,1,0,0,0\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,3,2,1,1.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,3,0,2,1.0\n"
      "*DEFINE_CURVE\n1\n0,0\n1,-0.01\n*DEFINE_CURVE\n2\n0,0\n10,10\n*END\n";
  dir.write("deck.k", deck);
  const Run r = run_mcdyna("run deck.k --out out -q", "cd " + dir.path().string() + " && ");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const std::filesystem::path out = dir.path() / "out";
  for (const char* f : {"nodout", "bndout", "spcforc", "matsum"}) {
    CHECK(std::filesystem::exists(out / f));
    check_csv_whole(out / (std::string(f) + ".csv"));
  }

  // nodout: the top node follows the prescribed displacement exactly.
  const CsvTable nodout = read_csv(out / "nodout.csv");
  for (const auto& row : nodout.rows) {
    CHECK(row[nodout.column("node")] == 25);
    CHECK(row[nodout.column("z_disp")] ==
          doctest::Approx(-0.01 * row[nodout.column("time")]).epsilon(1e-9));
  }
  CHECK(nodout.rows.size() >= 10);

  // bndout: one line per prescribed node (19..27) and the rigid part's constraint force m a = 2.
  const CsvTable bnd = read_csv(out / "bndout.csv");
  int motion_rows = 0, node_rows = 0;
  for (std::size_t k = 0; k < bnd.rows.size(); ++k) {
    const std::string& kind = bnd.text[k][bnd.column("kind")];
    const double id = bnd.rows[k][bnd.column("id")];
    if (kind == "rigid_part") {
      ++motion_rows;
      CHECK(id == 2);
      CHECK(bnd.rows[k][bnd.column("z_force")] == doctest::Approx(2.0).epsilon(1e-9));
    } else {
      ++node_rows;
      CHECK(kind == "node");
      CHECK((id >= 19 && id <= 27));
    }
  }
  CHECK(node_rows == 9 * motion_rows);
  CHECK(read_text(out / "bndout").find("mat#       2  xforce=") != std::string::npos);

  // spcforc: the nine bottom nodes, z reactions only; the ASCII lines carry the CSV numbers.
  const CsvTable spc = read_csv(out / "spcforc.csv");
  double last_time = 0.0;
  for (const auto& row : spc.rows) {
    CHECK(row[spc.column("node")] <= 9);
    CHECK(row[spc.column("x_force")] == 0.0);
    CHECK(row[spc.column("y_force")] == 0.0);
    last_time = row[spc.column("time")];
  }
  const std::string spc_ascii = read_text(out / "spcforc");
  const auto& last = spc.rows.back();
  CHECK(spc_ascii.find(fmt::format(" node={:8d} local x,y,z forces ={:14.4E}{:14.4E}{:14.4E}",
                                   static_cast<int>(last[spc.column("node")]), 0.0, 0.0,
                                   last[spc.column("z_force")])) != std::string::npos);
  CHECK(spc_ascii.find(fmt::format(" output at time ={:14.5E}", last_time)) != std::string::npos);

  // matsum: the rigid part's centre velocity follows the ramp v = t. The value shown is the mean
  // of the half-step velocities v(t - dt_old / 2) and v(t + dt_new / 2), which differs from
  // v(t) by (dt_new - dt_old) / 4, at most dt / 4 = 2.5e-4 with DTINIT = 0.001.
  const CsvTable mat = read_csv(out / "matsum.csv");
  int rigid_rows = 0;
  for (const auto& row : mat.rows)
    if (row[mat.column("part")] == 2) {
      ++rigid_rows;
      CHECK(std::abs(row[mat.column("z_rigid_velocity")] - row[mat.column("time")]) <= 2.5e-4);
    }
  CHECK(rigid_rows >= 10);
  check_ascii_matches_csv(out, "nodout", 1e-4, 12);
  check_ascii_matches_csv(out, "spcforc", 2e-4, 27);
  check_ascii_matches_csv(out, "bndout", 2e-3, 4 * 9 + 7);
  check_ascii_matches_csv(out, "matsum", 2e-4, 2 * 11);
}

TEST_CASE("rcforc: a slave and a master line per contact and output time, equal and opposite") {
  TempDir dir;
  // An elastic cube falling at 1 onto a fixed rigid shell plate (automatic nodes-to-surface).
  std::string deck =
      "*KEYWORD\n*TITLE\ncontact\n*CONTROL_TERMINATION\n0.6\n*DATABASE_RCFORC\n0.02\n"
      "*DATABASE_GLSTAT\n0.02\n*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n"
      "*MAT_ELASTIC\n1,1.0,100.0,0.3\n*PART\nplate\n2,2,2\n*SECTION_SHELL\n2\n"
      "0.1,0.1,0.1,0.1\n*MAT_RIGID\n2,1.0,100.0,0.3\n1,7,7\n" +
      box_mesh(2, 2, 2, 0.5, 1, 1, 1, 0.06) +
      "*NODE\n101,-1,-1,0\n102,2,-1,0\n103,2,2,0\n104,-1,2,0\n*ELEMENT_SHELL\n"
      "101,2,101,102,103,104\n*SET_PART_LIST\n1\n1\n"
      "*INITIAL_VELOCITY_GENERATION\n1,1,0,0,0,-1.0\n0,0,0\n"
      "*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID\n7,cube on plate\n1,2,3,3\n0,0\n\n*END\n";
  dir.write("deck.k", deck);
  const Run r = run_mcdyna("run deck.k --out out -q", "cd " + dir.path().string() + " && ");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const std::filesystem::path out = dir.path() / "out";
  check_csv_whole(out / "rcforc.csv");
  const CsvTable rc = read_csv(out / "rcforc.csv");
  REQUIRE(rc.rows.size() % 2 == 0);
  double largest = 0.0;
  for (std::size_t k = 0; k + 1 < rc.rows.size(); k += 2) {
    CHECK(rc.text[k][rc.column("side")] == "slave");
    CHECK(rc.text[k + 1][rc.column("side")] == "master");
    CHECK(rc.rows[k][rc.column("contact")] == 7.0);
    CHECK(rc.rows[k][0] == rc.rows[k + 1][0]);
    const double slave = rc.rows[k][rc.column("z_force")];
    const double master = rc.rows[k + 1][rc.column("z_force")];
    CHECK(std::abs(slave + master) <= 1e-9 * std::max(1.0, std::abs(slave)));
    largest = std::max(largest, slave);  // the plate pushes the cube up (+z)
  }
  CHECK(largest > 0.0);
  // The LS-DYNA layout: tokens side, id, "time", t, "x", fx, "y", fy, "z", fz, "mass", m.
  std::istringstream ascii(read_text(out / "rcforc"));
  std::string line;
  int lines = 0;
  while (std::getline(ascii, line)) {
    std::istringstream tokens(line);
    std::string side, time, x, y, z, mass;
    long id = 0;
    double t = 0, fx = 0, fy = 0, fz = 0, m = 0;
    if (!(tokens >> side) || (side != "slave" && side != "master")) continue;
    REQUIRE(
        static_cast<bool>(tokens >> id >> time >> t >> x >> fx >> y >> fy >> z >> fz >> mass >> m));
    CHECK(id == 7);
    CHECK(time == "time");
    CHECK(mass == "mass");
    ++lines;
  }
  CHECK(lines == static_cast<int>(rc.rows.size()));
  // glstat carries the interface's energy in the sliding column, and the balance holds: measured
  // 1.4e-3 off, the work of nodes that first touch within a step (the penalty force is found at
  // the step's end, the trapezoidal rule credits half of it for the whole step).
  const CsvTable gl = read_csv(out / "glstat.csv");
  double sliding = 0.0;
  for (const auto& row : gl.rows)
    sliding = std::max(sliding, row[gl.column("sliding_energy")]);
  CHECK(sliding > 0.0);
  CHECK(std::abs(gl.rows.back()[gl.column("energy_ratio")] - 1.0) < 3e-3);
  check_ascii_matches_csv(out, "rcforc", 1e-4, 2 * 7);
  // The timing table has a contact row for a deck with contact and no SPG part.
  CHECK(read_text(out / "d3hsp").find("\n  contact ") != std::string::npos);
  check_ascii_matches_csv(out, "glstat", 1e-4, 13);
}

TEST_CASE("eroded elements vanish from the forces and the d3plot states, their mass stays") {
  TempDir dir;
  // A 6 x 1 x 1 bar of MAT_003 with FS = 0.05, its far end pulled at 5 length/time: it necks
  // and fails.
  const std::string deck =
      eroding_bar("*CONTROL_TERMINATION\n0.2\n*DATABASE_BINARY_D3PLOT\n0.02\n");
  Simulation sim = prepare(dir, deck);
  double mass0 = 0.0;
  for (double m : sim.state->nodes.mass)
    mass0 += m;
  run(sim);
  int eroded = 0;
  for (std::size_t e = 0; e < solver::solids_of(*sim.state).eroded.size(); ++e)
    if (solver::solids_of(*sim.state).eroded[e]) {
      ++eroded;
      for (int k = 0; k < 24; ++k)
        CHECK(solver::solids_of(*sim.state).corner_force[24 * e + static_cast<std::size_t>(k)] ==
              0.0);
    }
  double mass1 = 0.0;
  for (double m : sim.state->nodes.mass)
    mass1 += m;
  MESSAGE(eroded, " of 6 elements eroded");
  CHECK(eroded >= 1);
  CHECK(mass1 == mass0);

  // The same deck from the command line: the last state has fewer cells than the first.
  const Run r = run_mcdyna("run " + (dir.path() / "deck.k").string() + " --out " +
                           (dir.path() / "out").string() + " -q");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto files = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(files.size() >= 2);
  const auto first = read_vtu(dir.path() / "out" / files.front());
  const auto last = read_vtu(dir.path() / "out" / files.back());
  CHECK(first->GetNumberOfCells() == 6);
  CHECK(last->GetNumberOfCells() == 6 - eroded);
  CHECK(last->GetNumberOfPoints() == first->GetNumberOfPoints());
}

TEST_CASE("--spg-angular-budget reports the scheme's own angular momentum (Taylor bar: none)") {
  // The coarse SPG Taylor bar hits its wall straight, and its mesh is mirror-symmetric: the
  // gather's first-moment defects (theory.md, Angular momentum) cancel over the bar, so the
  // scheme's own part stays at round-off of the bar's sum m|x - x_c||u| (measured 5.7e-19 over
  // 300 cycles, 5.9e-16 over the whole 37,101-cycle run).
  TempDir dir;
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/decks/taylor_bar/taylor_spg_coarse.k";
  const Run r = run_mcdyna("run " + deck + " --cycles 40 --threads 2 --spg-angular-budget --out " +
                           dir.path().string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const std::string key = " of the initial sum m|x - x_c||u| ";
  const std::size_t at = r.output.find(key);
  REQUIRE_MESSAGE(at != std::string::npos, r.output);
  const std::size_t start = r.output.rfind(", ", at) + 2;
  const double share = std::stod(r.output.substr(start, at - start));
  MESSAGE("the scheme's own angular momentum over the bar's scale: ", share);
  CHECK(share < 1e-12);
  CHECK(std::stod(r.output.substr(at + key.size())) > 1.0);  // the scale: 7.394 t mm^2/s
}

TEST_CASE("beams are line cells of the d3plot series with their resultants") {
  // A two-element Hughes-Liu cantilever (t, mm, s units) under a tip force of 1 N along z: the
  // clamped element's axial force is ~0, its shear along t carries the 1 N, and its moment about
  // s is the force times the arm to its point (75 mm, the mid-point of the first element), once
  // the tip has settled under *DAMPING_GLOBAL.
  TempDir dir;
  const auto deck = dir.write(
      "beam.k",
      "*KEYWORD\n*CONTROL_TERMINATION\n0.2\n*DATABASE_BINARY_D3PLOT\n0.1\n"
      "*PART\nbeam\n1,1,1\n*SECTION_BEAM\n1,1,0.8333333,2\n10.0,10.0,10.0,10.0\n"
      "*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n*NODE\n1,0,0,0\n2,50,0,0\n3,100,0,0\n"
      "*ELEMENT_BEAM\n1,1,1,2,0\n2,1,2,3,0\n*BOUNDARY_SPC_NODE\n1,0,1,1,1,1,1,1\n"
      "*LOAD_NODE_POINT\n3,3,1,1.0\n*DEFINE_CURVE\n1\n0,1\n1,1\n*DAMPING_GLOBAL\n0,3000\n*END\n");
  const Run r = run_mcdyna("run -q " + deck.string() + " --out " + (dir.path() / "out").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(states.size() == 3);
  const auto grid = read_vtu(dir.path() / "out" / states.back());
  REQUIRE(grid->GetNumberOfCells() == 2);
  CHECK(grid->GetCellType(0) == VTK_LINE);
  vtkDataArray* res = grid->GetCellData()->GetArray("beam_resultants");
  REQUIRE(res != nullptr);
  REQUIRE(res->GetNumberOfComponents() == 6);
  const double* root = res->GetTuple6(0);
  MESSAGE("root element: N ", root[0], ", Vt ", root[2], ", Ms ", root[4]);
  CHECK(std::abs(root[0]) < 1e-3);
  CHECK(std::abs(root[2]) == doctest::Approx(1.0).epsilon(1e-3));
  CHECK(std::abs(root[4]) == doctest::Approx(75.0).epsilon(1e-3));
  CHECK(grid->GetCellData()->GetArray("stress") != nullptr);
}

namespace {

// The numbers after `label` on d3hsp's deformable-parts line.
double summary_value(const std::string& log, const std::string& label) {
  const std::size_t line = log.find("  deformable parts (rigid bodies left out)");
  REQUIRE(line != std::string::npos);
  const std::size_t at = log.find(label, line);
  REQUIRE(at != std::string::npos);
  return std::stod(log.substr(at + label.size()));
}

double last_of(const io::HistoryTable& t, const std::string& name) {
  const int k = t.find(name);
  REQUIRE(k >= 0);
  return t.columns[static_cast<std::size_t>(k)].back();
}

}  // namespace

TEST_CASE("run summary: the deformable parts' energies and added mass, rigid bodies left out") {
  TempDir dir;
  // The falling cube (no rigid body): its energies at the end are glstat's, to the printed digits.
  const std::string cube = std::string(MCDYNA_SOURCE_DIR) + "/decks/cube/cube_drop.k";
  Run r = run_mcdyna("run " + cube + " -q --threads 1 --out " + (dir.path() / "cube").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  std::string log = read_text(dir.path() / "cube" / "d3hsp");
  const io::HistoryTable cube_glstat = io::read_history(dir.path() / "cube" / "glstat.csv");
  const double ke = last_of(cube_glstat, "kinetic_energy");
  const double ie = last_of(cube_glstat, "internal_energy");
  CHECK(summary_value(log, "kinetic energy ") == doctest::Approx(ke).epsilon(1e-4));
  CHECK(summary_value(log, "internal energy ") == doctest::Approx(ie).epsilon(1e-4));
  CHECK(summary_value(log, "KE/IE ") == doctest::Approx(ke / ie).epsilon(1e-4));
  CHECK(summary_value(log, "largest KE/IE ") >= ke / ie);
  // FDS h 0.3 before the screw touches: the plate rests, the rigid screw spins. glstat's kinetic
  // energy is the screw's; the deformable parts' is zero.
  const std::string fds = std::string(MCDYNA_SOURCE_DIR) + "/decks/fds/fds_h0.3.k";
  r = run_mcdyna("run " + fds + " -q --threads 1 --cycles 50 --out " +
                 (dir.path() / "fds").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  log = read_text(dir.path() / "fds" / "d3hsp");
  CHECK(last_of(io::read_history(dir.path() / "fds" / "glstat.csv"), "kinetic_energy") > 1.0);
  CHECK(summary_value(log, "kinetic energy ") == 0.0);
  CHECK(summary_value(log, "added mass (DT2MS) ") == 0.0);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("run summary: the driven screw's speed, the wave speed and rho v^2 / yield") {
  TempDir dir;
  // FDS h 0.3 (time scale 20) past its start ramp (2.3 us): the screw turns at 100,000 rpm and
  // plunges at 40 m/s, so its nodes, at radii from the minor 2.067 mm to the major 2.5 mm, move
  // at sqrt(v^2 + (w r)^2). The body turns about its centre of mass, which the thread's helix
  // moves off the axis: 0.03 mm allowed (measured: an effective radius of 2.509 mm).
  const std::string fds = std::string(MCDYNA_SOURCE_DIR) + "/decks/fds/fds_h0.3.k";
  const Run r = run_mcdyna("run " + fds + " -q --threads 1 --cycles 400 --out " +
                           (dir.path() / "fds").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const std::string log = read_text(dir.path() / "fds" / "d3hsp");
  const std::size_t line = log.find("  driven nodes: fastest ");
  REQUIRE_MESSAGE(line != std::string::npos, log);
  const std::string text = log.substr(line, log.find('\n', line) - line);
  MESSAGE(text);
  const double v = std::stod(text.substr(std::string("  driven nodes: fastest ").size()));
  const double plunge = 40'000.0, omega = 100'000.0 * 2.0 * M_PI / 60.0;  // mm/s, rad/s
  CHECK(v >= std::hypot(plunge, omega * 2.067));
  CHECK(v <= std::hypot(plunge, omega * (2.5 + 0.03)));
  // The plate: JC A 324 MPa, rho 2.7e-9 t/mm^3, G 26,000 MPa, Gruneisen C 5,386,000 mm/s.
  const double rho = 2.7e-9, wave = std::sqrt(5.386e6 * 5.386e6 + 4.0 / 3.0 * 26'000.0 / rho);
  const std::size_t of = text.find(" of the slowest wave speed (");
  REQUIRE(of != std::string::npos);
  CHECK(std::stod(text.substr(of + std::string(" of the slowest wave speed (").size())) ==
        doctest::Approx(wave).epsilon(1e-4));
  const std::size_t number = text.find("rho v^2 / yield ");
  REQUIRE(number != std::string::npos);
  CHECK(std::stod(text.substr(number + std::string("rho v^2 / yield ").size())) ==
        doctest::Approx(rho * v * v / 324.0).epsilon(1e-3));
  CHECK(text.find("(part 1)") != std::string::npos);
  CHECK(text.find("quasi-static by its speeds") != std::string::npos);
  // 400 cycles are the first bite alone: the tip strikes at 40 m/s and the plate's KE/IE is
  // 0.1 where its internal energy is largest; ρv²/yield, 0.019, is above its bound (0.01) too.
  // Under -q the warning goes to the terminal as well.
  const std::size_t warning = log.find("warning: the run looks quasi-static");
  REQUIRE_MESSAGE(warning != std::string::npos, log);
  const std::string warned = log.substr(warning, log.find('\n', warning) - warning);
  CHECK(warned.find("their largest KE/IE is 0.1") != std::string::npos);
  CHECK(warned.find("rho v^2 / yield of part 1 at the tool's speed is 0.019") != std::string::npos);
  CHECK(r.output.find(warned) != std::string::npos);
}

}  // namespace mcdyna::test
