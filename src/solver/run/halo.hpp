#pragma once
/// The halo of one process in a run over several (issue 25, design.md §7): which nodes it
/// advances, which hexahedra it computes, and the messages that keep its copies of the other
/// processes' nodes current.
///
/// Every process holds the whole model; what it computes is set by the decomposition. It moves
/// the nodes it owns and the replicated ones (the nodes of blocks still computed whole on every
/// process: SPG parts, contact), and computes every hexahedron with
/// a moved node, so each moved node gathers its force from the same corners in the same order
/// as one process does: the bits do not depend on the process count. A hexahedron on a border
/// is computed by each process that moves one of its nodes (redundantly, the ghost elements),
/// which needs the nodes of those elements that another process moves (the ghost nodes).
///
/// Per cycle one exchange, after the positions: each process sends x^{n+1} and v^{n+1/2} of its
/// owned nodes to the processes that hold them as ghosts. At an output the owned values of
/// nodes and elements go to process 0, which writes every file.
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

#include "core/communicator.hpp"
#include "solver/run/decomposition.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::parallel {

/// Sizes of one process's share, for the d3hsp decomposition summary.
struct HaloSize {
  Index owned_nodes = 0;           ///< owned and not replicated
  Index replicated_nodes = 0;      ///< moved by every process
  Index ghost_nodes = 0;           ///< received each cycle
  Index sent_nodes = 0;            ///< sent each cycle (the sum over peers)
  Index peers = 0;                 ///< processes it exchanges with
  Index elements = 0;              ///< hexahedra it computes
  Index ghost_elements = 0;        ///< of them, owned by another process
  Index particles = 0;             ///< SPG particles it owns (split parts)
  Index rows = 0;                  ///< SPG rows it computes (its own and those holding its own)
  Index particle_ghosts = 0;       ///< particle values received per cycle (a and u-hat)
  std::size_t particle_bytes = 0;  ///< their bytes per cycle
};

class Halo {
 public:
  /// Collective over `comm`. `replicated`: per node, moved by every process. Sets
  /// s.ownership.
  Halo(State& s, const Decomposition& d, std::vector<std::uint8_t> replicated,
       core::Communicator comm);

  /// After s.ownership.owner or the SPG shares changed (particles re-owned at a renewal): the
  /// masks, the ghost nodes and the output shares again. Collective.
  void rebuild(State& s);

  /// x and v of the ghost nodes from the processes that own them.
  void exchange_motion(State& s);
  /// The owned values of nodes, hexahedra and nodal conditions to process 0, with the velocity
  /// before the cycle's update (`previous`), so process 0 holds what the outputs read: for the
  /// histories the nodes, the conditions and the elements' energies, added mass and erosion;
  /// with `states` (a d3plot state) every element value and integration point too.
  void gather_for_output(State& s, Eigen::Matrix3Xd& previous, bool states) const;

  [[nodiscard]] const HaloSize& size() const { return size_; }
  /// Bytes one exchange moves into this process.
  [[nodiscard]] std::size_t received_bytes() const;
  /// On process 0: the table of every process's share (collective).
  [[nodiscard]] std::string summary() const;

 private:
  core::Communicator comm_;
  ExchangePlan motion_;  ///< x and v of the ghost nodes
  /// Per process other than 0: the nodes and hexahedra it sends to process 0 (the blocks that
  /// own their data send theirs, Block::synchronise).
  struct OutputShare {
    std::vector<Index> nodes, elements;
  };
  std::vector<OutputShare> output_;  ///< indexed by process
  HaloSize size_;
};

}  // namespace mcdyna::solver::parallel
