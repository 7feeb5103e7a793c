#include "post/difference_series.hpp"

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <cstring>

#include "io/checked_file.hpp"
#include "io/vtk_series.hpp"

namespace mcdyna::post {

namespace {

constexpr double kNotCompared = 0.0;

vtkNew<vtkDoubleArray> field(const char* name, const std::vector<double>& values, int components) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / components);
  for (std::size_t k = 0; k < values.size(); ++k)
    a->SetValue(static_cast<vtkIdType>(k), values[k]);
  return a;
}

vtkNew<vtkIdTypeArray> ids(const char* name, const std::vector<std::int64_t>& values) {
  vtkNew<vtkIdTypeArray> a;
  a->SetName(name);
  for (const std::int64_t v : values)
    a->InsertNextValue(v);
  return a;
}

}  // namespace

DifferenceSeries::DifferenceSeries(std::filesystem::path dir, const io::d3plot::Reader& b)
    : dir_(std::move(dir)), b_(b) {
  std::filesystem::create_directories(dir_);
}

std::size_t DifferenceSeries::cell(const char* element_class, std::size_t b) const {
  std::size_t offset = 0;
  for (const auto& [name, e] : {std::pair{"solid", &b_.solids()},
                                {"shell", &b_.shells()},
                                {"beam", &b_.beams()},
                                {"particle", &b_.particles()}}) {
    if (std::strcmp(name, element_class) == 0) return offset + b;
    offset += e->count();
  }
  return offset + b;
}

void DifferenceSeries::begin_state(double time_b, const std::vector<double>& x_b) {
  time_ = time_b;
  x_ = x_b;
  const std::size_t nodes = b_.node_ids().size();
  const std::size_t cells =
      b_.solids().count() + b_.shells().count() + b_.beams().count() + b_.particles().count();
  displacement_.assign(3 * nodes, kNotCompared);
  velocity_.assign(3 * nodes, kNotCompared);
  stress_.assign(6 * cells, kNotCompared);
  resultants_.assign(6 * cells, kNotCompared);
  strain_.assign(cells, kNotCompared);
  node_compared_.assign(nodes, 0.0);
  cell_compared_.assign(cells, 0.0);
}

void DifferenceSeries::node(std::size_t b, const char* field_name, const double* a_minus_b) {
  std::vector<double>& to =
      std::strcmp(field_name, "displacement") == 0 ? displacement_ : velocity_;
  for (std::size_t c = 0; c < 3; ++c)
    to[3 * b + c] = a_minus_b[c];
  node_compared_[b] = 1.0;
}

void DifferenceSeries::element(const char* element_class, std::size_t b, const char* field_name,
                               const double* a_minus_b, int components) {
  const std::size_t k = cell(element_class, b);
  cell_compared_[k] = 1.0;
  if (std::strcmp(field_name, "plastic_strain") == 0) {
    strain_[k] = a_minus_b[0];
    return;
  }
  std::vector<double>& to = std::strcmp(field_name, "resultants") == 0 ? resultants_ : stress_;
  for (int c = 0; c < components; ++c)
    to[6 * k + static_cast<std::size_t>(c)] = a_minus_b[c];
}

void DifferenceSeries::end_state() {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const auto nodes = static_cast<vtkIdType>(b_.node_ids().size());
  points->SetNumberOfPoints(nodes);
  for (vtkIdType n = 0; n < nodes; ++n)
    points->SetPoint(n, x_[static_cast<std::size_t>(3 * n)],
                     x_[static_cast<std::size_t>(3 * n + 1)],
                     x_[static_cast<std::size_t>(3 * n + 2)]);
  grid->SetPoints(points);
  std::vector<std::int64_t> element_ids, part_ids;
  for (const io::d3plot::Elements* e : {&b_.solids(), &b_.shells(), &b_.beams(), &b_.particles()})
    for (std::size_t k = 0; k < e->count(); ++k) {
      vtkIdType corner[8];
      for (int c = 0; c < e->corners; ++c)
        corner[c] =
            e->nodes[k * static_cast<std::size_t>(e->corners) + static_cast<std::size_t>(c)];
      int type = VTK_VERTEX, n = 1;
      if (e->corners == 8) {
        type = VTK_HEXAHEDRON;
        n = 8;
      } else if (e->corners == 4) {
        n = corner[3] == corner[2] ? 3 : 4;
        type = n == 3 ? VTK_TRIANGLE : VTK_QUAD;
      } else if (e->corners == 2) {
        type = VTK_LINE;
        n = 2;
      }
      grid->InsertNextCell(type, n, corner);
      element_ids.push_back(e->ids[k]);
      part_ids.push_back(e->parts[k]);
    }
  grid->GetPointData()->AddArray(field("displacement_difference", displacement_, 3));
  grid->GetPointData()->AddArray(field("velocity_difference", velocity_, 3));
  grid->GetPointData()->AddArray(ids("node_id", b_.node_ids()));
  grid->GetPointData()->AddArray(field("compared", node_compared_, 1));
  grid->GetCellData()->AddArray(field("stress_difference", stress_, 6));
  grid->GetCellData()->AddArray(field("resultants_difference", resultants_, 6));
  grid->GetCellData()->AddArray(field("plastic_strain_difference", strain_, 1));
  grid->GetCellData()->AddArray(ids("element_id", element_ids));
  grid->GetCellData()->AddArray(ids("part_id", part_ids));
  grid->GetCellData()->AddArray(field("compared", cell_compared_, 1));
  const std::string name = fmt::format("difference_{:04d}.vtu", entries_.size());
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->WriteToOutputStringOn();
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  if (writer->Write() != 1)
    throw io::WriteError(
        fmt::format("cannot write {}: VTK's writer failed", (dir_ / name).string()));
  io::write_file_atomically(dir_ / name, writer->GetOutputString());
  entries_.emplace_back(time_, name);
  io::write_file_atomically(collection(), io::pvd_collection(entries_));
}

}  // namespace mcdyna::post
