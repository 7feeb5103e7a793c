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
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

#include "io/checked_file.hpp"
#include "solver/results.hpp"

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

// Cell fields in cell order: deformable solids and shells (not eroded), SPG particles
// (vertices), rigid solids, rigid shells.
struct CellFields {
  vtkNew<vtkFloatArray> stress, von_mises, plastic_strain, temperature, damage, pressure;
  vtkNew<vtkFloatArray> bond_damage;  ///< SPG: share of the particle's bonds broken (0 for FE)
  /// SPG: the particle's stable step at its last stress update (with any DT2MS mass, before
  /// TSSFAC); 0 where not recorded (FE and rigid cells, particles that carry no stress)
  vtkNew<vtkFloatArray> time_step;
  vtkNew<vtkIntArray> part, eroded;
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
    eroded->SetName("erosion_state");
    spg_state->SetName("spg_state");
  }
  void add(const solver::ElementResult& r, double pressure_value, double temp, int part_id,
           double bonds = 0.0, int particle_state = -1, double step = 0.0) {
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
    eroded->InsertNextValue(0);  // eroded cells are not written; every written cell is intact
    spg_state->InsertNextValue(particle_state);
  }
  void attach(vtkUnstructuredGrid* g) {
    for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{
             stress, von_mises, plastic_strain, temperature, damage, pressure, bond_damage,
             time_step, part, eroded, spg_state})
      g->GetCellData()->AddArray(a);
  }
};

// The beams' own field, written when the model has deformable beams: the resultants in the
// beam's local axes r s t (LS-DYNA's elout order: axial force, shear s, shear t, torsion,
// moment s, moment t); zero on the other cells.
struct BeamFields {
  vtkNew<vtkFloatArray> resultants;
  BeamFields() {
    resultants->SetName("beam_resultants");
    resultants->SetNumberOfComponents(6);
    const char* comps[6] = {"N", "Vs", "Vt", "T", "Ms", "Mt"};
    for (int k = 0; k < 6; ++k)
      resultants->SetComponentName(k, comps[k]);
  }
  void add(const float (&r)[6]) { resultants->InsertNextTypedTuple(r); }
  void add(const solver::State& s, const solver::BeamBlock& block, solver::Index e) {
    const std::array<double, 6> v = solver::beam_resultants(s, block, e);
    const float r[6] = {static_cast<float>(v[0]), static_cast<float>(v[1]),
                        static_cast<float>(v[2]), static_cast<float>(v[3]),
                        static_cast<float>(v[4]), static_cast<float>(v[5])};
    add(r);
  }
  void pad_to(vtkIdType cells) {
    const float zero[6] = {};
    while (resultants->GetNumberOfTuples() < cells)
      add(zero);
  }
  void attach(vtkUnstructuredGrid* g) { g->GetCellData()->AddArray(resultants); }
};

// The shells' own fields, written when the model has deformable shells: the stress of the top
// and bottom layers (global axes; `stress` holds the mean of the layers) and the thickness;
// zero on the other cells.
struct ShellFields {
  vtkNew<vtkFloatArray> top, bottom, thickness;
  ShellFields() {
    const char* comps[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
    for (vtkFloatArray* a : {top.Get(), bottom.Get()}) {
      a->SetNumberOfComponents(6);
      for (int k = 0; k < 6; ++k)
        a->SetComponentName(k, comps[k]);
    }
    top->SetName("stress_top");
    bottom->SetName("stress_bottom");
    thickness->SetName("thickness");
  }
  static void put(vtkFloatArray* a, const std::array<double, 6>& s) {
    const float t[6] = {static_cast<float>(s[0]), static_cast<float>(s[1]),
                        static_cast<float>(s[2]), static_cast<float>(s[3]),
                        static_cast<float>(s[4]), static_cast<float>(s[5])};
    a->InsertNextTypedTuple(t);
  }
  void add(const solver::ElementResult& t, const solver::ElementResult& b, double h) {
    put(top, t.stress);
    put(bottom, b.stress);
    thickness->InsertNextValue(static_cast<float>(h));
  }
  void pad_to(vtkIdType cells) {
    while (thickness->GetNumberOfTuples() < cells)
      add({}, {}, 0.0);
  }
  void attach(vtkUnstructuredGrid* g) {
    for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{top, bottom, thickness})
      g->GetCellData()->AddArray(a);
  }
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
  for (const solver::spg::Domain& d : s.spg)
    for (std::size_t i = 0; i < d.particles.nodes.size(); ++i)
      added->SetValue(d.particles.nodes[i], added->GetValue(d.particles.nodes[i]) +
                                                static_cast<float>(d.particles.added_mass[i]));
  grid->GetPointData()->AddArray(mass);
  grid->GetPointData()->AddArray(added);

