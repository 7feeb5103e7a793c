#pragma once
/// A geometric rigid wall (*RIGIDWALL_GEOMETRIC_FLAT / PRISM / CYLINDER / SPHERE): a surface the
/// tracked nodes may not cross, held by the stonewall's constraint method (loads.hpp
/// land_on_wall), optionally translating by a curve (_MOTION).
#include <vector>

#include "solver/state.hpp"

namespace mcdyna::solver::walls {

enum class Shape { flat, prism, cylinder, sphere };

struct GeometricWall {
  model::Id id = 0;
  Shape shape = Shape::flat;
  /// At t = 0: the tail point, the unit normal (flat: into the allowed side; prism: its third
  /// edge; cylinder: its axis) and the edges l, m = n x l (flat, prism).
  Vec3 point = Vec3::Zero(), normal = Vec3::UnitZ();
  Vec3 edge_l = Vec3::UnitX(), edge_m = Vec3::UnitY();
  double length_l = 0.0, length_m = 0.0, length_p = 0.0;  ///< 0: infinite (flat)
  double radius = 0.0;                                    ///< cylinder, sphere
  double cylinder_length = 0.0;                           ///< 0: infinite
  double friction = 0.0;
  double birth = 0.0, death = 1.0e20;
  bool switched_off = false;  ///< by *SENSOR_CONTROL (sensors/)
  /// _MOTION: curve index (-1: none), whether it gives the displacement (else the velocity),
  /// and the unit direction.
  Index motion_curve = -1;
  bool motion_is_displacement = false;
  Vec3 motion_direction = Vec3::UnitX();
  std::vector<Index> nodes;  ///< tracked nodes
  // What changes during a run:
  Vec3 displacement = Vec3::Zero();  ///< the wall's translation so far
  Vec3 velocity = Vec3::Zero();      ///< over the last step
  Vec3 force = Vec3::Zero();         ///< on the wall from the nodes, last step
  double normal_force = 0.0;         ///< its part against the nodes' normals (> 0 in contact)
  double energy = 0.0;               ///< work the wall has absorbed
};

/// Where a point is against a wall displaced by `offset`: `gap` < 0 when it is inside the
/// wall's solid side (by that depth), with the unit `normal` out of it, toward the allowed side.
struct Penetration {
  bool inside = false;
  double gap = 0.0;
  Vec3 normal = Vec3::Zero();
};
Penetration penetration(const GeometricWall& w, const Vec3& offset, const Vec3& x);

}  // namespace mcdyna::solver::walls
