// Bonds of the initial configuration and their failure (paper §3.2, Eqs. 35-36).
#include <algorithm>
#include <numeric>

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

long break_bonds(const State& s, Domain& d) {
  const SpgSettings& st = d.settings;
  if (!st.bond_failure) return 0;
  Bonds& b = d.kernel.bonds;
  const auto& ep = d.fields.points.plastic_strain;
  const Eigen::Matrix3Xd& x = s.nodes.position;
  long broken = 0;
  // Each bond is stored at both ends; decide it once (i < j) and mark both entries, so the
  // result is the same for any thread count.
#pragma omp parallel for schedule(dynamic, 512) reduction(+ : broken) if (d.count() > 4096)
  for (Index i = 0; i < d.count(); ++i) {
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
      if (!(stretch > st.failure_stretch)) continue;
      b.broken[kk] = 1;
      // The mirror entry (j, i): written by this thread only, as (i, j) with i < j is owned here.
      const auto first = b.partners.begin() + b.offsets[static_cast<std::size_t>(j)];
      const auto last = b.partners.begin() + b.offsets[static_cast<std::size_t>(j) + 1];
      b.broken[static_cast<std::size_t>(std::lower_bound(first, last, i) - b.partners.begin())] = 1;
      ++broken;
    }
  }
  d.diagnostics.broken_bonds += broken;
  return broken;
}

Pieces count_pieces(const Domain& d) {
  // Union-find over the neighbour pairs, with path halving.
  std::vector<Index> root(static_cast<std::size_t>(d.count()));
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](Index i) {
    while (root[static_cast<std::size_t>(i)] != i) {
      auto& r = root[static_cast<std::size_t>(i)];
      r = root[static_cast<std::size_t>(r)];
      i = r;
    }
    return i;
  };
  for (Index i = 0; i < d.count(); ++i)
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(i)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
      const Index a = find(i), c = find(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
      if (a != c) root[static_cast<std::size_t>(std::max(a, c))] = std::min(a, c);
    }
  std::vector<Index> size(static_cast<std::size_t>(d.count()), 0);
  for (Index i = 0; i < d.count(); ++i)
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
