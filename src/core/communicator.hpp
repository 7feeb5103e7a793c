#pragma once
/// The processes of a run (issue 25). Built with MPI (MCDYNA_WITH_MPI, CMake option MCDYNA_MPI
/// and an MPI found) it is MPI_COMM_WORLD, which the caller has initialised; built without, or
/// before MPI is initialised, it is this one process.
///
/// Reductions keep their bits for any process count: a sum goes through core::ExactSum, whose
/// partials merge by integer addition (an MPI_SUM over its limbs is exact and associative), and
/// a minimum is exact by nature.
#include "core/exact_sum.hpp"

namespace mcdyna::core {

class Communicator {
 public:
  /// MPI_COMM_WORLD when MPI is built in and initialised, else one process.
  static Communicator world();

  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }

  /// The sum over all processes of their partial sums: the same bits for any process count
  /// and any split of the terms.
  [[nodiscard]] double sum(const ExactSum& partial) const;
  /// The smallest of the processes' values.
  [[nodiscard]] double min(double value) const;

 private:
  Communicator(int rank, int size, bool mpi) : rank_(rank), size_(size), mpi_(mpi) {}
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

}  // namespace mcdyna::core
