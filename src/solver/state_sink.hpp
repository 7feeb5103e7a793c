#pragma once
/// What a block shows in a state output: its cells, in the blocks' order, each with the fields
/// every cell carries, and fields of the block's own (a shell's layer stresses, a beam's
/// resultants) that the other cells carry as zeros. A block shows every cell of every state, its
/// eroded ones flagged `deleted`, so that the cells of each state are the same list. io/
/// implements the sinks (io/vtk_series.cpp leaves the deleted cells out; io/d3plot/ keeps them
/// with LS-DYNA's deletion flag); the blocks know nothing of the file formats.
#include <initializer_list>
#include <string_view>

#include "model/entities.hpp"
#include "solver/results.hpp"

namespace mcdyna::solver {

enum class CellShape { hexahedron, quadrilateral, triangle, line, vertex };

/// The number of nodes a cell of `shape` names.
constexpr int cell_nodes(CellShape shape) {
  switch (shape) {
    case CellShape::hexahedron:
      return 8;
    case CellShape::quadrilateral:
      return 4;
    case CellShape::triangle:
      return 3;
    case CellShape::line:
      return 2;
    case CellShape::vertex:
      return 1;
  }
  return 0;
}

/// The fields every cell carries.
struct CellValues {
  ElementResult result;  ///< stress (global axes), von Mises, plastic strain, damage
  double pressure = 0.0;
  double temperature = 0.0;
  model::Id part = 0;
  double bond_damage = 0.0;  ///< SPG: share of the particle's bonds broken
  /// SPG: 0 smoothed (MC-SPG), 1 pinned, 2 isolated, 3 debris; -1 for the other cells
  int particle_state = -1;
  double step = 0.0;     ///< SPG: the particle's stable step at its last stress update
  model::Id id = 0;      ///< the element's user ID (a particle: its node's)
  bool deleted = false;  ///< eroded
};

class StateSink {
 public:
  virtual ~StateSink() = default;
  /// A field of the block's own, declared before its first cell (and also when it shows none,
  /// so that every state of a series has the same fields).
  virtual void declare(std::string_view name, std::initializer_list<const char*> components) = 0;
  /// A cell: its shape, its nodes (solver indices, cell_nodes(shape) of them) and the common
  /// fields; the value() calls that follow belong to it.
  virtual void cell(CellShape shape, const Index* nodes, const CellValues& values) = 0;
  /// The last cell's value of a declared field (one number per component).
  virtual void value(std::string_view name, const double* values) = 0;
};

}  // namespace mcdyna::solver
