#pragma once
/// What the blocks give the ASCII histories (io/histories.cpp) beside the nodes and the
/// energies: their lines of rwforc, rcforc, bndout and spcforc, collected through
/// Block::add_history_records. io/ reads these records, never a formulation's state.
#include <Eigen/Core>

#include <string>
#include <vector>

#include "model/entities.hpp"  // model::Id

namespace mcdyna::solver {

struct State;

/// A rigid wall's line in rwforc and glstat: its ID, the normal force on it (positive in contact),
/// the force on it from the nodes, last step, and the work it has taken.
struct WallRecord {
  model::Id id = 0;
  double normal_force = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double energy = 0.0;
};

/// A contact interface's two lines in rcforc (keywords.md §3.2): the resultant of the contact
/// forces on each side's nodes and its moment about the origin, and the mass of the slave nodes
/// in contact. `deck_position`: the interface's place among the deck's contacts, rcforc's order.
struct ContactRecord {
  model::Id id = 0;
  std::string heading;
  std::size_t deck_position = 0;
  Eigen::Vector3d force_a = Eigen::Vector3d::Zero(), moment_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_b = Eigen::Vector3d::Zero(), moment_b = Eigen::Vector3d::Zero();
  double mass_in_contact = 0.0;
};

/// A line of bndout: the force a prescribed motion puts on one of its nodes, or the constraint
/// force and moment on a rigid part whose motion is prescribed or fixed, and the work done.
struct BoundaryRecord {
  enum class Kind { node, rigid_part };
  Kind kind = Kind::node;
  model::Id id = 0;  ///< node ID or part ID
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double energy = 0.0;
};

/// A constrained node's line in spcforc: the force its constraint applies.
struct ReactionRecord {
  model::Id node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

struct HistoryRecords {
  std::vector<WallRecord> walls;           ///< in the blocks' order
  std::vector<ContactRecord> contacts;     ///< in the deck's order of the interfaces
  std::vector<BoundaryRecord> boundaries;  ///< the prescribed nodes, then the rigid parts
  std::vector<ReactionRecord> reactions;   ///< in the blocks' order
};

/// Every block's records at the state's time, in the orders above.
HistoryRecords history_records(const State& s);

}  // namespace mcdyna::solver
