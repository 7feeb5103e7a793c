#pragma once
/// What `mcdyna run` needs to know about the processes of a run over several (issue 25): the
/// per-process restart file names, the stop of all when one fails alone before the time loop,
/// and whether the process count fits the model.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "core/communicator.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

/// Stops every process with `code` (MPI_Abort) when there are several; returns `code`.
int stop_all(const core::Communicator& comm, int code, std::ostream& err);
/// d3dump01 -> d3dump01.0003 on process 3 of several; the plain name on one process.
std::filesystem::path process_file(const std::filesystem::path& path,
                                   const core::Communicator& comm);
/// " on each of N processes", or "" on one process.
std::string processes_text(const core::Communicator& comm);
/// Why the run cannot go over these processes, or "": more processes than deformable elements
/// and particles, or `--spg-angular-budget` (`angular_budget`) or `--step-log` (`step_log`) over
/// several.
std::string process_problem(const solver::State& s, const core::Communicator& comm,
                            bool angular_budget, bool step_log);

}  // namespace mcdyna::cli
