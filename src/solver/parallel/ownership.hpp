#pragma once
/// What this process advances and computes in a run over several processes (issue 25; built by
/// parallel::Halo). Empty masks mean one process: every node and every hexahedron.
#include <cstdint>
#include <vector>

#include "core/communicator.hpp"

namespace mcdyna::solver::parallel {

struct Ownership {
  /// The run's processes (one by default).
  core::Communicator comm;
  /// Per node: this process advances it, because it owns it or because the node belongs to a
  /// block every process computes whole (SPG parts and contact today).
  std::vector<std::uint8_t> moves;
  /// Per hexahedron: this process computes it, because one of its nodes is moved here. An
  /// element on a border is computed by every process that moves one of its nodes.
  std::vector<std::uint8_t> computes;
  /// Per node: this process owns it. A sum over nodes (a rigid wall's force) takes each node on
  /// its owner only, then sums over the processes (core::ExactSum: the same bits for any count).
  std::vector<std::uint8_t> owns;

  [[nodiscard]] bool moves_node(std::int32_t n) const {
    return moves.empty() || moves[static_cast<std::size_t>(n)] != 0;
  }
  [[nodiscard]] bool owns_node(std::int32_t n) const {
    return owns.empty() || owns[static_cast<std::size_t>(n)] != 0;
  }
  [[nodiscard]] bool computes_element(std::int32_t e) const {
    return computes.empty() || computes[static_cast<std::size_t>(e)] != 0;
  }
};

}  // namespace mcdyna::solver::parallel
