#pragma once
/// A planar rigid wall (*RIGIDWALL_PLANAR with _FINITE, _MOVING, _ID): a stonewall through
/// `point` with the unit `normal` into the allowed side. Its block (planar_walls.cpp) owns the
/// walls, as the geometric walls' block does theirs.
#include <vector>

#include "solver/state.hpp"

namespace mcdyna::solver::walls {

struct PlanarWall {
  model::Id id = 0;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  ///< unit, into the allowed side
  bool finite = false;
  Vec3 edge_l = Vec3::UnitX(), edge_m = Vec3::UnitY();  ///< unit in-plane edges (finite)
  double length_l = 0.0, length_m = 0.0;
  double friction = 0.0;
  double birth = 0.0, death = 1.0e20;
  bool switched_off = false;  ///< by *SENSOR_CONTROL (sensors/)
  bool moving = false;
  double mass = 0.0, velocity = 0.0, displacement = 0.0;  ///< along the normal
  std::vector<Index> nodes;                               ///< tracked nodes
  Vec3 force = Vec3::Zero();  ///< force on the wall this cycle (from the nodes)
  double energy = 0.0;        ///< work the wall has absorbed
};

/// The planar walls of a compiled state (empty when it has none), for tests.
const std::vector<PlanarWall>& planar_walls_of(const State& s);

}  // namespace mcdyna::solver::walls
