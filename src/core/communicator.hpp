#pragma once
/// The processes of a run (issue 25). Built with MPI (MCDYNA_WITH_MPI, CMake option MCDYNA_MPI
/// and an MPI found) it is MPI_COMM_WORLD, which the caller has initialised (Session); built
/// without, or before MPI is initialised, it is this one process and every call below is the
/// identity.
///
/// Reductions keep their bits for any process count: a sum goes through core::ExactSum, whose
/// partials merge by integer addition (an MPI_SUM over its limbs is exact and associative), and
/// a minimum is exact by nature. Everything MPI is in communicator.cpp, so the solver compiles
/// the same with and without it.
#include <cstdint>
#include <string>
#include <vector>

#include "core/exact_sum.hpp"

namespace mcdyna::core {

class Communicator {
 public:
  /// One process.
  Communicator() = default;
  /// MPI_COMM_WORLD when MPI is built in and initialised, else one process.
  static Communicator world();

  /// Whether this build has MPI (CMake MCDYNA_MPI with an MPI found).
  static bool built_with_mpi();

  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }

  /// The sum over all processes of their partial sums: the same bits for any process count
  /// and any split of the terms.
  [[nodiscard]] double sum(const ExactSum& partial) const;
  /// The same for several sums at once (one message).
  [[nodiscard]] std::vector<double> sum(const std::vector<ExactSum>& partials) const;
  /// The integer sums over all processes, entry by entry (exact, hence any order).
  [[nodiscard]] std::vector<std::int64_t> sum(const std::vector<std::int64_t>& partial) const;
  /// The smallest of the processes' values.
  [[nodiscard]] double min(double value) const;
  [[nodiscard]] std::int64_t min(std::int64_t value) const;
  /// The bitwise or of the processes' flags.
  [[nodiscard]] unsigned bitwise_or(unsigned flags) const;
  /// Every process's `mine` (all of the same length), in rank order.
  [[nodiscard]] std::vector<double> all_gather(const std::vector<double>& mine) const;
  /// Every process's `mine` (lengths may differ) on every process, concatenated in rank order.
  [[nodiscard]] std::vector<double> all_gather_varying(const std::vector<double>& mine) const;
  /// `text` of process `root` on every process.
  void broadcast(std::string& text, int root) const;
  /// Personalised all-to-all: to[r] goes to process r; returns what each process sent here.
  [[nodiscard]] std::vector<std::vector<std::int32_t>> all_to_all(
      const std::vector<std::vector<std::int32_t>>& to) const;
  [[nodiscard]] std::vector<std::vector<double>> all_to_all(
      const std::vector<std::vector<double>>& to) const;
  /// Point-to-point with the given peers at once: send[k] to peers[k], receive[k] (already
  /// sized) from peers[k]. Returns when every message has arrived.
  void exchange(const std::vector<int>& peers, const std::vector<std::vector<double>>& send,
                std::vector<std::vector<double>>& receive) const;
  /// Every process's `mine` on process 0, in rank order (empty elsewhere); `counts` the sizes.
  [[nodiscard]] std::vector<double> gather_to_root(const std::vector<double>& mine,
                                                   std::vector<int>& counts) const;
  /// Stops every process of the run (a failure one process alone met, which would leave the
  /// others waiting in a collective).
  [[noreturn]] void abort(int code) const;

 private:
  Communicator(int rank, int size, bool mpi) : rank_(rank), size_(size), mpi_(mpi) {}
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

/// MPI initialised for the lifetime of the object (thread support: funneled, the OpenMP
/// threads never call MPI) when `wanted` and MPI is built in; finalised at its end.
class Session {
 public:
  explicit Session(bool wanted);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  [[nodiscard]] bool active() const { return active_; }

 private:
  bool active_ = false;
};

}  // namespace mcdyna::core
