#pragma once
/// Particle neighbour lists in CSR form. neighbours(I) are the particles J whose kernel support
/// contains X_I (J = I included), in ascending order: exactly the J with phi_J(X_I) != 0, the
/// sums the shape functions and the velocity gradient at particle I run over. Supports differ
/// between particles, so the relation is not symmetric. Built from a uniform cell list whose
/// cell edge is the largest support half-size, so every neighbour lies in the 27 cells around
/// X_I; the order of the result does not depend on the cell layout or the thread count.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "solver/spg/kernel.hpp"

namespace mcdyna::solver::spg {

using Index = std::int32_t;

struct NeighbourList {
  std::vector<Index> offsets;     ///< size particles + 1
  std::vector<Index> neighbours;  ///< J of particle I at [offsets[I], offsets[I + 1])
  [[nodiscard]] Index count(Index i) const {
    return offsets[static_cast<std::size_t>(i) + 1] - offsets[static_cast<std::size_t>(i)];
  }
};

/// x: particle positions (3 x N); support: per particle; `active` (size N or empty: all) leaves
/// inactive particles out of every list and gives them an empty list; `rows` (size N or empty:
/// all) limits the search to those particles' own lists, the others are left empty (a partial
/// renewal of the kernel, renewal.cpp).
NeighbourList find_neighbours(const Eigen::Matrix3Xd& x, const Supports& support, KernelShape shape,
                              const std::vector<std::uint8_t>& active = {},
                              const std::vector<std::uint8_t>& rows = {});

/// The same by checking every pair (O(N^2)); for tests.
NeighbourList find_neighbours_brute_force(const Eigen::Matrix3Xd& x, const Supports& support,
                                          KernelShape shape);

}  // namespace mcdyna::solver::spg
