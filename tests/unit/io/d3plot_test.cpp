// LS-DYNA's binary d3plot (issue 49): the control words, geometry, IDs and titles in the layout
// of LSTC's "LS-DYNA Database Binary Output Files", each state the size the control words give
// (LS-DYNA's formula), the states equal to the VTK series to single precision, the deletion
// flags to the eroded elements, and the family split at its size without a state cut in two.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cstring>

#include "io/d3plot/d3plot_family.hpp"
#include "output_support.hpp"

namespace mcdyna::test {

namespace {

namespace fs = std::filesystem;

// A file as 4-byte words, read as integers and as reals.
struct WordFile {
  std::vector<std::int32_t> i;
  std::vector<float> f;
  explicit WordFile(const fs::path& p) {
    const std::string bytes = read_text(p);
    REQUIRE(bytes.size() % 4 == 0);
    i.resize(bytes.size() / 4);
    f.resize(bytes.size() / 4);
    std::memcpy(i.data(), bytes.data(), bytes.size());
    std::memcpy(f.data(), bytes.data(), bytes.size());
  }
  [[nodiscard]] std::size_t size() const { return i.size(); }
};

constexpr float kMarker = -999999.0F;

// The control words the tests read (LSTC's names).
enum Word : std::size_t {
  NDIM = 15,
  NUMNP = 16,
  ICODE = 17,
  NGLBV = 18,
  IU = 20,
  IV = 21,
  IA = 22,
  NEL8 = 23,
  NUMMAT8 = 24,
  NV3D = 27,
  NEL2 = 28,
  NV1D = 30,
  NEL4 = 31,
  NV2D = 33,
  MAXINT = 36,
  NMSPH = 37,
  NGPSPH = 38,
  NARBS = 39,
  NMMAT = 51
};

std::int64_t state_words(const WordFile& h) {
  const std::int64_t nel8 = h.i[NEL8], nel2 = h.i[NEL2], nel4 = h.i[NEL4];
  return 1 + h.i[NGLBV] + 3 * (h.i[IU] + h.i[IV] + h.i[IA]) * std::int64_t{h.i[NUMNP]} +
         nel8 * h.i[NV3D] + nel2 * h.i[NV1D] + nel4 * h.i[NV2D] + nel8 + nel2 + nel4;
}

// Runs `text` as DIR/NAME into DIR/out with `options` (REQUIREs a normal end); returns the output
// folder.
fs::path run_deck(const TempDir& dir, const std::string& name, const std::string& text,
                  const std::string& options = "") {
  const fs::path deck = dir.write(name, text);
  const fs::path out = dir.path() / "out";
  const Run r = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q " + options);
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  return out;
}

}  // namespace

TEST_CASE("d3plot: the cube's control words, geometry, IDs and titles in LS-DYNA's layout") {
  TempDir dir;
  const fs::path out = run_deck(dir, "cube.k", source_text("decks/cube/cube_drop.k"));
  const fs::path deck = dir.path() / "cube.k";
  const WordFile g(out / "d3plot");
  CHECK(g.size() % 512 == 0);  // whole 512-word records
  CHECK(g.i[NDIM] == 4);
  CHECK(g.i[ICODE] == 6);
  CHECK(g.f[14] == 960.0F);
  CHECK(g.i[NUMNP] == 27);
  CHECK(g.i[NEL8] == 8);
  CHECK(g.i[NUMMAT8] == 1);
  CHECK(g.i[NV3D] == 7);
  CHECK(g.i[NEL2] == 0);
  CHECK(g.i[NEL4] == 0);
  CHECK(g.i[NMMAT] == 1);
  CHECK(g.i[NGLBV] == 6 + 7 * 1);
  CHECK(g.i[MAXINT] == -10003);
  CHECK(g.i[NARBS] == 16 + 27 + 8 + 3 * 1);
  // Geometry: 27 coordinates (the first node at the deck's first node), 8 solids of 8 1-based
  // node numbers and part number 1.
  const std::size_t geometry = 64, solids = geometry + 3 * 27, ids = solids + 8 * 9;
  const auto model = load_file(deck, true);
  const model::Node& first = model->built.model.nodes.front();
  CHECK(g.f[geometry] == static_cast<float>(first.position[0]));
  CHECK(g.f[geometry + 2] == static_cast<float>(first.position[2]));
  for (std::size_t e = 0; e < 8; ++e) {
    for (std::size_t k = 0; k < 8; ++k) {
      CHECK(g.i[solids + 9 * e + k] >= 1);
      CHECK(g.i[solids + 9 * e + k] <= 27);
    }
    CHECK(g.i[solids + 9 * e + 8] == 1);
  }
  // IDs: NSORT < 0 (part IDs follow), the counts, the node and element IDs in the deck's order.
  CHECK(g.i[ids] < 0);
  CHECK(g.i[ids + 5] == 27);
  CHECK(g.i[ids + 6] == 8);
  CHECK(g.i[ids + 15] == 1);
  CHECK(g.i[ids + 16] == static_cast<std::int32_t>(first.id));
  CHECK(g.i[ids + 16 + 27] == static_cast<std::int32_t>(model->built.model.solids.front().id));
  const std::size_t parts = ids + 16 + 27 + 8;
  const auto part_id = static_cast<std::int32_t>(model->built.model.parts.front().id);
  CHECK(g.i[parts] == part_id);
  CHECK(g.i[parts + 1] == part_id);
  CHECK(g.i[parts + 2] == 1);
  // The end of the geometry, the part titles (72 characters), the end again.
  const std::size_t titles = parts + 3;
  REQUIRE(g.f[titles] == kMarker);
  CHECK(g.i[titles + 1] == 90001);
  CHECK(g.i[titles + 2] == 1);
  CHECK(g.i[titles + 3] == part_id);
  const std::string heading(reinterpret_cast<const char*>(&g.i[titles + 4]), 72);
  CHECK(heading.rfind(model->built.model.parts.front().heading, 0) == 0);
  CHECK(g.f[titles + 4 + 18] == kMarker);
}

TEST_CASE("d3plot: every state the size LS-DYNA's formula gives, equal to the VTK series") {
  TempDir dir;
  const fs::path out = run_deck(dir, "cube.k", source_text("decks/cube/cube_drop.k"));
  const WordFile g(out / "d3plot");
  const std::int64_t size = state_words(g);
  CHECK(size == 1 + 13 + 9 * 27 + 8 * 7 + 8);
  const WordFile s(out / "d3plot01");
  CHECK(s.size() % 512 == 0);
  const std::vector<std::string> vtu = collection(out / "d3plot.pvd");
  REQUIRE(vtu.size() >= 2);
  // The states one after the other, the end-of-file marker after the last.
  REQUIRE(s.size() >= vtu.size() * static_cast<std::size_t>(size) + 1);
  CHECK(s.f[vtu.size() * static_cast<std::size_t>(size)] == kMarker);
  for (std::size_t k = 0; k < vtu.size(); ++k) {
    CAPTURE(k);
    const std::size_t at = k * static_cast<std::size_t>(size);
    const auto grid = read_vtu(out / vtu[k]);
    // Coordinates after the time and the 13 globals; the VTK points are the same nodes in the
    // same order, in double precision.
    const std::size_t coords = at + 1 + 13;
    for (vtkIdType n = 0; n < 27; ++n)
      for (int c = 0; c < 3; ++c)
        CHECK(s.f[coords + 3 * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] ==
              static_cast<float>(grid->GetPoint(n)[c]));
    // The solids' stress and plastic strain after the nodes' 9 words each.
    vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
    vtkDataArray* eps = grid->GetCellData()->GetArray("effective_plastic_strain");
    const std::size_t elements = coords + 9 * 27;
    for (vtkIdType e = 0; e < 8; ++e) {
      const std::size_t w = elements + 7 * static_cast<std::size_t>(e);
      for (int c = 0; c < 6; ++c)
        CHECK(s.f[w + static_cast<std::size_t>(c)] ==
              static_cast<float>(stress->GetComponent(e, c)));
      CHECK(s.f[w + 6] == static_cast<float>(eps->GetComponent(e, 0)));
      CHECK(s.f[elements + 8 * 7 + static_cast<std::size_t>(e)] == 1.0F);  // not deleted
    }
  }
}

TEST_CASE("d3plot: eroded elements are flagged deleted, as many as the VTK series leaves out") {
  TempDir dir;
  const fs::path out = run_deck(
      dir, "bar.k", eroding_bar("*CONTROL_TERMINATION\n0.2\n*DATABASE_BINARY_D3PLOT\n0.02\n"));
  const WordFile g(out / "d3plot");
  const std::int64_t size = state_words(g);
  const auto nel8 = static_cast<std::size_t>(g.i[NEL8]);
  const std::vector<std::string> vtu = collection(out / "d3plot.pvd");
  std::size_t states = 0, last_alive = nel8;
  for (int member = 1; fs::exists(out / fmt::format("d3plot{:02d}", member)); ++member) {
    const WordFile s(out / fmt::format("d3plot{:02d}", member));
    for (std::size_t at = 0; at + static_cast<std::size_t>(size) < s.size() && s.f[at] != kMarker;
         at += static_cast<std::size_t>(size)) {
      REQUIRE(states < vtu.size());
      const std::size_t flags = at + static_cast<std::size_t>(size) - nel8;
      std::size_t alive = 0;
      for (std::size_t e = 0; e < nel8; ++e) {
        CHECK((s.f[flags + e] == 0.0F || s.f[flags + e] == 1.0F));
        alive += s.f[flags + e] == 1.0F ? 1 : 0;
      }
      CHECK(alive == static_cast<std::size_t>(read_vtu(out / vtu[states])->GetNumberOfCells()));
      last_alive = alive;
      ++states;
    }
  }
  CHECK(states == vtu.size());
  CHECK(last_alive < nel8);  // the bar did erode
}

TEST_CASE("d3plot: SPG particles in the SPH section, each state's words equal to the series") {
  TempDir dir;
  const fs::path out =
      run_deck(dir, "bar.k", source_text("decks/taylor_bar/taylor_spg_coarse.k"), "--cycles 60");
  const WordFile g(out / "d3plot");
  const std::vector<std::string> vtu = collection(out / "d3plot.pvd");
  const auto last = read_vtu(out / vtu.back());
  const auto particles = static_cast<std::size_t>(last->GetNumberOfCells());
  REQUIRE(g.i[NMSPH] == static_cast<std::int32_t>(particles));
  CHECK(g.i[NGPSPH] == 1);
  // ISPHFG: 11 flags; pressure, stress, plastic strain, two history words: 11 words a particle.
  const std::vector<std::int32_t> flags(g.i.begin() + 64, g.i.begin() + 75);
  CHECK(flags == std::vector<std::int32_t>{11, 0, 1, 6, 1, 0, 0, 0, 0, 0, 2});
  const std::size_t numnp = static_cast<std::size_t>(g.i[NUMNP]);
  const std::size_t list = 75 + 3 * numnp + static_cast<std::size_t>(g.i[NARBS]);  // no elements
  const std::int64_t size = state_words(g) + static_cast<std::int64_t>(11 * particles);
  const WordFile s(out / "d3plot01");
  REQUIRE(s.size() >= vtu.size() * static_cast<std::size_t>(size) + 1);
  CHECK(s.f[vtu.size() * static_cast<std::size_t>(size)] == kMarker);
  vtkDataArray* pressure = last->GetCellData()->GetArray("pressure");
  vtkDataArray* stress = last->GetCellData()->GetArray("stress");
  vtkDataArray* eps = last->GetCellData()->GetArray("effective_plastic_strain");
  vtkDataArray* bonds = last->GetCellData()->GetArray("bond_damage");
  vtkDataArray* state = last->GetCellData()->GetArray("spg_state");
  const std::size_t first =
      (vtu.size() - 1) * static_cast<std::size_t>(size) + static_cast<std::size_t>(state_words(g));
  for (std::size_t p = 0; p < particles; ++p) {
    const auto c = static_cast<vtkIdType>(p);
    CHECK(g.i[list + 2 * p] == last->GetCell(c)->GetPointId(0) + 1);  // node number
    CHECK(g.i[list + 2 * p + 1] == 1);                                // part number
    const std::size_t w = first + 11 * p;
    CHECK(s.f[w] == 1.0F);
    CHECK(s.f[w + 1] == static_cast<float>(pressure->GetComponent(c, 0)));
    for (int k = 0; k < 6; ++k)
      CHECK(s.f[w + 2 + static_cast<std::size_t>(k)] ==
            static_cast<float>(stress->GetComponent(c, k)));
    CHECK(s.f[w + 8] == static_cast<float>(eps->GetComponent(c, 0)));
    CHECK(s.f[w + 9] == static_cast<float>(bonds->GetComponent(c, 0)));
    CHECK(s.f[w + 10] == static_cast<float>(state->GetComponent(c, 0)));
  }
  CHECK(g.f[list + 2 * particles] == kMarker);
}

TEST_CASE("d3plot family: a new file at the family size, never a state cut in two") {
  TempDir dir;
  io::d3plot::Words geometry(4);
  for (int k = 0; k < 70; ++k)
    geometry.integer(k);
  io::d3plot::Family family(dir.path(), "d3plot", geometry, 250);
  io::d3plot::Words state(4);
  for (int k = 0; k < 100; ++k)
    state.real(k);
  for (int k = 0; k < 5; ++k)
    family.append(state);
  // Two states fit in 250 words with the marker (201), a third would not (301): files of 2, 2
  // and 1 state, each padded to 512 words, the marker after its last state.
  CHECK(family.position().member == 3);
  CHECK(family.position().states == 5);
  CHECK(family.position().words == 100);
  CHECK(fs::file_size(dir.path() / "d3plot") == 512 * 4);
  for (const auto& [name, states] : std::vector<std::pair<std::string, std::size_t>>{
           {"d3plot01", 2}, {"d3plot02", 2}, {"d3plot03", 1}}) {
    CAPTURE(name);
    const WordFile f(dir.path() / name);
    CHECK(f.size() == 512);
    CHECK(f.f[0] == 0.0F);
    CHECK(f.f[99] == 99.0F);
    CHECK(f.f[states * 100] == kMarker);
    CHECK(f.i[states * 100 + 1] == 0);
  }
  CHECK(!fs::exists(dir.path() / "d3plot04"));
  // A member holds one state, however large.
  io::d3plot::Words big(4);
  for (int k = 0; k < 600; ++k)
    big.real(1.0);
  family.append(big);
  CHECK(family.position().member == 4);
  CHECK(fs::file_size(dir.path() / "d3plot04") == 2 * 512 * 4);
}

TEST_CASE("d3plot family: continued from a dump's position, the same files as straight through") {
  // Two states to a member (family of 250 words, states of 100). A dump after the second state
  // holds a full member: the next state opens a new one and must leave the first closed with its
  // end-of-file marker, as a run that never stopped does; a dump after the first state continues
  // the member it holds.
  TempDir dir;
  io::d3plot::Words geometry(4), state(4);
  geometry.integer(7);
  for (int k = 0; k < 100; ++k)
    state.real(k);
  const fs::path straight = dir.path() / "straight", resumed = dir.path() / "resumed";
  fs::create_directories(straight);
  fs::create_directories(resumed);
  {
    io::d3plot::Family family(straight, "d3plot", geometry, 250);
    for (int k = 0; k < 3; ++k)
      family.append(state);
  }
  for (const int dumped_after : {1, 2}) {
    CAPTURE(dumped_after);
    fs::remove_all(resumed);
    fs::create_directories(resumed);
    io::d3plot::FamilyPosition at;
    {
      io::d3plot::Family family(resumed, "d3plot", geometry, 250);
      for (int k = 0; k < dumped_after; ++k)
        family.append(state);
      at = family.position();
    }
    io::d3plot::Family family(resumed, "d3plot", 4, at, 250);
    for (int k = dumped_after; k < 3; ++k)
      family.append(state);
    for (const char* name : {"d3plot", "d3plot01", "d3plot02"}) {
      CAPTURE(name);
      CHECK(read_text(straight / name) == read_text(resumed / name));
    }
  }
}

}  // namespace mcdyna::test
