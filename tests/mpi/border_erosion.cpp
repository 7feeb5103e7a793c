// Run under mpiexec with 2 and 4 processes (tests/CMakeLists.txt): the eroding bar
// (tests/data/mpi/eroding_bar.k), whose weak middle slabs lie on the border of the
// decomposition's first cut. Every process counts the hexahedra it computes; an element
// computed by two or more processes is on a border. The test passes when at least one border
// element eroded, and when every process holds the same erosion flags for the elements it
// computes (a border element erodes on every process that computes it, in the same cycle).
// tests/mpi/same_bits.sh checks the histories of the same deck against one process.
#include <mpi.h>

#include <cstdio>
#include <vector>

#include "compiled_deck.hpp"
#include "core/communicator.hpp"
#include "solver/run/driver.hpp"
#include "solver/solids/solids.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: border_erosion DECK\n");
    return 2;
  }
  MPI_Init(&argc, &argv);
  const auto world = mcdyna::core::Communicator::world();
  std::unique_ptr<mcdyna::solver::State> s = compiled_deck(argv[1]);
  const mcdyna::solver::RunResult result = mcdyna::solver::run(*s, {});
  const auto n = static_cast<int>(mcdyna::solver::solids_of(*s).count());
  // Per element: how many processes compute it, and how many of them found it eroded.
  std::vector<int> computed(static_cast<std::size_t>(n)), eroded(computed.size());
  for (int e = 0; e < n; ++e) {
    const bool here = s->ownership.computes_element(e);
    computed[static_cast<std::size_t>(e)] = here ? 1 : 0;
    eroded[static_cast<std::size_t>(e)] =
        here && mcdyna::solver::solids_of(*s).eroded[static_cast<std::size_t>(e)];
  }
  MPI_Allreduce(MPI_IN_PLACE, computed.data(), n, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, eroded.data(), n, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  int total = 0, border = 0, split = 0;
  for (int e = 0; e < n; ++e) {
    const auto i = static_cast<std::size_t>(e);
    if (eroded[i] > 0) ++total;
    if (eroded[i] > 0 && computed[i] > 1) ++border;
    if (eroded[i] > 0 && eroded[i] != computed[i]) ++split;  // eroded on some copies only
  }
  const bool ok = result.reason == mcdyna::solver::StopReason::end_time && border > 0 &&
                  split == 0 && world.size() > 1;
  if (world.rank() == 0)
    std::printf(
        "%d processes: %d of %d elements eroded, %d of them on a border, %d eroded on "
        "some of their processes only: %s\n",
        world.size(), total, n, border, split, ok ? "pass" : "FAIL");
  MPI_Finalize();
  return ok ? 0 : 1;
}
