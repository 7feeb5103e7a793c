// Bonds of the initial configuration and their failure (paper §3.2, Eqs. 35-36).
#include <algorithm>
#include <numeric>

#include "solver/spg/distribution.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

bool Bonds::is_broken(Index i, Index j) const {
  const auto first = partners.begin() + offsets[static_cast<std::size_t>(i)];
  const auto last = partners.begin() + offsets[static_cast<std::size_t>(i) + 1];
  const auto it = std::lower_bound(first, last, j);
  return it != last && *it == j && broken[static_cast<std::size_t>(it - partners.begin())] != 0;
}

double Bonds::damage(Index i) const {
  const Index first = offsets[static_cast<std::size_t>(i)];
  const Index last = offsets[static_cast<std::size_t>(i) + 1];
  if (last == first) return 0.0;
  Index n = 0;
  for (Index k = first; k < last; ++k)
    n += broken[static_cast<std::size_t>(k)];
  return static_cast<double>(n) / static_cast<double>(last - first);
}

Bonds initial_bonds(const Domain& d) {
  // Symmetrise the row lists: J in N(I) or I in N(J), self excluded.
  const Index n = d.count();
  std::vector<std::vector<Index>> partners(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i)
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(i)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
      const Index j = d.kernel.list.neighbours[static_cast<std::size_t>(p)];
      if (j == i) continue;
      partners[static_cast<std::size_t>(i)].push_back(j);
      partners[static_cast<std::size_t>(j)].push_back(i);
    }
  Bonds b;
  b.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  for (Index i = 0; i < n; ++i) {
    auto& v = partners[static_cast<std::size_t>(i)];
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    b.offsets[static_cast<std::size_t>(i) + 1] =
        b.offsets[static_cast<std::size_t>(i)] + static_cast<Index>(v.size());
    for (const Index j : v) {
      b.partners.push_back(j);
      b.length.push_back(
          (d.particles.initial_position.col(j) - d.particles.initial_position.col(i)).norm());
    }
  }
  b.broken.assign(b.partners.size(), 0);
  return b;
}

// Over several processes each decides the bonds of its own particles (the pair's lower end),
// from the positions and plastic strains every process received for the check, and all share
// the bonds that broke: every process then holds the same bonds.
long break_bonds(const State& s, Domain& d) {
  const SpgSettings& st = d.settings;
  if (!st.bond_failure) return 0;
  Bonds& b = d.kernel.bonds;
  const auto& ep = d.fields.points.plastic_strain;
  const Eigen::Matrix3Xd& x = s.nodes.position;
  const parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const ParticleSubset* owned = share ? &share->owned : nullptr;
  const std::size_t count = members(owned, d.count());
  // Each bond is stored at both ends; it is decided once, at its lower end (i < j), and its
  // entry (i, j) listed in particle order, so the result is the same for any thread count.
  std::vector<std::vector<Index>> broke_at(count);
#pragma omp parallel for schedule(dynamic, 512) if (count > 4096)
  for (std::size_t m = 0; m < count; ++m) {
    const Index i = member(owned, m);
    for (Index k = b.offsets[static_cast<std::size_t>(i)];
         k < b.offsets[static_cast<std::size_t>(i) + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const Index j = b.partners[kk];
      if (j < i || b.broken[kk]) continue;
      const double mean_strain =
          0.5 * (ep[static_cast<std::size_t>(i)] + ep[static_cast<std::size_t>(j)]);
      if (!(mean_strain > st.failure_strain)) continue;
      const double stretch = (x.col(d.particles.nodes[static_cast<std::size_t>(j)]) -
                              x.col(d.particles.nodes[static_cast<std::size_t>(i)]))
                                 .norm() /
                             b.length[kk];
      if (stretch > st.failure_stretch) broke_at[m].push_back(k);
    }
  }
  std::vector<double> broken;
  for (const std::vector<Index>& entries : broke_at)
    broken.insert(broken.end(), entries.begin(), entries.end());
  if (share) broken = s.ownership.comm.all_gather_varying(broken);
  for (const double entry : broken) {
    const auto kk = static_cast<std::size_t>(entry);
    b.broken[kk] = 1;
    // The mirror entry (j, i).
    const Index i = static_cast<Index>(
        std::upper_bound(b.offsets.begin(), b.offsets.end(), static_cast<Index>(kk)) -
        b.offsets.begin() - 1);
    const Index j = b.partners[kk];
    const auto first = b.partners.begin() + b.offsets[static_cast<std::size_t>(j)];
    const auto last = b.partners.begin() + b.offsets[static_cast<std::size_t>(j) + 1];
    b.broken[static_cast<std::size_t>(std::lower_bound(first, last, i) - b.partners.begin())] = 1;
  }
  d.diagnostics.broken_bonds += static_cast<long>(broken.size());
  return static_cast<long>(broken.size());
}

Pieces count_pieces(const NeighbourList& list) {
  const auto n = static_cast<Index>(list.offsets.size() - 1);
  // Union-find over the neighbour pairs, with path halving.
  std::vector<Index> root(static_cast<std::size_t>(n));
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](Index i) {
    while (root[static_cast<std::size_t>(i)] != i) {
      auto& r = root[static_cast<std::size_t>(i)];
      r = root[static_cast<std::size_t>(r)];
      i = r;
    }
    return i;
  };
  for (Index i = 0; i < n; ++i)
    for (Index p = list.offsets[static_cast<std::size_t>(i)];
         p < list.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
      const Index a = find(i), c = find(list.neighbours[static_cast<std::size_t>(p)]);
      if (a != c) root[static_cast<std::size_t>(std::max(a, c))] = std::min(a, c);
    }
  std::vector<Index> size(static_cast<std::size_t>(n), 0);
  for (Index i = 0; i < n; ++i)
    ++size[static_cast<std::size_t>(find(i))];
  Pieces p;
  for (const Index s : size) {
    if (s == 0) continue;
    ++p.pieces;
    if (s == 1) ++p.single;
    p.largest = std::max(p.largest, s);
  }
  return p;
}

}  // namespace mcdyna::solver::spg
