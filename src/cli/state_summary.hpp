#pragma once
/// d3hsp's "Solver state": nodes, blocks, rigid parts, mass and mass scaling, each SPG part's
/// settings, as compiled (and changed by the run's options).
#include <ostream>

#include "solver/state.hpp"

namespace mcdyna::cli {

void print_state_summary(std::ostream& log, const solver::State& s);

}  // namespace mcdyna::cli
