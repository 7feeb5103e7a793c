#pragma once
/// The element pass over deformable shells and the gather of their corner forces and moments.
/// Belytschko-Tsay (ELFORM 2; Belytschko, Lin and Tsay 1984, LS-DYNA's default shell): a
/// corotational frame per element from its diagonals and first side, one in-plane point,
/// Mindlin plate kinematics (membrane, curvature and transverse-shear rates from the nodal
/// velocities and angular velocities), plane-stress layers through the thickness, and hourglass
/// control of the membrane, bending and warping modes. Every element writes only its own data,
/// so results do not depend on the thread count.
#include "solver/fe/element_loop.hpp"  // ElementPassResult
#include "solver/shells/shells.hpp"

namespace mcdyna::solver {

struct ShellPassInput {
  double step = 0.0;               ///< dt the current velocities were integrated over
  double scale_factor = 0.9;       ///< TSSFAC
  double mass_scaling_step = 0.0;  ///< target dt with mass scaling (TSSFAC*|DT2MS|), 0 = off
};

ElementPassResult shell_element_pass(State& state, Shells& shells, const ShellPassInput& input);

/// Sums the shells' corner forces into the nodal forces and their corner moments into the
/// nodal moments (gather over Shells::node_corners).
void gather_shell_forces(const State& state, const Shells& shells, NodalForces& f);

/// The element's corotational axes at the current geometry, as columns e1 e2 e3 (e3 the normal):
/// its stored stresses are components on these.
Mat3 shell_axes(const Nodes& nodes, const Shells& shells, Index element);

/// Young's modulus and Poisson's ratio of a compiled material (from its G and K).
double youngs_modulus(const Material& m);
double poisson_ratio(const Material& m);

}  // namespace mcdyna::solver
