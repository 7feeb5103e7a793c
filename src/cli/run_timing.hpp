#pragma once
/// The timing table that ends a run's summary: seconds per phase, element and particle rates.
#include <iosfwd>

#include "solver/driver.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

/// `processes`: of the run (the exchange row shows over several); `restarted`: the core time of
/// the run's parts is added.
void print_timing(std::ostream& summary, const solver::RunResult& result,
                  const solver::State& state, int processes, bool restarted);

}  // namespace mcdyna::cli
