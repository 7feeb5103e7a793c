#pragma once
/// The deformable beams' data: its block owns it (beam_block.cpp), made by the beams' compile
/// pass (compile_beams.cpp).
#include <array>
#include <memory>
#include <vector>

#include "solver/fe/shell_points.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

enum class BeamFormulation {
  hughes_liu,         ///< ELFORM 1: fibres over the cross section, one point along the length
  belytschko_schwer,  ///< ELFORM 2: elastic resultants, cubic bending (exact end moments)
};

/// Beam elements of one part: a contiguous range [begin, end) of the beam arrays. Hughes-Liu
/// points are numbered element by element, section point by section point.
struct BeamBlock {
  Index part = 0;
  Index begin = 0, end = 0;
  Index point_begin = 0;
  int points = 0;  ///< cross-section points (0: resultant beam)
  BeamFormulation formulation = BeamFormulation::hughes_liu;
  Index material = 0;
  double shear_factor = 1.0;        ///< SHRF (Hughes-Liu); the resultant beam takes SA instead
  int constrained_iterations = 30;  ///< secant steps of the uniaxial-stress return
  /// Section points: s and t as fractions of the element's section widths, weights as fractions
  /// of its area (rectangle: Gauss or Lobatto in both; tube: a ring).
  std::array<double, 16> point_s{}, point_t{}, point_weight{};
};

/// Deformable 2-node beams. Local axes r (N1 -> N2), s (from N3 or the orientation vector,
/// carried by the mean spin of the nodes), t = r x s.
struct Beams {
  std::vector<model::Id> ids;
  std::vector<std::array<Index, 2>> nodes;
  std::vector<Index> part;
  Eigen::Matrix3Xd s_axis;  ///< unit, current
  std::vector<double> initial_length, mass;
  /// Section: area, moments of inertia about s and t, torsion constant, shear area (resultant
  /// beam), and the widths that scale the Hughes-Liu points (rectangle TS, TT; tube the ring
  /// diameter twice).
  std::vector<double> area, inertia_s, inertia_t, torsion, shear_area, width_s, width_t;
  /// Rotary inertia each end gives its node, and the stable step of the bending and torsion
  /// modes at the initial length (scaled by L / L0 as the beam stretches).
  std::vector<double> end_inertia, flexural_step;
  /// 6 per element: resultants in the local axes. Hughes-Liu: N, V_s, V_t, T, M_s, M_t of the
  /// last pass. Belytschko-Schwer: N, T, M_s at N1, M_s at N2, M_t at N1, M_t at N2 (its state).
  std::vector<double> resultants;
  std::vector<double> temperature;      ///< room temperature (no heating in beams)
  std::vector<double> internal_energy;  ///< absolute
  std::vector<double> time_step, added_mass;
  std::vector<std::uint8_t> eroded;
  /// 12 per element: force (3) then moment (3) on each end node, global axes, this cycle.
  std::vector<double> corner_force;
  std::vector<BeamBlock> blocks;
  ShellPoints points;  ///< Hughes-Liu fibres: stress xx, xy, zx in the local axes (r s t)
  /// Node -> (element * 2 + end) of the beams that touch it, in element order (the gather of
  /// their end forces and moments, fixed order as for the solids).
  std::vector<Index> end_offsets, ends;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

class Block;
/// The beams' block, owning `beams` (beam_block.cpp).
std::unique_ptr<Block> make_beams_block(Beams beams);
/// The beams of a compiled state (its beams block's), or nullptr when it has none: for tests
/// and tools that read them after a run.
const Beams* beams_of(const State& s);

}  // namespace mcdyna::solver
