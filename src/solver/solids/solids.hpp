#pragma once
/// The deformable 8-node solids' data: what the hexahedra's block owns (hexahedra_block.cpp) and
/// the accessors through which the formulations compiled after it, the halo and the outputs
/// read it.
#include <memory>

#include "solver/fe/hourglass.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

class Block;           // block.hpp
class CompiledBlocks;  // block.hpp

enum class SolidFormulation {
  one_point,          ///< ELFORM 1: one-point quadrature + Flanagan-Belytschko hourglass control
  selective_reduced,  ///< ELFORM 2: 2x2x2 deviatoric, mean volumetric strain rate (B-bar)
};

/// Solid elements of one part: a contiguous range [begin, end) of the element arrays.
struct SolidBlock {
  Index part = 0;
  Index begin = 0, end = 0;
  Index point_begin = 0;       ///< first integration point of the block
  int points_per_element = 1;  ///< 1 (ELFORM 1) or 8 (ELFORM 2)
  SolidFormulation formulation = SolidFormulation::one_point;
  Index material = 0;
  HourglassParams hourglass;
  BulkViscosityParams bulk_viscosity;
  /// *CONTROL_ACCURACY OSU 1 (or the part in PIDOSU): mid-step strain rates and Hughes-Winget
  /// stress rotation (solid_elements.cpp, point_kinematics.hpp).
  bool objective = false;
};

/// Deformable 8-node solids (rigid-part elements only contribute mass properties).
struct Solids {
  std::vector<model::Id> ids;
  std::vector<std::array<Index, 8>> nodes;
  std::vector<Index> part;
  std::vector<double> initial_volume, volume, mass;
  std::vector<double> pressure;          ///< element pressure (compression positive), stress
  std::vector<double> eos_energy;        ///< internal energy per initial volume (EOS materials)
  std::vector<double> temperature;       ///< JC adiabatic temperature (room temperature otherwise)
  std::vector<double> internal_energy;   ///< absolute, energy
  std::vector<double> hourglass_energy;  ///< absolute, energy
  std::vector<double> hourglass_force;   ///< 12 per element: hourglass resistance of the last pass
  std::vector<double> viscosity;         ///< bulk viscosity q of the last pass, stress
  std::vector<double> time_step;         ///< last critical step estimate (before TSSFAC)
  std::vector<double> added_mass;        ///< DT2MS mass given to the element so far
  std::vector<std::uint8_t> eroded;
  std::vector<double> corner_force;  ///< 24 per element: force on each corner node, this cycle
  std::vector<SolidBlock> blocks;
  MaterialPoints points;  ///< integration-point state (stress, plastic strain, ...)
  /// Node -> (element * 8 + corner) of the elements that touch it, in element order: the fixed
  /// summation order that makes the force gather bitwise reproducible (node_corners[
  /// corner_offsets[n] .. corner_offsets[n + 1]) for node n).
  std::vector<Index> corner_offsets, node_corners;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

/// The block of the deck's hexahedra (compile_solids.cpp makes it when there are some).
std::unique_ptr<Block> make_hexahedra_block(Solids solids);

/// The hexahedra's data, or an empty Solids when the deck has none: at run time from the state's
/// blocks, during compile from the blocks compiled before (the contact sides, the SPG parts).
const Solids& solids_of(const State& s);
const Solids& solids_of(const CompiledBlocks& before);
/// The same to write (the halo's gather of the values another process computed), or nullptr.
Solids* solids_in(State& s);

}  // namespace mcdyna::solver
