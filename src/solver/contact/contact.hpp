#pragma once
/// Penalty contact (keywords.md §2.15): once per cycle, after the internal forces, every active
/// interface finds the slave nodes that have penetrated a master segment (bucket-sorted
/// candidates, contact_search.cpp) and adds the penalty, friction and damping forces to the
/// nodes of both sides (contact_forces.cpp). Deterministic for any thread and process count: the
/// per-node work runs in parallel, each slave node's hit on the process that owns it, and every
/// node's forces are added in the order of one process (contact_block.cpp says how the processes
/// share the work).
#include <memory>
#include <span>
#include <vector>

#include "solver/contact/interface.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {
class Block;  // block.hpp
}  // namespace mcdyna::solver

namespace mcdyna::solver::contact {

/// The blocks of the deck's interfaces (`interfaces` in deck order, which rcforc keeps): the
/// contacts in that order, then the force transducers, which read what the contacts applied.
void add_interface_blocks(std::vector<Interface> interfaces,
                          std::vector<std::unique_ptr<Block>>& blocks);
/// The interfaces the blocks own, in deck order (the step log, tests).
std::vector<const Interface*> interfaces_of(const State& s);

/// Adds the interface's contact forces at t^n to `force` (positions at t^n, velocities at
/// t^{n-1/2}) and updates its resultants and energy.
/// `sort`: whether the candidate lists are rebuilt first (sort_due). Adds the wall seconds of its
/// exchanges between processes (and the waits in them) to `exchange_seconds`.
void interface_pass(State& s, Interface& c, bool sort, Eigen::Matrix3Xd& force,
                    double& exchange_seconds);

/// A force transducer (*CONTACT_FORCE_TRANSDUCER_PENALTY): its resultants from the forces the
/// `contacts` applied this cycle (their `computed` lists), applying none itself. Run after every
/// contact's pass.
void transducer_pass(State& s, Interface& t, std::span<const Interface* const> contacts,
                     double& exchange_seconds);

/// Whether the interface's candidate lists must be rebuilt this cycle: NSBCS cycles since the
/// last sort, or a node has moved more than half the search margin. Over several processes
/// each looks at the nodes it owns and all agree (collective).
bool sort_due(const State& s, const Interface& c);

/// Rebuilds the candidate segments of every node of every pass: the segments whose bounding box,
/// widened by the contact thickness and the search margin, holds the node.
void sort_buckets(const State& s, Interface& c);

/// What resolve_initial_penetrations found.
struct InitialPenetrations {
  long count = 0;  ///< slave nodes that start inside a master surface
  long moved = 0;  ///< of them moved onto it
  double deepest = 0.0;
  Index node = -1;  ///< the deepest one
};

/// At t = 0, the slave nodes that start inside a master surface. With IGNORE 0 (LS-DYNA's
/// default) FE nodes are moved onto the surface (initial and current position); SPG particles
/// (their kernels are built on the generating mesh) and rigid-body nodes, and every node under
/// IGNORE 1/2, keep their depth as an offset that contact only pushes beyond (`particle`: per
/// node, an SPG particle's).
InitialPenetrations resolve_initial_penetrations(State& s, Interface& c,
                                                 const std::vector<std::uint8_t>& particle);

}  // namespace mcdyna::solver::contact
