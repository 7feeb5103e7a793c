#include "cli/run_timing.hpp"

#include "solver/block.hpp"
#include "solver/spg/spg_parts.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <omp.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace mcdyna::cli {

void print_timing(std::ostream& summary, const solver::RunResult& result,
                  const solver::State& state, const core::Communicator& comm, bool restarted) {
  const int processes = comm.size();
  // Over several processes each phase also shows the least and the most any process took: a
  // process that computes more makes the others wait at the next exchange, so an imbalance
  // shows as one process's compute against the other's exchange.
  std::vector<double> all(result.phases.seconds.begin(), result.phases.seconds.end());
  if (processes > 1) all = comm.all_gather(all);
  const auto range = [&](int phase) {
    double least = all[static_cast<std::size_t>(phase)], most = least;
    for (std::size_t k = static_cast<std::size_t>(phase); k < all.size();
         k += solver::PhaseTimes::kCount) {
      least = std::min(least, all[k]);
      most = std::max(most, all[k]);
    }
    return std::pair{least, most};
  };
  fmt::print(summary, "\nTiming per phase (wall clock, {} thread(s){})\n", omp_get_max_threads(),
             processes > 1 ? fmt::format(" on each of {} processes; process 0, and the least and "
                                         "the most of any process",
                                         processes)
                           : std::string());
  for (int p = 0; p < solver::PhaseTimes::kCount; ++p) {
    const double sec = result.phases.seconds[static_cast<std::size_t>(p)];
    // SPG rows only for decks with SPG parts, the contact row only for decks with contact.
    if (p == solver::PhaseTimes::contact) {
      if (std::none_of(state.blocks.begin(), state.blocks.end(),
                       [](const auto& b) { return b->phase() == solver::PhaseTimes::contact; }))
        continue;
    } else if (p == solver::PhaseTimes::exchange) {
      if (processes == 1) continue;
    } else if (p >= solver::PhaseTimes::spg_neighbours && solver::spg::domains_of(state).empty()) {
      continue;
    }
    fmt::print(summary, "  {:<22}{:10.3f} s {:6.1f} %", solver::PhaseTimes::name(p), sec,
               result.wall_seconds > 0 ? 100.0 * sec / result.wall_seconds : 0.0);
    if (processes > 1) {
      const auto [least, most] = range(p);
      fmt::print(summary, "  {:9.3f} - {:.3f} s", least, most);
    }
    fmt::print(summary, "\n");
  }
  fmt::print(summary, "  {:<22}{:10.3f} s\n", "total", result.wall_seconds);
  // A restarted run may have run its parts on different thread counts: its cost in core time.
  if (restarted)
    fmt::print(summary, "  {:<22}{:10.3f} s (wall x threads over the run's parts)\n", "core time",
               result.core_seconds);
  if (result.element_cycles > 0) {
    fmt::print(summary, "  {:.3f} million element-cycles/s\n",
               1e-6 * result.element_cycles / result.wall_seconds);
  }
  if (result.particle_cycles > 0) {
    fmt::print(summary, "  {:.3f} million particle-steps/s\n",
               1e-6 * result.particle_cycles / result.wall_seconds);
  }
}

}  // namespace mcdyna::cli
