#pragma once
/// The decomposition of a model over processes (issue 25): which rank owns each node, and what
/// each rank then computes. Ranks own nodes; a rank computes every element and SPG row that
/// reaches one of its nodes, the ones that also reach other ranks' nodes redundantly (ghosts),
/// so that every owned node's force is gathered in the global order of one process and the
/// answer keeps its bits for any rank count (design.md §7).
///
/// Each kind of work is balanced on its own, as LS-DYNA's
/// *CONTROL_MPP_DECOMPOSITION_PARTS_DISTRIBUTE spreads chosen parts over all processors: the
/// phases of a cycle are separated by exchanges, so a rank that is light in one phase cannot
/// lend its time to another. The SPG particles' nodes are bisected over all ranks, then the
/// nodes of the deformable solids that are not particles, each by recursive coordinate
/// bisection weighted by the measured cost of what sits on the node. Rigid-body and other
/// nodes, which carry little work each, are bisected over all ranks by count.
///
/// Recursive coordinate bisection rather than METIS: the SPG kernels reach a fixed distance, so
/// a rank's halo is its boundary layer of that thickness and compact boxes keep it small; RCB
/// is deterministic (sorting by coordinate and index), needs no graph of the particles (which
/// changes at every renewal) and no dependency.
#include <vector>

#include "solver/parallel/bisection.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::parallel {

/// Seconds a cycle costs per entity, from the study's rates on one core (manual/verification.md
/// study table: FE hexahedra 3.5 M element-steps per core-s, MC-SPG particles 1.0 M, ITB 1
/// particles 0.3 M; contact about a tenth of a particle per slave node, FDS h 0.2 timing).
struct EntityCosts {
  double hexahedron = 0.29e-6;
  double particle = 1.0e-6;
  double contact_node = 0.1e-6;
};

struct Decomposition {
  int ranks = 1;
  std::vector<int> owner;  ///< rank of each node
};

Decomposition decompose(const State& s, int ranks, const EntityCosts& costs = {});

/// What one rank owns and computes, for a decomposition of a state whose SPG kernels are built
/// (spg::initialise).
struct RankLoad {
  Index owned_nodes = 0;
  Index ghost_nodes = 0;     ///< nodes it reads but another rank owns (halo)
  Index peers = 0;           ///< ranks that own its ghost nodes (messages per exchange)
  Index elements = 0;        ///< hexahedra it computes (those with an owned node)
  Index ghost_elements = 0;  ///< of them, also computed by another rank
  Index particles = 0;       ///< owned SPG particles
  Index rows = 0;            ///< SPG rows it computes (those holding an owned particle)
  Index ghost_rows = 0;      ///< of them, rows of particles another rank owns
  double cost = 0.0;         ///< seconds per cycle of what it computes (EntityCosts)
};

std::vector<RankLoad> rank_loads(const State& s, const Decomposition& d,
                                 const EntityCosts& costs = {});

}  // namespace mcdyna::solver::parallel
