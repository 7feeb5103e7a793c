#include "cli/processes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include <string>

#include "solver/block.hpp"

namespace mcdyna::cli {

// Over several processes a failure one of them meets alone before the time loop: the others
// would wait for it in the loop's first exchange, so it stops them all (MPI_Abort).
int stop_all(const core::Communicator& comm, int code, std::ostream& err) {
  err.flush();
  if (comm.size() > 1) comm.abort(code);
  return code;
}

// Each process of a run over several writes and reads its own restart dump: d3dump01.0000,
// d3dump01.0001, ... as LS-DYNA MPP names them; one process keeps the plain name.
std::filesystem::path process_file(const std::filesystem::path& path,
                                   const core::Communicator& comm) {
  if (comm.size() == 1) return path;
  return std::filesystem::path(path.string() + fmt::format(".{:04d}", comm.rank()));
}

std::string processes_text(const core::Communicator& comm) {
  return comm.size() > 1 ? fmt::format(" on each of {} processes", comm.size()) : std::string();
}

// Every process needs a share of the deformable elements and particles.
std::string process_problem(const solver::State& s, const core::Communicator& comm,
                            bool angular_budget, bool step_log) {
  // The budget reads every particle's velocities every cycle and the step log any particle's
  // kernel row; over several processes each holds current values for its own particles and
  // the rows it reads only (spg/distribution.hpp).
  if (angular_budget && comm.size() > 1)
    return "--spg-angular-budget runs on one process only; run it without mpirun";
  if (step_log && comm.size() > 1)
    return "--step-log runs on one process only; run it without mpirun";
  if (comm.size() > 1)
    for (const auto& b : s.blocks)
      if (const std::string what = b->one_process_only(); !what.empty())
        return fmt::format(
            "{} run on one process only; run without mpirun (--threads N uses the cores of one "
            "machine)",
            what);
  long entities = 0;
  for (const auto& b : s.blocks)
    entities += b->elements() + b->particles();
  if (comm.size() <= std::max(entities, 1L)) return {};
  return fmt::format(
      "{} processes for {} deformable element(s) and SPG particle(s): each process needs at "
      "least one; run with mpirun -np {} or fewer",
      comm.size(), entities, std::max(entities, 1L));
}

}  // namespace mcdyna::cli
