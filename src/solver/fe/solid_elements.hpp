#pragma once
/// The element pass over deformable solids: strain rate, stress update, internal and hourglass
/// forces per corner, critical time step and mass scaling, erosion. One OpenMP loop per block;
/// every element writes only its own data, so results do not depend on the thread count.
#include "solver/state.hpp"

namespace mcdyna::solver {

struct ElementPassInput {
  double step = 0.0;               ///< dt the current velocities were integrated over (0 at start)
  double scale_factor = 0.9;       ///< TSSFAC
  double mass_scaling_step = 0.0;  ///< target dt with mass scaling (TSSFAC*|DT2MS|), 0 = off
};

struct ElementPassResult {
  double critical_step = 0.0;  ///< min over elements of the element step (before TSSFAC)
  Index controlling = -1;      ///< element giving it (lowest index on ties)
  Index inverted = -1;         ///< lowest element with non-positive volume, or -1
  Index non_finite = -1;       ///< lowest element with a NaN/Inf state (its step), or -1
  Index newly_eroded = 0;
  bool mass_changed = false;  ///< mass scaling added mass this pass
};

ElementPassResult solid_element_pass(State& state, const ElementPassInput& input);

/// Sums corner forces into nodal forces (gather over Nodes::corners). Adds to `force`.
void gather_solid_forces(State& state);

}  // namespace mcdyna::solver
