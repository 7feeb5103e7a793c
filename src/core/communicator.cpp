#include "core/communicator.hpp"

#ifdef MCDYNA_WITH_MPI
#include <mpi.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <tuple>

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

bool Communicator::built_with_mpi() {
#ifdef MCDYNA_WITH_MPI
  return true;
#else
  return false;
#endif
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

std::vector<double> Communicator::sum(const std::vector<ExactSum>& partials) const {
  std::vector<double> totals(partials.size());
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    using Parts = ExactSum::Parts;
    std::vector<std::int64_t> mine(partials.size() * std::tuple_size_v<Parts>), all(mine.size());
    for (std::size_t k = 0; k < partials.size(); ++k) {
      const Parts p = partials[k].parts();
      std::copy(p.begin(), p.end(), mine.begin() + static_cast<std::ptrdiff_t>(k * p.size()));
    }
    MPI_Allreduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_INT64_T, MPI_SUM,
                  MPI_COMM_WORLD);
    for (std::size_t k = 0; k < partials.size(); ++k) {
      Parts p{};
      std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(k * p.size()), p.size(), p.begin());
      totals[k] = ExactSum::from_parts(p).value();
    }
    return totals;
  }
#endif
  for (std::size_t k = 0; k < partials.size(); ++k)
    totals[k] = partials[k].value();
  return totals;
}

std::vector<std::int64_t> Communicator::sum(const std::vector<std::int64_t>& partial) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    std::vector<std::int64_t> all(partial.size());
    MPI_Allreduce(partial.data(), all.data(), static_cast<int>(partial.size()), MPI_INT64_T,
                  MPI_SUM, MPI_COMM_WORLD);
    return all;
  }
#endif
  return partial;
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

std::int64_t Communicator::min(std::int64_t value) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    std::int64_t smallest = value;
    MPI_Allreduce(&value, &smallest, 1, MPI_INT64_T, MPI_MIN, MPI_COMM_WORLD);
    return smallest;
  }
#endif
  return value;
}

unsigned Communicator::bitwise_or(unsigned flags) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    unsigned all = flags;
    MPI_Allreduce(&flags, &all, 1, MPI_UNSIGNED, MPI_BOR, MPI_COMM_WORLD);
    return all;
  }
#endif
  return flags;
}

std::vector<double> Communicator::all_gather(const std::vector<double>& mine) const {
  std::vector<double> all(mine.size() * static_cast<std::size_t>(size_));
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                  static_cast<int>(mine.size()), MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
  }
#endif
  std::copy(mine.begin(), mine.end(), all.begin());
  return all;
}

std::vector<double> Communicator::all_gather_varying(const std::vector<double>& mine) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    const int count = static_cast<int>(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(counts.size(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      offsets[r] = total;
      total += counts[r];
    }
    std::vector<double> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                   MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
  }
#endif
  return mine;
}

void Communicator::broadcast(std::string& text, int root) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    auto length = static_cast<std::int64_t>(text.size());
    MPI_Bcast(&length, 1, MPI_INT64_T, root, MPI_COMM_WORLD);
    text.resize(static_cast<std::size_t>(length));
    MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, MPI_COMM_WORLD);
  }
#else
  (void)text;
  (void)root;
#endif
}

namespace {

#ifdef MCDYNA_WITH_MPI
MPI_Datatype mpi_type(std::int32_t) {
  return MPI_INT32_T;
}
MPI_Datatype mpi_type(double) {
  return MPI_DOUBLE;
}
#endif

// Personalised all-to-all of lists of any length: the counts first, then the lists.
template <class T>
std::vector<std::vector<T>> all_to_all_lists(bool mpi, int size,
                                             const std::vector<std::vector<T>>& to) {
  std::vector<std::vector<T>> from(static_cast<std::size_t>(size));
#ifdef MCDYNA_WITH_MPI
  if (mpi && size > 1) {
    std::vector<int> send_counts(static_cast<std::size_t>(size)), recv_counts(send_counts.size());
    std::vector<int> send_offsets(send_counts.size()), recv_offsets(send_counts.size());
    std::vector<T> send;
    for (int r = 0; r < size; ++r) {
      const auto& list = to[static_cast<std::size_t>(r)];
      send_offsets[static_cast<std::size_t>(r)] = static_cast<int>(send.size());
      send_counts[static_cast<std::size_t>(r)] = static_cast<int>(list.size());
      send.insert(send.end(), list.begin(), list.end());
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size; ++r) {
      recv_offsets[static_cast<std::size_t>(r)] = total;
      total += recv_counts[static_cast<std::size_t>(r)];
    }
    std::vector<T> received(static_cast<std::size_t>(total));
    MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), mpi_type(T{}),
                  received.data(), recv_counts.data(), recv_offsets.data(), mpi_type(T{}),
                  MPI_COMM_WORLD);
    for (int r = 0; r < size; ++r) {
      const auto begin = received.begin() + recv_offsets[static_cast<std::size_t>(r)];
      from[static_cast<std::size_t>(r)].assign(begin,
                                               begin + recv_counts[static_cast<std::size_t>(r)]);
    }
    return from;
  }
#else
  (void)mpi;
#endif
  from[0] = to[0];
  return from;
}

}  // namespace

std::vector<std::vector<std::int32_t>> Communicator::all_to_all(
    const std::vector<std::vector<std::int32_t>>& to) const {
  return all_to_all_lists(mpi_, size_, to);
}

std::vector<std::vector<double>> Communicator::all_to_all(
    const std::vector<std::vector<double>>& to) const {
  return all_to_all_lists(mpi_, size_, to);
}

void Communicator::exchange(const std::vector<int>& peers,
                            const std::vector<std::vector<double>>& send,
                            std::vector<std::vector<double>>& receive) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    std::vector<MPI_Request> requests(2 * peers.size());
    for (std::size_t k = 0; k < peers.size(); ++k)
      MPI_Irecv(receive[k].data(), static_cast<int>(receive[k].size()), MPI_DOUBLE, peers[k], 25,
                MPI_COMM_WORLD, &requests[k]);
    for (std::size_t k = 0; k < peers.size(); ++k)
      MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, peers[k], 25,
                MPI_COMM_WORLD, &requests[peers.size() + k]);
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  }
#else
  (void)peers;
  (void)send;
  (void)receive;
#endif
}

std::vector<double> Communicator::gather_to_root(const std::vector<double>& mine,
                                                 std::vector<int>& counts) const {
  counts.assign(static_cast<std::size_t>(size_), 0);
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) {
    const int count = static_cast<int>(mine.size());
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(counts.size(), 0);
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      offsets[r] = total;
      total += counts[r];
    }
    std::vector<double> all(rank_ == 0 ? static_cast<std::size_t>(total) : 0);
    MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return all;
  }
#endif
  counts[0] = static_cast<int>(mine.size());
  return mine;
}

void Communicator::abort(int code) const {
#ifdef MCDYNA_WITH_MPI
  if (mpi_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

Session::Session(bool wanted) {
#ifdef MCDYNA_WITH_MPI
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (wanted && !initialised) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    active_ = true;
  }
#else
  (void)wanted;
#endif
}

Session::~Session() {
#ifdef MCDYNA_WITH_MPI
  if (active_) MPI_Finalize();
#endif
}

}  // namespace mcdyna::core
