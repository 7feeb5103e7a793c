#pragma once
/// Every process's values of the entities it owns, to every process or to process 0 (issue 25):
/// an SPG part's synchronisations, the contact nodes' motion and hits. Entities are 0 .. count-1
/// with `owner(k)` their process. Each process packs its own in ascending order; the receivers
/// unpack them process by process in the same order, so no index travels.
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "core/communicator.hpp"

namespace mcdyna::solver::parallel {

/// pack(k, out) appends entity k's values to `out`; unpack(k, in) reads them from `in` and
/// advances it. With `to_root` only process 0 receives. Collective.
template <class Owner, class Pack, class Unpack>
void gather_owned(const core::Communicator& comm, std::size_t count, Owner&& owner, Pack&& pack,
                  Unpack&& unpack, bool to_root = false) {
  const int me = comm.rank();
  std::vector<double> mine;
  if (!to_root || me != 0)
    for (std::size_t k = 0; k < count; ++k)
      if (owner(k) == me) pack(k, mine);
  std::vector<int> counts;
  const std::vector<double> all =
      to_root ? comm.gather_to_root(mine, counts) : comm.all_gather_varying(mine);
  if (to_root && me != 0) return;
  const double* in = all.data();
  for (int r = to_root ? 1 : 0; r < comm.size(); ++r)
    for (std::size_t k = 0; k < count; ++k)
      if (owner(k) == r) unpack(k, in);
  if (in != all.data() + all.size())
    throw std::logic_error("parallel::gather_owned: the processes' shares do not match");
}

}  // namespace mcdyna::solver::parallel
