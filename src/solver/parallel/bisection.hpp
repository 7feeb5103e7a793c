#pragma once
/// Recursive coordinate bisection, the cut under the decomposition of a model over processes
/// (solver/run/decomposition.hpp) and the SPG parts' re-owning of particles at a renewal
/// (spg/distribution.cpp). Why bisection rather than a graph partitioner: decomposition.hpp.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace mcdyna::solver::parallel {

using Index = std::int32_t;

/// Recursive coordinate bisection: `parts` cells of nearly equal weight, each cut across the
/// longest extent of its points at the weighted split that gives the two sides their share of
/// the parts. Returns the cell of each point, 0 .. parts - 1. Ties in a coordinate go by index,
/// so the result depends on nothing but the points and weights.
std::vector<int> bisect(const Eigen::Matrix3Xd& points, const std::vector<double>& weights,
                        int parts);

}  // namespace mcdyna::solver::parallel
