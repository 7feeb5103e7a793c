#pragma once
/// The joints' data (*CONSTRAINED_JOINT_*, *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED), owned by
/// their block (joints.cpp), which compile_joints.cpp makes.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "model/conditions.hpp"  // JointKind
#include "solver/state.hpp"

namespace mcdyna::solver {

/// A joint (*CONSTRAINED_JOINT_*): a penalty spring on each node pair (body A's node first)
/// along the directions the joint holds (all three, or those normal to the axis N1 -> N3).
struct JointState {
  model::Id id = 0;
  std::string heading;
  model::JointKind kind = model::JointKind::spherical;
  std::array<Index, 6> nodes{};
  int pairs = 1;
  double relative_stiffness = 1.0;  ///< RPS
  /// The smallest reduced mass of a pair, each node's mass as the force on it sees it (for a
  /// rigid body's node, the least over the directions of the mass its point answers with).
  double reduced_mass = 0.0;
  double stiffness = 0.0;     ///< RPS m* / (4 dt0^2) with the first cycle's step; 0 until then
  double initial_step = 0.0;  ///< dt0
  double energy = 0.0;        ///< stored in the springs, 1/2 k |d|^2
  Vec3 force = Vec3::Zero();  ///< on body B, summed over the pairs, this cycle
  bool switched_off = false;  ///< by *SENSOR_CONTROL (sensors/): no force
};

/// *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: rotational springs between rigid bodies A and B about
/// the axes of A's local system, the angles those of B's system turned from A's.
struct JointStiffnessState {
  model::Id id = 0;
  Index body_a = -1, body_b = -1;
  Mat3 frame_a = Mat3::Identity(), frame_b = Mat3::Identity();  ///< local axes at t = 0
  std::array<Index, 3> curves{-1, -1, -1};  ///< moment against angle, about x y z
  Vec3 elastic = Vec3::Zero(), friction = Vec3::Zero();
  Vec3 friction_moment = Vec3::Zero();  ///< the elastic-plastic part, carried
  Vec3 angles = Vec3::Zero();           ///< last cycle's
  Vec3 moment = Vec3::Zero();           ///< last cycle's, on B about A's axes
  double work = 0.0;                    ///< done on the springs (stored and dissipated)
};

class Block;

/// The block of the deck's joints (none when both lists are empty).
std::unique_ptr<Block> make_joints_block(std::vector<JointState> joints,
                                         std::vector<JointStiffnessState> stiffnesses);

/// The joint stiffnesses of a compiled state (empty when it has none), for tests.
const std::vector<JointStiffnessState>& joint_stiffnesses_of(const State& s);

}  // namespace mcdyna::solver
