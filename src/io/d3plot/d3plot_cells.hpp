#pragma once
/// One state's cells as the blocks show them (solver/state_sink.hpp), sorted into d3plot's
/// element classes with each element's state words in LS-DYNA's order:
///  - solids (hexahedra, the rigid parts' too): sigma xx yy zz xy yz zx, effective plastic
///    strain (NV3D = 7);
///  - beams: axial force, shear s, shear t, moment s, moment t, torsion (NV1D = 6);
///  - shells (quadrilaterals, triangles as LS-DYNA's degenerate quadrilateral): three layers,
///    mid-surface, inner (bottom) and outer (top) surface, each sigma xx yy zz xy yz zx and
///    effective plastic strain, then thickness, two element-dependent words (written 0) and
///    internal energy per volume (NV2D = 3 x 7 + 4; no force resultants, IOSHL3 999).
///  - SPG particles (vertex cells), in d3plot's SPH particle section: the part number, then
///    pressure, sigma xx yy zz xy yz zx, effective plastic strain, and two history words: the
///    share of the particle's bonds broken and how it is integrated (0 smoothed, 1 pinned,
///    2 isolated, 3 debris) (NUMSPH = 11).
#include <array>
#include <string_view>
#include <vector>

#include "model/entities.hpp"
#include "solver/state_sink.hpp"

namespace mcdyna::io::d3plot {

using solver::Index;

inline constexpr int kSolidWords = 7;
inline constexpr int kBeamWords = 6;
inline constexpr int kShellLayers = 3;  ///< MAXINT
inline constexpr int kShellWords = kShellLayers * 7 + 4;
inline constexpr int kParticleWords = 10;  ///< after the part number: NUMSPH - 1

/// The elements of one d3plot class: their nodes (`corners` solver indices each), user IDs,
/// parts (user IDs), deletion, and `words` state words each.
struct ElementClass {
  int corners = 0;
  int words = 0;
  std::vector<Index> nodes;
  std::vector<model::Id> ids, parts;
  std::vector<std::uint8_t> deleted;
  std::vector<double> values;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

class StateCells final : public solver::StateSink {
 public:
  StateCells();
  void declare(std::string_view name, std::initializer_list<const char*> components) override;
  void cell(solver::CellShape shape, const Index* nodes, const solver::CellValues& v) override;
  void value(std::string_view name, const double* values) override;

  ElementClass solids, beams, shells;
  ElementClass particles;  ///< one node each; `values` without the part number

 private:
  ElementClass* last_ = nullptr;  ///< the class of the last cell (its own fields follow)
};

}  // namespace mcdyna::io::d3plot
