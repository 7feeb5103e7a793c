#pragma once
/// The deformable shells' data: what the shells' block owns (shell_block.cpp) and the accessors
/// through which the formulations compiled after it and the outputs read it.
#include <memory>

#include "solver/fe/hourglass.hpp"
#include "solver/fe/shell_points.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

class Block;           // block.hpp
class CompiledBlocks;  // block.hpp

enum class ShellFormulation {
  belytschko_tsay,   ///< ELFORM 2: one in-plane point, corotational, hourglass control
  fully_integrated,  ///< ELFORM 16: 2x2 in-plane points, assumed transverse shear strain
  c0_triangle,       ///< ELFORM 4: three-node Mindlin triangle, MITC3 shear (shell_c0_triangle.hpp)
};

/// How a shell's thickness follows its strain (*CONTROL_SHELL ISTUPD).
enum class ThicknessUpdate { none, membrane, plastic };

/// Shell elements of one part: a contiguous range [begin, end) of the shell arrays.
/// Integration points are numbered element by element, in-plane point by in-plane point, layer
/// by layer (bottom to top).
struct ShellBlock {
  Index part = 0;
  Index begin = 0, end = 0;
  Index point_begin = 0;
  int in_plane_points = 1;  ///< 1 (ELFORM 2) or 4 (ELFORM 16)
  int layers = 2;           ///< NIP: points through the thickness
  ShellFormulation formulation = ShellFormulation::belytschko_tsay;
  /// *CONTROL_SHELL ESORT >= 1: the block's triangles run as C0 triangles, not as degenerate
  /// quadrilaterals of its formulation.
  bool sort_triangles = false;
  Index material = 0;
  HourglassParams hourglass;       ///< IHQ, QM (membrane)
  double bending_hourglass = 0.1;  ///< QB
  double warping_hourglass = 0.1;  ///< QW
  double shear_factor = 1.0;       ///< SHRF
  /// *CONTROL_SHELL ISTUPD: constant (0), from the membrane thickness strain (1, 3) or from its
  /// plastic part only (4).
  ThicknessUpdate thickness_update = ThicknessUpdate::none;
  int plane_stress_iterations = 3;  ///< secant steps of the plane-stress return (MITER)
  /// NLOC: where the nodes sit through the thickness, 0 mid-surface, 1 top, -1 bottom (the
  /// layers sit at z = (zeta - NLOC) t / 2 from the nodes' surface).
  double reference_surface = 0.0;
  /// Layer positions through the thickness in [-1, 1] (bottom to top) and their weights
  /// (summing to 2): Gauss (QR 0) or trapezoidal (QR 1).
  std::array<double, 10> layer_z{}, layer_weight{};
};

/// Deformable 3- and 4-node shells (a triangle repeats its third node).
struct Shells {
  std::vector<model::Id> ids;
  std::vector<std::array<Index, 4>> nodes;
  std::vector<Index> part;
  std::vector<double> initial_thickness, thickness;  ///< length
  std::vector<double> initial_area, mass;
  /// Rotary inertia each corner gives its node: the corner's mass times max(t^2 / 12, A / 8)
  /// (Belytschko, Lin and Tsay 1984) times *CONTROL_SHELL ROTASCL.
  std::vector<double> corner_inertia;
  std::vector<double> temperature;       ///< JC adiabatic temperature
  std::vector<double> internal_energy;   ///< absolute
  std::vector<double> hourglass_energy;  ///< absolute
  /// 5 per element: the hourglass resistances of the last pass, membrane x y, bending x y and
  /// warping (Belytschko-Tsay's Q^M, Q^B, Q^W).
  std::vector<double> hourglass_force;
  std::vector<double> time_step, added_mass;
  std::vector<std::uint8_t> eroded;
  /// 24 per element: force (3) then moment (3) on each corner node, global axes, this cycle.
  std::vector<double> corner_force;
  std::vector<ShellBlock> blocks;
  ShellPoints points;
  /// Node -> (element * 4 + corner) of the elements that touch it, in element order: the fixed
  /// order of the gather of their forces and moments (node_corners[corner_offsets[n] ..
  /// corner_offsets[n + 1]) for node n).
  std::vector<Index> corner_offsets, node_corners;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

/// The block of the deck's deformable shells (compile_shells.cpp makes it when there are some).
std::unique_ptr<Block> make_shell_block(Shells shells);

/// The shells' data, or an empty Shells when the deck has none: at run time from the state's
/// blocks, during compile from the blocks compiled before (the contact sides).
const Shells& shells_of(const State& s);
const Shells& shells_of(const CompiledBlocks& before);

}  // namespace mcdyna::solver
