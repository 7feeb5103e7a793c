#pragma once
/// A subset of an SPG part's particles, and loops over it or over the whole part: a process's
/// own and stressed particles over several processes (ParticleShare, ownership.hpp), and the
/// power iteration's patches (spg/frequency.cpp). Here, below the State, because the ownership
/// the State holds is made of them; the SPG code takes them into its namespace (spg_solver.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mcdyna::solver::parallel {

using Index = std::int32_t;

/// A subset of a domain's particles: a flag per particle and the flagged ones ascending.
struct ParticleSubset {
  std::vector<std::uint8_t> flag;
  std::vector<Index> index;
};
/// The k-th particle of `subset`, or k itself for the whole domain (subset null).
inline Index member(const ParticleSubset* subset, std::size_t k) {
  return subset != nullptr ? subset->index[k] : static_cast<Index>(k);
}
/// How many particles a loop over `subset` (null: all `count`) visits.
inline std::size_t members(const ParticleSubset* subset, Index count) {
  return subset != nullptr ? subset->index.size() : static_cast<std::size_t>(count);
}

}  // namespace mcdyna::solver::parallel