  CellFields fields;
  vtkIdType hex[8];
  const solver::Solids& so = s.solids;
  for (const solver::SolidBlock& block : so.blocks) {
    const int part_id = static_cast<int>(s.parts[static_cast<std::size_t>(block.part)].id);
    for (Index e = block.begin; e < block.end; ++e) {
      const auto i = static_cast<std::size_t>(e);
      if (so.eroded[i]) continue;
      for (int c = 0; c < 8; ++c)
        hex[c] = so.nodes[i][static_cast<std::size_t>(c)];
      grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      fields.add(solver::element_result(s, block, e), so.pressure[i], so.temperature[i], part_id);
    }
  }
  // Deformable shells (quadrilaterals, triangles) with their layer fields.
  const solver::Shells& sh = s.shells;
  const bool shells = sh.count() > 0;
  ShellFields shell_fields;
  if (shells) shell_fields.pad_to(grid->GetNumberOfCells());
  for (const solver::ShellBlock& block : sh.blocks) {
    const int part_id = static_cast<int>(s.parts[static_cast<std::size_t>(block.part)].id);
    for (Index e = block.begin; e < block.end; ++e) {
      const auto i = static_cast<std::size_t>(e);
      if (sh.eroded[i]) continue;
      const auto& q = sh.nodes[i];
      vtkIdType quad[4] = {q[0], q[1], q[2], q[3]};
      grid->InsertNextCell(q[3] == q[2] ? VTK_TRIANGLE : VTK_QUAD, q[3] == q[2] ? 3 : 4, quad);
      const solver::ElementResult mid =
          solver::shell_result(s, block, e, solver::ShellSurface::all);
      fields.add(mid, -(mid.stress[0] + mid.stress[1] + mid.stress[2]) / 3.0, sh.temperature[i],
                 part_id);
      shell_fields.add(solver::shell_result(s, block, e, solver::ShellSurface::top),
                       solver::shell_result(s, block, e, solver::ShellSurface::bottom),
                       sh.thickness[i]);
    }
  }
  // Deformable beams (lines) with their resultants.
  const solver::Beams& bm = s.beams;
  const bool beams = bm.count() > 0;
  BeamFields beam_fields;
  if (beams) beam_fields.pad_to(grid->GetNumberOfCells());
  for (const solver::BeamBlock& block : bm.blocks) {
    const int part_id = static_cast<int>(s.parts[static_cast<std::size_t>(block.part)].id);
    for (Index e = block.begin; e < block.end; ++e) {
      const auto i = static_cast<std::size_t>(e);
      if (bm.eroded[i]) continue;
      const vtkIdType line[2] = {bm.nodes[i][0], bm.nodes[i][1]};
      grid->InsertNextCell(VTK_LINE, 2, line);
      const solver::ElementResult r = solver::beam_result(s, block, e);
      fields.add(r, -(r.stress[0] + r.stress[1] + r.stress[2]) / 3.0, bm.temperature[i], part_id);
      beam_fields.add(s, block, e);
    }
  }
  // SPG particles: one vertex cell each, with the fields of their integration point.
  for (const solver::spg::Domain& d : s.spg) {
    const int part_id = static_cast<int>(s.parts[static_cast<std::size_t>(d.part)].id);
    for (Index i = 0; i < d.count(); ++i) {
      const vtkIdType vertex = d.particles.nodes[static_cast<std::size_t>(i)];
      grid->InsertNextCell(VTK_VERTEX, 1, &vertex);
      const auto ii = static_cast<std::size_t>(i);
      const int state = d.fields.debris[ii]     ? 3
                        : d.kernel.isolated[ii] ? 2
                        : d.kernel.pinned[ii]   ? 1
                                                : 0;
      fields.add(solver::particle_result(d, i), d.fields.pressure[ii], d.fields.temperature[ii],
                 part_id, d.kernel.bonds.damage(i), state, d.fields.step[ii]);
    }
  }
  const solver::DisplayCells& rc = s.rigid_cells;
  const solver::ElementResult none;
  for (std::size_t k = 0; k < rc.solids.size(); ++k) {
    for (int c = 0; c < 8; ++c)
      hex[c] = rc.solids[k][static_cast<std::size_t>(c)];
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
    fields.add(none, 0.0, 0.0,
               static_cast<int>(s.parts[static_cast<std::size_t>(rc.solid_parts[k])].id));
  }
  for (std::size_t k = 0; k < rc.shells.size(); ++k) {
    const auto& q = rc.shells[k];
    vtkIdType quad[4] = {q[0], q[1], q[2], q[3]};
    if (q[3] == q[2])
      grid->InsertNextCell(VTK_TRIANGLE, 3, quad);
    else
      grid->InsertNextCell(VTK_QUAD, 4, quad);
    fields.add(none, 0.0, 0.0,
               static_cast<int>(s.parts[static_cast<std::size_t>(rc.shell_parts[k])].id));
  }
  fields.attach(grid);
  if (shells) {
    shell_fields.pad_to(grid->GetNumberOfCells());
    shell_fields.attach(grid);
  }
  if (beams) {
    beam_fields.pad_to(grid->GetNumberOfCells());
    beam_fields.attach(grid);
  }

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

void VtkSeries::write_collection(const std::vector<std::pair<double, std::string>>& entries) const {
  std::string text = "<?xml version=\"1.0\"?>\n";
  text += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  text += "  <Collection>\n";
  for (const auto& [t, file] : entries)
    text += fmt::format("    <DataSet timestep=\"{:.9e}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                        file);
  text += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(collection(), text);
}

}  // namespace mcdyna::io
