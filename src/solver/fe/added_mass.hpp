#pragma once
/// DT2MS mass scaling gives elements added mass; the nodes take their corners' shares.
#include "solver/state.hpp"

namespace mcdyna::solver {

/// Nodal added mass from every block's elements (Block::spread_added_mass: the solids' 1/8 per
/// corner, the shells' 1/4 or a triangle's 1/3, the beams' 1/2), each in its fixed gather order.
void refresh_added_mass(State& s);

}  // namespace mcdyna::solver
