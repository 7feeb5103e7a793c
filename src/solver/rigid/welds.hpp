#pragma once
/// Spot welds: each a rigid body of two nodes (compile_rigid.cpp) that fails and frees its
/// nodes. The weld's force is the constraint force its body puts on N2: m2 a2 - f2 after the
/// body's update (the acceleration the body gives the node, less the force the elements and
/// loads put on it); its normal part is along N1 -> N2, tension positive, as LS-DYNA's
/// (max(f_n, 0) / SN)^N + (|f_s| / SS)^M >= 1 reads it.
#include "solver/rigid/rigid_bodies.hpp"

namespace mcdyna::solver {

/// After the rigid bodies' update: each holding weld's force, and the welds that fail this
/// cycle (force criterion, TF, or the plastic strain EP of an element at their nodes) released.
/// `force`: the nodal forces of the cycle (the weld's force is m a - f at its N2).
void check_welds(State& state, const Eigen::Matrix3Xd& force, const StepTimes& t);

}  // namespace mcdyna::solver
