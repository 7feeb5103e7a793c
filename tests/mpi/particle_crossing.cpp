// Run under mpiexec with 2 and 3 processes (tests/CMakeLists.txt): the coarse SPG Taylor bar
// for 60 cycles (renewals at cycles 15, 30, 45, 60). Its free particles are bisected again by their
// current positions at every kernel renewal (spg/distribution.hpp), so as the bar shortens and
// spreads on the wall the particles near a cut move to the other process with their rows, bonds and
// material state. The test passes when particles changed process during the run, every particle has
// exactly one owner at the end, each process keeps exactly the kernel rows it reads (its stressed
// rows, fewer than all), the transposes of its own particles are complete (as many pairs as the
// rows of all processes' own particles hold them), and the run ended normally.
// tests/mpi/same_bits.sh checks that the histories of the same deck keep the bits of one process.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "compiled_deck.hpp"
#include "core/communicator.hpp"
#include "solver/run/decomposition.hpp"
#include "solver/run/driver.hpp"
#include "solver/spg/spg_parts.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: particle_crossing DECK CYCLES\n");
    return 2;
  }
  MPI_Init(&argc, &argv);
  const auto world = mcdyna::core::Communicator::world();
  std::unique_ptr<mcdyna::solver::State> s = compiled_deck(argv[1]);
  if (mcdyna::solver::spg::domains_of(*s).empty()) {
    std::fprintf(stderr, "%s has no SPG part\n", argv[1]);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  s->time_control.end_cycle = std::atol(argv[2]);
  const mcdyna::solver::RunResult result = mcdyna::solver::run(*s, {});
  // The owners the run started with: the decomposition of the initial positions.
  const mcdyna::solver::parallel::Decomposition start =
      mcdyna::solver::parallel::decompose(*s, world.size());
  const mcdyna::solver::spg::Domain& dom = mcdyna::solver::spg::domain_of(*s, 0);
  const mcdyna::solver::parallel::ParticleShare* share = s->ownership.split_part(0);
  const auto n = static_cast<int>(dom.count());
  int moved = 0, owned = 0;
  std::vector<int> owners(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n && share != nullptr; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (share->owner[jj] != start.owner[static_cast<std::size_t>(dom.particles.nodes[jj])]) ++moved;
    owners[jj] = share->owned.flag[jj];
  }
  MPI_Allreduce(MPI_IN_PLACE, owners.data(), n, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (const int k : owners)
    if (k == 1) ++owned;
  // Rows kept here against rows read here, and how often each particle sits in an own row.
  int kept = 0, misplaced = 0;
  std::vector<int> in_rows(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n && share != nullptr; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const bool has_row = dom.kernel.list.count(j) > 0;
    kept += has_row ? 1 : 0;
    if (has_row != (share->stressed.flag[jj] != 0)) ++misplaced;
    if (!share->owned.flag[jj]) continue;
    for (int p = dom.kernel.list.offsets[jj]; p < dom.kernel.list.offsets[jj + 1]; ++p)
      ++in_rows[static_cast<std::size_t>(dom.kernel.list.neighbours[static_cast<std::size_t>(p)])];
  }
  MPI_Allreduce(MPI_IN_PLACE, in_rows.data(), n, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  int incomplete = 0;
  for (int j = 0; j < n && share != nullptr; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (share->owned.flag[jj] &&
        dom.kernel.transpose.offsets[jj + 1] - dom.kernel.transpose.offsets[jj] != in_rows[jj])
      ++incomplete;
  }
  int largest_kept = kept;
  MPI_Allreduce(MPI_IN_PLACE, &misplaced, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &incomplete, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &largest_kept, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const bool ok = result.reason == mcdyna::solver::StopReason::end_cycle && share != nullptr &&
                  moved > 0 && owned == n && world.size() > 1 && misplaced == 0 &&
                  incomplete == 0 && largest_kept < n;
  if (world.rank() == 0)
    std::printf(
        "%d processes, %ld cycles: %d of %d particles on another process than at the start, %d "
        "with exactly one owner; at most %d rows kept per process, %d rows kept but not read or "
        "read but not kept, %d own particles with an incomplete transpose: %s\n",
        world.size(), s->cycle, moved, n, owned, largest_kept, misplaced, incomplete,
        ok ? "pass" : "FAIL");
  MPI_Finalize();
  return ok ? 0 : 1;
}
