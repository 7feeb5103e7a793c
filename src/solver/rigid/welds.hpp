#pragma once
/// Spot welds: each a rigid body of two nodes (compile_rigid.cpp) that fails and frees its
/// nodes. The weld's force is the constraint force its body puts on N2: m2 a2 - f2 after the
/// body's update (the acceleration the body gives the node, less the force the elements and
/// loads put on it); its normal part is along N1 -> N2, tension positive, as LS-DYNA's
/// (max(f_n, 0) / SN)^N + (|f_s| / SS)^M >= 1 reads it.
#include "solver/rigid/rigid_bodies.hpp"

#include <memory>
#include <vector>

namespace mcdyna::solver {

/// A spot weld (*CONSTRAINED_SPOTWELD, *CONSTRAINED_GENERALIZED_WELD_SPOT): the rigid body of
/// its two nodes until it fails (rigid/welds.cpp).
struct WeldState {
  model::Id id = 0;  ///< WID or its number among the welds
  Index body = -1;
  Index first = -1, last = -1;                         ///< N1 and N2: the normal runs N1 -> N2
  double normal_force = 0.0, shear_force = 0.0;        ///< SN, SS (0: no term)
  double normal_exponent = 0.0, shear_exponent = 0.0;  ///< N, M
  double failure_time = 1.0e20, plastic_strain = 1.0e20;
  Vec3 force = Vec3::Zero();  ///< the weld's force on N2 this cycle
  double normal = 0.0;        ///< its tension along the normal (compression negative)
  double shear = 0.0;         ///< its magnitude across the normal
  double failed_at = -1.0;    ///< time it failed, -1 while it holds
};

class Block;  // block.hpp

/// The block of the rigid bodies (rigid_block.cpp), which owns the welds' failure state.
std::unique_ptr<Block> make_rigid_bodies_block(std::vector<WeldState> welds);
/// Its welds, or none (for tests).
const std::vector<WeldState>& welds_of(const State& s);

/// After the rigid bodies' update: each holding weld's force, and the welds that fail this
/// cycle (force criterion, TF, or the plastic strain EP of an element at their nodes) released.
/// `force`: the nodal forces of the cycle (the weld's force is m a - f at its N2).
void check_welds(State& state, std::vector<WeldState>& welds, const Eigen::Matrix3Xd& force,
                 const StepTimes& t);

}  // namespace mcdyna::solver
