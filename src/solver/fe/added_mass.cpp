#include "solver/fe/added_mass.hpp"

#include <algorithm>

#include "solver/block.hpp"

namespace mcdyna::solver {

void refresh_added_mass(State& s) {
  std::vector<double>& nodal = s.nodes.added_mass;
  std::fill(nodal.begin(), nodal.end(), 0.0);
  for (const auto& b : s.blocks)
    b->spread_added_mass(s, nodal);
}

}  // namespace mcdyna::solver
