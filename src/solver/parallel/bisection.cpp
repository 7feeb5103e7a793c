#include "solver/parallel/bisection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace mcdyna::solver::parallel {

namespace {

// Cells first_cell .. first_cell + parts - 1 for the points in `members`.
void split(const Eigen::Matrix3Xd& points, const std::vector<double>& weights,
           std::vector<Index> members, int first_cell, int parts, std::vector<int>& cell) {
  if (parts <= 1 || members.size() <= 1) {
    for (const Index i : members)
      cell[static_cast<std::size_t>(i)] = first_cell;
    return;
  }
  // Across the longest extent (the lowest axis on a tie).
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (const Index i : members) {
    low = low.cwiseMin(points.col(i));
    high = high.cwiseMax(points.col(i));
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (high[k] - low[k] > high[axis] - low[axis]) axis = k;
  std::sort(members.begin(), members.end(), [&](Index a, Index b) {
    const double xa = points(axis, a), xb = points(axis, b);
    return xa < xb || (xa == xb && a < b);
  });
  // The split whose left weight is nearest the left cells' share (both sides non-empty).
  const int left_parts = parts / 2;
  double total = 0.0;
  for (const Index i : members)
    total += weights[static_cast<std::size_t>(i)];
  const double target = total * left_parts / parts;
  std::size_t best = 1;
  double prefix = 0.0, best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < members.size(); ++k) {
    prefix += weights[static_cast<std::size_t>(members[k - 1])];
    const double gap = std::abs(prefix - target);
    if (gap < best_gap) {
      best_gap = gap;
      best = k;
    }
  }
  std::vector<Index> right(members.begin() + static_cast<std::ptrdiff_t>(best), members.end());
  members.resize(best);
  split(points, weights, std::move(members), first_cell, left_parts, cell);
  split(points, weights, std::move(right), first_cell + left_parts, parts - left_parts, cell);
}

}  // namespace

std::vector<int> bisect(const Eigen::Matrix3Xd& points, const std::vector<double>& weights,
                        int parts) {
  std::vector<int> cell(static_cast<std::size_t>(points.cols()), 0);
  std::vector<Index> all(static_cast<std::size_t>(points.cols()));
  std::iota(all.begin(), all.end(), Index{0});
  split(points, weights, std::move(all), 0, std::max(parts, 1), cell);
  return cell;
}

}  // namespace mcdyna::solver::parallel
