#pragma once
/// What this process advances and computes in a run over several processes (issue 25; built by
/// parallel::Halo). Empty masks mean one process: every node and every hexahedron.
#include <cstdint>
#include <vector>

#include "core/communicator.hpp"
#include "solver/parallel/exchange_plan.hpp"
#include "solver/parallel/particle_subset.hpp"

namespace mcdyna::solver::parallel {

/// An SPG part split over the processes like the hexahedra (spg/distribution.cpp). A process
/// owns particles; it computes the stress of the rows its particles' forces need (its own and
/// every row holding one of them: the transpose), redundantly with the other processes that need
/// them, and advances the velocities of its own particles only. Rebuilt at kernel renewals.
struct ParticleShare {
  bool split = false;      ///< false: every process computes the whole part (replicated)
  std::vector<int> owner;  ///< process of each particle
  /// The particles it owns, and those it computes the stress of: owned or holding an owned
  /// particle in their row.
  ParticleSubset owned, stressed;
  /// The particles whose u-hat this process keeps current: its own and the column ghosts.
  ParticleSubset current;
  /// The particles in the rows of the owned ones that another process owns: their accelerations
  /// (Eq. 30's scatter) and constraint changes arrive through `row_ghosts`.
  ExchangePlan row_ghosts;
  /// The particles whose rows hold an owned one (the transpose) that another process owns: their
  /// u-hat (Eq. 13's gather) arrives through `column_ghosts`.
  ExchangePlan column_ghosts;
  /// With the eigenvalue step: the particles in the stressed rows that another process owns;
  /// the power iteration's iterate (spg/frequency.cpp) arrives through `stress_ghosts`.
  ExchangePlan stress_ghosts;
  /// Wall seconds in this part's exchanges and synchronisations (the timing's "exchange" row).
  double exchange_seconds = 0.0;
};

struct Ownership {
  /// The run's processes (one by default).
  core::Communicator comm;
  /// Per node: the process that owns it (empty on one process).
  std::vector<int> owner;
  /// Per node: this process advances it, because it owns it or because the node belongs to a
  /// block every process computes whole (contact today).
  std::vector<std::uint8_t> moves;
  /// The nodes of `moves`, ascending: the per-cycle node loops visit these only, so a process's
  /// share of them shrinks with the process count (a mask alone is still read whole).
  std::vector<std::int32_t> moved_nodes;
  /// Per hexahedron: this process computes it, because one of its nodes is moved here. An
  /// element on a border is computed by every process that moves one of its nodes.
  std::vector<std::uint8_t> computes;
  /// Per node: this process owns it. A sum over nodes (a rigid wall's force) takes each node on
  /// its owner only, then sums over the processes (core::ExactSum: the same bits for any count).
  std::vector<std::uint8_t> owns;
  /// Per node: moved by every process, since a block that holds it is computed whole on each
  /// (Block::mark_replicated: shells, beams, ITB 1 SPG parts, ...). A force another block
  /// computes on it once (a contact hit) must reach every process.
  std::vector<std::uint8_t> replicated;
  /// Per SPG part (State::spg), how its particles are shared (empty on one process).
  std::vector<ParticleShare> particles;
  /// Counts the changes of `owner` (particles re-owned at renewals): the halo and the contact
  /// plans are rebuilt when it moves.
  long generation = 0;

  /// How many nodes a per-cycle node loop visits (all `count` on one process), and the k-th.
  [[nodiscard]] std::size_t moved_count(std::int32_t count) const {
    return moves.empty() ? static_cast<std::size_t>(count) : moved_nodes.size();
  }
  [[nodiscard]] std::int32_t moved_node(std::size_t k) const {
    return moves.empty() ? static_cast<std::int32_t>(k) : moved_nodes[k];
  }
  [[nodiscard]] bool moves_node(std::int32_t n) const {
    return moves.empty() || moves[static_cast<std::size_t>(n)] != 0;
  }
  [[nodiscard]] bool replicated_node(std::int32_t n) const {
    return !replicated.empty() && replicated[static_cast<std::size_t>(n)] != 0;
  }
  /// The process that reports node n's values to process 0 for the outputs: its owner, or 0 for
  /// a node every process moves (process 0 has it too).
  [[nodiscard]] int output_owner(std::int32_t n) const {
    return replicated_node(n) ? 0 : owner[static_cast<std::size_t>(n)];
  }
  [[nodiscard]] bool owns_node(std::int32_t n) const {
    return owns.empty() || owns[static_cast<std::size_t>(n)] != 0;
  }
  /// Per node: `owner` names this process. Within the cycle of a renewal that re-owns particles
  /// `owner` is already new while `owns` and `moves` follow at the halo's rebuild after the
  /// forces: the blocks that route work by owner in that cycle (contact) read this.
  [[nodiscard]] bool owned_now(std::int32_t n) const {
    return owner.empty() || owner[static_cast<std::size_t>(n)] == comm.rank();
  }
  [[nodiscard]] bool computes_element(std::int32_t e) const {
    return computes.empty() || computes[static_cast<std::size_t>(e)] != 0;
  }
  /// The share of SPG part `domain` when it is split, else null.
  [[nodiscard]] ParticleShare* split_part(std::size_t domain) {
    return domain < particles.size() && particles[domain].split ? &particles[domain] : nullptr;
  }
  [[nodiscard]] const ParticleShare* split_part(std::size_t domain) const {
    return domain < particles.size() && particles[domain].split ? &particles[domain] : nullptr;
  }
};

}  // namespace mcdyna::solver::parallel
