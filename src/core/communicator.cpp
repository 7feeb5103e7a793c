#include "core/communicator.hpp"

#ifdef MCDYNA_WITH_MPI
#include <mpi.h>
#endif

#include <array>
#include <cstdint>

namespace mcdyna::core {

Communicator Communicator::world() {
#ifdef MCDYNA_WITH_MPI
  int initialised = 0;
  MPI_Initialized(&initialised);
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (initialised && !finalised) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return {rank, size, true};
  }
#endif
  return {0, 1, false};
}

double Communicator::sum(const ExactSum& partial) const {
  ExactSum total = partial;
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    // The limbs (each below 2^32 but the top one) summed as integers over the processes, and
    // the non-finite counts beside them; the result is the partials' exact sum.
    const ExactSum::Parts mine = total.parts();
    ExactSum::Parts all{};
    MPI_Allreduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_INT64_T, MPI_SUM,
                  MPI_COMM_WORLD);
    total = ExactSum::from_parts(all);
  }
#endif
  return total.value();
}

double Communicator::min(double value) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    double smallest = value;
    MPI_Allreduce(&value, &smallest, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    return smallest;
  }
#endif
  return value;
}

}  // namespace mcdyna::core
