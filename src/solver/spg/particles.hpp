#pragma once
/// Particles generated from the hexahedra of *SECTION_SOLID_SPG (ELFORM 47) parts: every node of
/// those elements becomes a particle with a lumped volume (1/8 of each element it belongs to,
/// as the FE lumped mass) and a nodal spacing per axis (the largest x, y and z extent of the
/// element edges that meet it), from which the support half-sizes are DX/DY/DZ x spacing
/// (keywords.md §2.6). Every mesh neighbour then lies inside the box support (DX >= 1), and a
/// mesh whose edges are not axis-aligned (the butterfly mesh of a cylinder) does not get the
/// oversized supports that the longest edge in every direction would give.
#include <Eigen/Core>

#include <array>
#include <vector>

#include "solver/spg/neighbours.hpp"

namespace mcdyna::solver::spg {

struct GeneratedParticles {
  std::vector<Index> nodes;    ///< node index of each particle, ascending
  std::vector<double> volume;  ///< lumped volume
  Eigen::Matrix3Xd spacing;    ///< per axis: largest |edge_k| over the incident edges
};

/// positions: all node positions (3 x nodes); elements: corner node indices of the SPG hexahedra
/// (LS-DYNA order, degenerate ones allowed); volumes: their volumes.
GeneratedParticles particles_from_hexahedra(const Eigen::Matrix3Xd& positions,
                                            const std::vector<std::array<Index, 8>>& elements,
                                            const std::vector<double>& volumes);

/// Support half-sizes (3 x particles): scale (DX, DY, DZ) times each particle's spacing.
Eigen::Matrix3Xd support_sizes(const GeneratedParticles& p, const Eigen::Vector3d& scale);

}  // namespace mcdyna::solver::spg
