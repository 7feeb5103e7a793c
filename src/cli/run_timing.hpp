#pragma once
/// The timing table that ends a run's summary: seconds per phase, element and particle rates.
#include <iosfwd>

#include "core/communicator.hpp"
#include "solver/run/driver.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

/// `comm`: the run's processes (over several the exchange row shows, and every phase the least
/// and the most any process took; collective); `restarted`: the core time of the run's parts is
/// added.
void print_timing(std::ostream& summary, const solver::RunResult& result,
                  const solver::State& state, const core::Communicator& comm, bool restarted);

}  // namespace mcdyna::cli
