#pragma once
/// The conditions' and loads' data (SPC and *NODE TC, *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET,
/// *LOAD_BODY, *LOAD_NODE, *LOAD_RIGID_BODY, *LOAD_SEGMENT, *DAMPING_GLOBAL), each kind owned by
/// its block (condition_blocks.cpp, applied_loads.cpp, global_damping.cpp), which
/// compile_conditions.cpp and compile_loads.cpp make.
#include <array>
#include <memory>
#include <vector>

#include "solver/state.hpp"

namespace mcdyna::solver {

/// Constrained nodal degrees of freedom (SPC and *NODE TC), merged per node.
struct NodalConstraints {
  std::vector<Index> nodes;  ///< ascending
  /// bit 0 x, 1 y, 2 z; 3 rx, 4 ry, 5 rz (acting on nodes with rotations only)
  std::vector<std::uint8_t> masks;
  std::vector<double> birth, death;
  Eigen::Matrix3Xd reaction;  ///< force the constraint applies, this cycle
};

/// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET line expanded to nodes.
struct NodalMotion {
  model::Id id = 0;
  std::vector<Index> nodes;
  Vec3 axis = Vec3::UnitX();  ///< x, y, z (DOF 1-3) or the VID direction (DOF 4), unit
  MotionKind kind = MotionKind::velocity;
  Index curve = -1;
  double scale = 1.0;
  double birth = 0.0, death = 1.0e28;
  bool switched_off = false;      ///< by *SENSOR_CONTROL (sensors/)
  Eigen::Matrix3Xd node_force;    ///< per node of `nodes`, this cycle (bndout nd# lines)
  std::vector<double> node_work;  ///< per node of `nodes`, accumulated
  [[nodiscard]] Vec3 force() const { return node_force.rowwise().sum(); }
  [[nodiscard]] double work() const {
    double w = 0.0;
    for (double x : node_work)
      w += x;
    return w;
  }
};

/// *LOAD_BODY_X / _Y / _Z: base acceleration scale x curve(t) along `axis`; force -m a.
struct BodyLoadState {
  int axis = 2;
  Index curve = -1;
  double scale = 1.0;
};

/// *LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY: SF x curve(t) along `axis`, a force or a moment,
/// on each node or on a rigid body at its centre (body >= 0).
struct PointLoadState {
  std::vector<Index> nodes;
  Index body = -1;
  int axis = 0;
  bool moment = false;
  Index curve = -1;
  double scale = 1.0;
  double last = 0.0;  ///< the load last cycle, for its work
};

/// *LOAD_SEGMENT / _SET: pressure SF x curve(t - AT) on segments (a triangle repeats N3).
struct PressureLoadState {
  std::vector<std::array<Index, 4>> segments;
  Index curve = -1;
  double scale = 1.0, arrival = 0.0;
  Eigen::Matrix3Xd last;  ///< the force on each segment's corners last cycle, 4 per segment
};

/// *DAMPING_GLOBAL, compiled (curve < 0: the constant D).
struct GlobalDampingState {
  Index curve = -1;
  double value = 0.0;
  std::array<double, 6> scale{};
};

class Block;

std::unique_ptr<Block> make_nodal_constraints_block(NodalConstraints c);
std::unique_ptr<Block> make_nodal_motions_block(std::vector<NodalMotion> motions);
std::unique_ptr<Block> make_body_loads_block(std::vector<BodyLoadState> loads);
std::unique_ptr<Block> make_applied_loads_block(std::vector<PointLoadState> points,
                                                std::vector<PressureLoadState> pressures);
std::unique_ptr<Block> make_global_damping_block(GlobalDampingState damping);

}  // namespace mcdyna::solver
