// `mcdyna run` as users run it: LS-DYNA style i=, the output files (read back with VTK's own
// reader), the exit codes of an unstable and of an interrupted run.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The .vtu files listed in a .pvd collection, in order.
std::vector<std::string> collection(const std::filesystem::path& pvd) {
  const std::string text = slurp(pvd);
  std::vector<std::string> files;
  const std::string key = "file=\"";
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at)) {
    at += key.size();
    files.push_back(text.substr(at, text.find('"', at) - at));
  }
  return files;
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& p) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(p.string().c_str());
  reader->Update();
  REQUIRE(reader->GetErrorCode() == 0);
  return reader->GetOutput();
}

// Every CSV row has as many fields as the header.
void check_csv_whole(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string header, line;
  REQUIRE(std::getline(in, header));
  const auto fields = std::count(header.begin(), header.end(), ',');
  int rows = 0;
  while (std::getline(in, line)) {
    CHECK(std::count(line.begin(), line.end(), ',') == fields);
    ++rows;
  }
  CHECK(rows > 0);
}

}  // namespace

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
  CHECK(slurp(dir.path() / "d3hsp").find("2 thread") != std::string::npos);
  const auto states = collection(dir.path() / "d3plot.pvd");
  CHECK(states.size() == 51);  // t = 0, 1 us, ..., 50 us
  const auto first = read_vtu(dir.path() / states.front());
  const auto last = read_vtu(dir.path() / states.back());
  CHECK(last->GetNumberOfCells() == 8);
  CHECK(last->GetNumberOfPoints() == 27);
  REQUIRE(last->GetCellData()->GetArray("stress") != nullptr);
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
  const std::string glstat = slurp(dir.path() / "glstat");
  CHECK(glstat.find(" kinetic energy.................") != std::string::npos);
  CHECK(glstat.find(" total energy / initial energy..") != std::string::npos);
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
  std::string deck = slurp(std::string(MCDYNA_SOURCE_DIR) + "/decks/taylor_bar/taylor_coarse.k");
  const auto at = deck.find("*CONTROL_TERMINATION\n");
  deck.replace(at, deck.find('\n', at + 21) - at, "*CONTROL_TERMINATION\n       1.0");  // long
  const auto path = dir.write("long.k", deck);
  const Run r = run_mcdyna("run " + path.string() + " --out " + (dir.path() / "out").string(),
                           "timeout --preserve-status -s INT 2");
  CHECK_MESSAGE(r.exit_code == 5, r.output);
  CHECK(r.output.find("interrupted by signal") != std::string::npos);
  const auto states = collection(dir.path() / "out" / "d3plot.pvd");
  REQUIRE(states.size() >= 2);  // t = 0 and the final state at the interruption
  for (const auto& s : states)
    CHECK(read_vtu(dir.path() / "out" / s)->GetNumberOfCells() > 0);
  for (const char* f : {"glstat.csv", "matsum.csv", "rwforc.csv"})
    check_csv_whole(dir.path() / "out" / f);
  CHECK(slurp(dir.path() / "out" / "d3hsp").find("interrupted by signal") != std::string::npos);
}

}  // namespace mcdyna::test
