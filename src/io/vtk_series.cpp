#include "io/vtk_series.hpp"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>
#include <string>
#include <string_view>

#include "io/checked_file.hpp"
#include "solver/block.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::io {

namespace {

using solver::Index;
using solver::State;

// Fields are single precision, as in d3plot: half the bytes to compress and write, and far more
// digits than a plot shows. Point coordinates stay double (they are the deformed geometry).
vtkNew<vtkFloatArray> vector_array(const char* name, const Eigen::Matrix3Xd& v) {
  vtkNew<vtkFloatArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(v.cols());
  for (Index n = 0; n < v.cols(); ++n)
    a->SetTuple3(n, v(0, n), v(1, n), v(2, n));
  return a;
}

// The fields every cell carries, in cell order (the blocks' order: deformable solids, shells and
// beams not eroded, SPG particles as vertices, rigid solids and shells).
struct CellFields {
  vtkNew<vtkFloatArray> stress, von_mises, plastic_strain, temperature, damage, pressure;
  vtkNew<vtkFloatArray> bond_damage;  ///< SPG: share of the particle's bonds broken (0 for FE)
  /// SPG: the particle's stable step at its last stress update (with any DT2MS mass, before
  /// TSSFAC); 0 where not recorded (FE and rigid cells, particles that carry no stress)
  vtkNew<vtkFloatArray> time_step;
  vtkNew<vtkIntArray> part, eroded;
  vtkNew<vtkIntArray> element_id;  ///< the deck's element ID (a particle: its node's)
  /// SPG: how the particle is integrated now, 0 smoothed (MC-SPG), 1 pinned (plain velocity:
  /// shared with FE, constrained), 2 isolated (degenerate neighbourhood: no stress), 3 debris
  /// (failed material whose row inverted: no stress); -1 for other cells.
  vtkNew<vtkIntArray> spg_state;
  CellFields() {
    stress->SetName("stress");
    stress->SetNumberOfComponents(6);
    const char* comps[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
    for (int k = 0; k < 6; ++k)
      stress->SetComponentName(k, comps[k]);
    von_mises->SetName("von_mises");
    plastic_strain->SetName("effective_plastic_strain");
    temperature->SetName("temperature");
    damage->SetName("damage");
    pressure->SetName("pressure");
    bond_damage->SetName("bond_damage");
    time_step->SetName("time_step");
    part->SetName("part_id");
    element_id->SetName("element_id");
    eroded->SetName("erosion_state");
    spg_state->SetName("spg_state");
  }
  void add(const solver::ElementResult& r, double pressure_value, double temp, int part_id, int id,
           double bonds, int particle_state, double step) {
    const auto& s = r.stress;
    const float tuple[6] = {static_cast<float>(s[0]), static_cast<float>(s[1]),
                            static_cast<float>(s[2]), static_cast<float>(s[3]),
                            static_cast<float>(s[4]), static_cast<float>(s[5])};
    stress->InsertNextTypedTuple(tuple);
    von_mises->InsertNextValue(static_cast<float>(r.von_mises));
    plastic_strain->InsertNextValue(static_cast<float>(r.plastic_strain));
    temperature->InsertNextValue(static_cast<float>(temp));
    damage->InsertNextValue(static_cast<float>(r.damage));
    pressure->InsertNextValue(static_cast<float>(pressure_value));
    bond_damage->InsertNextValue(static_cast<float>(bonds));
    time_step->InsertNextValue(static_cast<float>(step));
    part->InsertNextValue(part_id);
    element_id->InsertNextValue(id);
    eroded->InsertNextValue(0);  // eroded cells are not written; every written cell is intact
    spg_state->InsertNextValue(particle_state);
  }
  void attach(vtkUnstructuredGrid* g) {
    for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{
             stress, von_mises, plastic_strain, temperature, damage, pressure, bond_damage,
             time_step, part, eroded, spg_state, element_id})
      g->GetCellData()->AddArray(a);
  }
};

// The cells of a state as the blocks show them (solver/state_sink.hpp): the common fields in
// CellFields, and each block's own fields (a shell's layer stresses and thickness, a beam's
// resultants) after them in the order declared, zero on the cells that do not carry them.
class VtkCells final : public solver::StateSink {
 public:
  explicit VtkCells(vtkUnstructuredGrid* grid) : grid_(grid) {}

