#pragma once
/// A subset of an SPG part's particles, and loops over it or over the whole part: the power
/// iteration's patches (frequency.cpp) and a process's own and stressed particles over several
/// processes (parallel::ParticleShare).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mcdyna::solver::spg {

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

}  // namespace mcdyna::solver::spg
