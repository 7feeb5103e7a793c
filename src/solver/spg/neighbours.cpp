#include "solver/spg/neighbours.hpp"

#include <algorithm>
#include <cmath>

namespace mcdyna::solver::spg {

namespace {

// Particles sorted into a uniform grid of cubic cells (CSR over cells).
struct CellGrid {
  Eigen::Vector3d origin;
  double edge = 1.0;
  Eigen::Vector3i dims;
  std::vector<Index> start, items;

  [[nodiscard]] Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    Eigen::Vector3i c;
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp(static_cast<int>(std::floor((p[k] - origin[k]) / edge)), 0, dims[k] - 1);
    return c;
  }
  [[nodiscard]] std::size_t flat(const Eigen::Vector3i& c) const {
    return static_cast<std::size_t>(c.x()) +
           static_cast<std::size_t>(dims.x()) *
               (static_cast<std::size_t>(c.y()) +
                static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(c.z()));
  }
};

CellGrid build_grid(const Eigen::Matrix3Xd& x, double edge, const std::vector<std::uint8_t>& on) {
  CellGrid g;
  g.origin = x.rowwise().minCoeff();
  const Eigen::Vector3d span = x.rowwise().maxCoeff() - g.origin;
  // Cells at least as large as the largest support; larger when particles are so spread out
  // that the grid would hold far more cells than particles (cells stay cubic either way).
  const double limit = 4.0 * static_cast<double>(x.cols()) + 64.0;
  g.edge = edge;
  for (;;) {
    for (int k = 0; k < 3; ++k)
      g.dims[k] = static_cast<int>(span[k] / g.edge) + 1;
    if (static_cast<double>(g.dims.x()) * g.dims.y() * g.dims.z() <= limit) break;
    g.edge *= 1.25;
  }
  const std::size_t cells = static_cast<std::size_t>(g.dims.prod());
  g.start.assign(cells + 1, 0);
  std::vector<std::size_t> cell_of(static_cast<std::size_t>(x.cols()));
  for (Index i = 0; i < x.cols(); ++i) {
    if (!on.empty() && !on[static_cast<std::size_t>(i)]) continue;
    cell_of[static_cast<std::size_t>(i)] = g.flat(g.cell_of(x.col(i)));
    ++g.start[cell_of[static_cast<std::size_t>(i)] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c)
    g.start[c + 1] += g.start[c];
  g.items.resize(static_cast<std::size_t>(g.start[cells]));
  std::vector<Index> fill(g.start.begin(), g.start.end() - 1);
  for (Index i = 0; i < x.cols(); ++i) {  // ascending i within each cell
    if (!on.empty() && !on[static_cast<std::size_t>(i)]) continue;
    g.items[static_cast<std::size_t>(fill[cell_of[static_cast<std::size_t>(i)]]++)] = i;
  }
  return g;
}

// Whether r = X_I - X_J lies in the support of particle j (the bounding box first).
bool in_support_of(const Supports& s, KernelShape shape, const Eigen::Vector3d& r, Eigen::Index j) {
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(r[k]) < s.reach(k, j))) return false;
  return in_unit_support(shape, s.matrix(j) * r);
}

// CSR from per-particle lists filled in parallel.
NeighbourList to_csr(std::vector<std::vector<Index>>& lists) {
  NeighbourList out;
  out.offsets.assign(lists.size() + 1, 0);
  for (std::size_t i = 0; i < lists.size(); ++i)
    out.offsets[i + 1] = out.offsets[i] + static_cast<Index>(lists[i].size());
  out.neighbours.resize(static_cast<std::size_t>(out.offsets.back()));
  for (std::size_t i = 0; i < lists.size(); ++i)
    std::copy(lists[i].begin(), lists[i].end(), out.neighbours.begin() + out.offsets[i]);
  return out;
}

}  // namespace

NeighbourList find_neighbours(const Eigen::Matrix3Xd& x, const Supports& support, KernelShape shape,
                              const std::vector<std::uint8_t>& active,
                              const std::vector<std::uint8_t>& rows) {
  const auto n = static_cast<Index>(x.cols());
  std::vector<std::vector<Index>> lists(static_cast<std::size_t>(n));
  if (n == 0) return to_csr(lists);
  // A neighbour J of I satisfies |X_I - X_J|_k < a_J,k <= edge: within one cell of I's cell.
  const double edge = support.reach.maxCoeff();
  const CellGrid g = build_grid(x, edge, active);
#pragma omp parallel for schedule(dynamic, 256) if (n > 2048)
  for (Index i = 0; i < n; ++i) {
    if (!active.empty() && !active[static_cast<std::size_t>(i)]) continue;
    if (!rows.empty() && !rows[static_cast<std::size_t>(i)]) continue;
    auto& list = lists[static_cast<std::size_t>(i)];
    const Eigen::Vector3d xi = x.col(i);
    const Eigen::Vector3i c = g.cell_of(xi);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Eigen::Vector3i cc = c + Eigen::Vector3i(dx, dy, dz);
          if ((cc.array() < 0).any() || (cc.array() >= g.dims.array()).any()) continue;
          const std::size_t f = g.flat(cc);
          for (Index k = g.start[f]; k < g.start[f + 1]; ++k) {
            const Index j = g.items[static_cast<std::size_t>(k)];
            if (in_support_of(support, shape, xi - x.col(j), j)) list.push_back(j);
          }
        }
    std::sort(list.begin(), list.end());
  }
  return to_csr(lists);
}

NeighbourList find_neighbours_brute_force(const Eigen::Matrix3Xd& x, const Supports& support,
                                          KernelShape shape) {
  std::vector<std::vector<Index>> lists(static_cast<std::size_t>(x.cols()));
  for (Index i = 0; i < x.cols(); ++i)
    for (Index j = 0; j < x.cols(); ++j)
      if (in_unit_support(shape, support.matrix(j) * (x.col(i) - x.col(j))))
        lists[static_cast<std::size_t>(i)].push_back(j);
  return to_csr(lists);
}

}  // namespace mcdyna::solver::spg