  void declare(std::string_view name, std::initializer_list<const char*> components) override {
    if (find(name) != nullptr) return;
    if (components.size() > kMaxComponents)
      throw std::logic_error("a block's field has more components than a tuple holds: " +
                             std::string(name));
    vtkNew<vtkFloatArray> a;
    a->SetName(std::string(name).c_str());
    a->SetNumberOfComponents(components.size() == 0 ? 1 : static_cast<int>(components.size()));
    int k = 0;
    for (const char* c : components)
      a->SetComponentName(k++, c);
    pad(a, grid_->GetNumberOfCells());
    own_.emplace_back(a.Get());
  }

  // An eroded cell is left out, with the values of its own fields that follow it.
  void cell(solver::CellShape shape, const Index* nodes, const solver::CellValues& v) override {
    skipping_ = v.deleted;
    if (skipping_) return;
    const int n = solver::cell_nodes(shape);
    vtkIdType ids[8];
    for (int c = 0; c < n; ++c)
      ids[c] = nodes[c];
    grid_->InsertNextCell(vtk_type(shape), n, ids);
    fields_.add(v.result, v.pressure, v.temperature, static_cast<int>(v.part),
                static_cast<int>(v.id), v.bond_damage, v.particle_state, v.step);
  }

  void value(std::string_view name, const double* values) override {
    if (skipping_) return;
    vtkFloatArray* a = find(name);
    if (a == nullptr)
      throw std::logic_error("a block's field was not declared: " + std::string(name));
    pad(a, grid_->GetNumberOfCells() - 1);
    float t[kMaxComponents];
    for (int k = 0; k < a->GetNumberOfComponents(); ++k)
      t[k] = static_cast<float>(values[k]);
    a->InsertNextTypedTuple(t);
  }

  // The arrays onto the grid, once every block has shown its cells.
  void attach() {
    fields_.attach(grid_);
    for (const vtkSmartPointer<vtkFloatArray>& a : own_) {
      pad(a, grid_->GetNumberOfCells());
      grid_->GetCellData()->AddArray(a);
    }
  }

 private:
  static constexpr std::size_t kMaxComponents = 16;  ///< the tuples value() and pad() fill
  static int vtk_type(solver::CellShape shape) {
    switch (shape) {
      case solver::CellShape::hexahedron:
        return VTK_HEXAHEDRON;
      case solver::CellShape::quadrilateral:
        return VTK_QUAD;
      case solver::CellShape::triangle:
        return VTK_TRIANGLE;
      case solver::CellShape::line:
        return VTK_LINE;
      case solver::CellShape::vertex:
        return VTK_VERTEX;
    }
    return VTK_EMPTY_CELL;
  }
  static void pad(vtkFloatArray* a, vtkIdType cells) {
    const float zero[kMaxComponents] = {};
    while (a->GetNumberOfTuples() < cells)
      a->InsertNextTypedTuple(zero);
  }
  vtkFloatArray* find(std::string_view name) const {
    for (const vtkSmartPointer<vtkFloatArray>& a : own_)
      if (name == a->GetName()) return a;
    return nullptr;
  }
  vtkUnstructuredGrid* grid_;
  bool skipping_ = false;  ///< the last cell was eroded
  CellFields fields_;
  std::vector<vtkSmartPointer<vtkFloatArray>> own_;
};

}  // namespace

VtkSeries::VtkSeries(std::filesystem::path dir, std::string base)
    : dir_(std::move(dir)), base_(std::move(base)) {}

