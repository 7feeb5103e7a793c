#pragma once
/// DT2MS mass scaling gives elements added mass; the nodes take their corners' shares.
#include "solver/state.hpp"

namespace mcdyna::solver {

/// Nodal added mass from the solids' (1/8 per corner) and the shells' (1/4, a triangle's 1/3)
/// added mass, gathered in the fixed corner order.
void refresh_added_mass(State& s);

}  // namespace mcdyna::solver
