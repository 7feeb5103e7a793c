#pragma once
/// The element pass over deformable solids: strain rate, stress update, internal and hourglass
/// forces per corner, critical time step and mass scaling, erosion. One OpenMP loop per block;
/// every element writes only its own data, so results do not depend on the thread count.
#include "solver/fe/element_loop.hpp"  // ElementPassResult
#include "solver/solids/solids.hpp"

namespace mcdyna::solver {

struct ElementPassInput {
  double step = 0.0;               ///< dt the current velocities were integrated over (0 at start)
  double scale_factor = 0.9;       ///< TSSFAC
  double mass_scaling_step = 0.0;  ///< target dt with mass scaling (TSSFAC*|DT2MS|), 0 = off
};

ElementPassResult solid_element_pass(State& state, Solids& solids, const ElementPassInput& input);

/// Sums corner forces into nodal forces (gather over Solids::node_corners). Adds to `f.force`.
void gather_solid_forces(const State& state, const Solids& solids, NodalForces& f);

}  // namespace mcdyna::solver