void VtkSeries::write(const State& s, const Eigen::Matrix3Xd& velocity) {
  const solver::Nodes& nd = s.nodes;
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nd.count());
  for (Index n = 0; n < nd.count(); ++n)
    points->SetPoint(n, nd.position(0, n), nd.position(1, n), nd.position(2, n));
  grid->SetPoints(points);
  const Eigen::Matrix3Xd displacement = nd.position - nd.initial;
  grid->GetPointData()->AddArray(vector_array("displacement", displacement));
  grid->GetPointData()->AddArray(vector_array("velocity", velocity));
  grid->GetPointData()->AddArray(vector_array("acceleration", nd.acceleration));
  vtkNew<vtkIntArray> ids;
  ids->SetName("node_id");
  for (Index n = 0; n < nd.count(); ++n)
    ids->InsertNextValue(static_cast<int>(nd.ids[static_cast<std::size_t>(n)]));
  grid->GetPointData()->AddArray(ids);
  // The mass each node moves with (an MC-SPG particle's smoothed mass, Eq. 20) and the part of
  // it DT2MS mass scaling added, to see where a run was mass-scaled. FE scaling is kept apart
  // from the node mass; an SPG particle's is already in it.
  vtkNew<vtkFloatArray> mass, added;
  mass->SetName("mass");
  added->SetName("added_mass");
  mass->SetNumberOfTuples(nd.count());
  added->SetNumberOfTuples(nd.count());
  for (Index n = 0; n < nd.count(); ++n) {
    const auto nn = static_cast<std::size_t>(n);
    mass->SetValue(n, static_cast<float>(nd.mass[nn] + nd.added_mass[nn]));
    added->SetValue(n, static_cast<float>(nd.added_mass[nn]));
  }
  for (const solver::spg::Domain* d : solver::spg::domains_of(s))
    for (std::size_t i = 0; i < d->particles.nodes.size(); ++i)
      added->SetValue(d->particles.nodes[i], added->GetValue(d->particles.nodes[i]) +
                                                 static_cast<float>(d->particles.added_mass[i]));
  grid->GetPointData()->AddArray(mass);
  grid->GetPointData()->AddArray(added);

  VtkCells cells(grid);
  for (const std::unique_ptr<solver::Block>& b : s.blocks)
    b->write_state(s, cells);
  cells.attach();

  // VTK writes into memory and the file is written here, every write checked: VTK's own file
  // writer on a full disk corrupted its heap on its error path (SEGV in
  // vtkXMLUnstructuredDataWriter::DeletePositionArrays).
  const std::string name = fmt::format("{}_{:04d}.vtu", base_, entries_.size());
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->WriteToOutputStringOn();
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();
  if (writer->Write() != 1)
    throw WriteError(fmt::format("cannot write {}: VTK's writer failed", (dir_ / name).string()));
  write_file_atomically(dir_ / name, writer->GetOutputString());
  // The collection lists a state only once its file is whole on disk, and `entries_` only what
  // the collection on disk lists.
  auto entries = entries_;
  entries.emplace_back(s.time, name);
  write_collection(entries);
  entries_ = std::move(entries);
}

void VtkSeries::restore(std::vector<std::pair<double, std::string>> entries) {
  write_collection(entries);
  entries_ = std::move(entries);
}

std::string pvd_collection(const std::vector<std::pair<double, std::string>>& entries) {
  std::string text = "<?xml version=\"1.0\"?>\n";
  text += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  text += "  <Collection>\n";
  for (const auto& [t, file] : entries)
    text += fmt::format("    <DataSet timestep=\"{:.9e}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                        file);
  text += "  </Collection>\n</VTKFile>\n";
  return text;
}

void VtkSeries::write_collection(const std::vector<std::pair<double, std::string>>& entries) const {
  write_file_atomically(collection(), pvd_collection(entries));
}

}  // namespace mcdyna::io
