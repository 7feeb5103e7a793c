#pragma once
/// The step context (design.md §7): the nodal forces and moments of a cycle belong to the time
/// loop, not to the State. Block::forces sums them at t^n; Block::advance_velocities takes them
/// up (a = f / m for the free nodes, a rigid body's resultant, the SPG scatter of Eqs. 29-30).
/// A restart dump, taken at the top of a cycle with them computed, carries them in its resume
/// point (driver.hpp), so a continued run starts its cycle from the same forces.
#include <Eigen/Core>

namespace mcdyna::solver {

struct NodalForces {
  Eigen::Matrix3Xd force;   ///< 3 x nodes
  Eigen::Matrix3Xd moment;  ///< 3 x nodes where some node rotates (shells, beams); else no columns
  NodalForces() = default;
  NodalForces(Eigen::Index nodes, bool rotations)
      : force(Eigen::Matrix3Xd::Zero(3, nodes)),
        moment(Eigen::Matrix3Xd::Zero(3, rotations ? nodes : 0)) {}
  [[nodiscard]] bool rotations() const { return moment.cols() > 0; }
};

}  // namespace mcdyna::solver
