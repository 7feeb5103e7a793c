// Bucket search: the segments' widened bounding boxes are binned into a uniform grid of cells
// (sorted (cell, segment) pairs, so the result does not depend on hashing or threads) and every
// node looks up its own cell.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "solver/contact/contact.hpp"

namespace mcdyna::solver::contact {

namespace {

using Key = std::uint64_t;

struct Grid {
  Vec3 origin = Vec3::Zero();
  double cell = 1.0;
  [[nodiscard]] Eigen::Array3i cell_of(const Vec3& x) const {
    return ((x - origin) / cell).array().floor().cast<int>().max(0).min((1 << 20) - 1);
  }
  [[nodiscard]] static Key key(const Eigen::Array3i& c) {
    return (static_cast<Key>(c[0]) << 42) | (static_cast<Key>(c[1]) << 21) | static_cast<Key>(c[2]);
  }
};

struct Box {
  Vec3 lo, hi;
};

Box segment_box(const State& s, const Surface& surface, std::size_t k, double margin) {
  Box b{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
  for (const Index n : surface.segments[k]) {
    b.lo = b.lo.cwiseMin(s.nodes.position.col(n));
    b.hi = b.hi.cwiseMax(s.nodes.position.col(n));
  }
  const double widen = margin + surface.half_thickness[k];
  b.lo.array() -= widen;
  b.hi.array() += widen;
  return b;
}

void sort_pass(const State& s, Pass& p, double margin) {
  const std::size_t segments = p.surface.segments.size();
  std::vector<Box> boxes(segments);
  Grid grid;
  grid.origin = Vec3::Constant(1e300);
  std::vector<double> extents(segments);
  for (std::size_t k = 0; k < segments; ++k) {
    boxes[k] = segment_box(s, p.surface, k, margin);
    grid.origin = grid.origin.cwiseMin(boxes[k].lo);
    extents[k] = (boxes[k].hi - boxes[k].lo).maxCoeff();
  }
  for (const Index n : p.nodes)
    if (s.ownership.owned_now(n)) grid.origin = grid.origin.cwiseMin(s.nodes.position.col(n));
  // Cells of twice the median widened segment: a node sees the few segments around it, and the
  // odd large segment (a fan closing a screw's end) is binned into every cell it covers.
  double cell = 1.0;
  if (segments > 0) {
    auto middle = extents.begin() + static_cast<long>(segments / 2);
    std::nth_element(extents.begin(), middle, extents.end());
    cell = 2.0 * *middle;
  }
  grid.cell = cell > 0.0 ? cell : 1.0;
  std::vector<std::pair<Key, Index>> bins;
  for (std::size_t k = 0; k < segments; ++k) {
    const Eigen::Array3i lo = grid.cell_of(boxes[k].lo), hi = grid.cell_of(boxes[k].hi);
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int l = lo[2]; l <= hi[2]; ++l)
          bins.emplace_back(Grid::key({i, j, l}), static_cast<Index>(k));
  }
  std::sort(bins.begin(), bins.end());
  const auto nodes = static_cast<Index>(p.nodes.size());
  // Over several processes each looks up the slave nodes it owns only: their owner alone
  // computes their hits (contact_forces.cpp). The candidates of a node are the boxes that hold
  // it, in segment order, whatever the grid's origin and cell: the same on any process count.
  auto each_candidate = [&](Index i, auto&& take) {
    const Index node = p.nodes[static_cast<std::size_t>(i)];
    if (!s.ownership.owned_now(node)) return;
    const Vec3 x = s.nodes.position.col(node);
    const Key key = Grid::key(grid.cell_of(x));
    auto it = std::lower_bound(bins.begin(), bins.end(), std::make_pair(key, Index{0}));
    for (; it != bins.end() && it->first == key; ++it) {
      const Box& b = boxes[static_cast<std::size_t>(it->second)];
      if ((x.array() >= b.lo.array()).all() && (x.array() <= b.hi.array()).all()) take(it->second);
    }
  };
  p.candidate_offsets.assign(p.nodes.size() + 1, 0);
#pragma omp parallel for schedule(static) if (nodes > 4096)
  for (Index i = 0; i < nodes; ++i) {
    Index count = 0;
    each_candidate(i, [&](Index) { ++count; });
    p.candidate_offsets[static_cast<std::size_t>(i) + 1] = count;
  }
  for (std::size_t i = 0; i < p.nodes.size(); ++i)
    p.candidate_offsets[i + 1] += p.candidate_offsets[i];
  p.candidates.resize(static_cast<std::size_t>(p.candidate_offsets.back()));
  // Nodes without candidates cannot touch before the next sort: they hold no friction, side or
  // initial penetration.
  p.near.clear();
  p.initial_penetration.resize(p.nodes.size(), 0.0);
  for (Index i = 0; i < nodes; ++i) {
    if (p.candidate_offsets[static_cast<std::size_t>(i) + 1] >
        p.candidate_offsets[static_cast<std::size_t>(i)]) {
      p.near.push_back(i);
    } else {
      p.friction.col(i).setZero();
      p.side.col(i).setZero();
      p.initial_penetration[static_cast<std::size_t>(i)] = 0.0;
    }
  }
#pragma omp parallel for schedule(static) if (nodes > 4096)
  for (Index i = 0; i < nodes; ++i) {
    auto out = static_cast<std::size_t>(p.candidate_offsets[static_cast<std::size_t>(i)]);
    each_candidate(i, [&](Index k) { p.candidates[out++] = k; });
  }
}

}  // namespace

bool sort_due(const State& s, const Interface& c) {
  if (c.last_sort < 0 || s.cycle - c.last_sort >= c.sort_interval) return true;
  const double limit = 0.25 * c.capture * c.capture;  // (capture / 2)^2
  const auto n = static_cast<Index>(c.tracked.size());
  bool moved = false;
#pragma omp parallel for schedule(static) reduction(|| : moved) if (n > 8192)
  for (Index i = 0; i < n; ++i) {
    const Index node = c.tracked[static_cast<std::size_t>(i)];
    // Over several processes the position of a deformable node is current on its owner only
    // between sorts (contact_block.cpp); rigid-body nodes are placed alike everywhere.
    if (!s.ownership.owned_now(node) && s.nodes.rigid_body[static_cast<std::size_t>(node)] < 0)
      continue;
    moved = moved || (s.nodes.position.col(node) - c.sorted_positions.col(i)).squaredNorm() > limit;
  }
  if (s.ownership.comm.size() > 1) moved = s.ownership.comm.bitwise_or(moved ? 1U : 0U) != 0;
  return moved;
}

void sort_buckets(const State& s, Interface& c) {
  for (Pass& p : c.passes)
    sort_pass(s, p, c.capture);
  c.sorted_positions.resize(3, static_cast<Eigen::Index>(c.tracked.size()));
  for (std::size_t i = 0; i < c.tracked.size(); ++i)
    c.sorted_positions.col(static_cast<Eigen::Index>(i)) = s.nodes.position.col(c.tracked[i]);
  c.last_sort = s.cycle;
}

}  // namespace mcdyna::solver::contact
