#pragma once
/// The element pass over deformable beams and the gather of their end forces and moments.
///
/// Both formulations are corotational and written in rates, like the shells: the local axes
/// r (N1 -> N2), s (carried by the mean spin of the two nodes, kept normal to r) and t = r x s;
/// from the nodal velocities and angular velocities the axial, twist, curvature and shear rates.
/// - Hughes-Liu (ELFORM 1; Hughes and Liu 1981, LS-DYNA's default beam): one point along the
///   length, fibres over the cross section (*SECTION_BEAM QR, CST), each a uniaxial-stress point
///   (sigma_rr, tau_rs, tau_rt) of the part's material with plasticity; transverse shear scaled
///   by SHRF.
/// - Belytschko-Schwer (ELFORM 2; Belytschko, Schwer and Klein 1977): elastic resultants, the
///   end moments from the ends' deformational rotations by the Timoshenko beam's stiffness (so a
///   tip-loaded cantilever is exact with one element), shear area SA.
/// Every element writes only its own data, so results do not depend on the thread count.
#include "solver/beams/beams.hpp"
#include "solver/fe/element_loop.hpp"  // ElementPassResult

namespace mcdyna::solver {

struct BeamPassInput {
  double step = 0.0;               ///< dt the current velocities were integrated over
  double scale_factor = 0.9;       ///< TSSFAC
  double mass_scaling_step = 0.0;  ///< target dt with mass scaling, 0 = off
  double time = 0.0;               ///< t^n, for *MAT_SPOTWELD's TFAIL
};

ElementPassResult beam_element_pass(State& state, Beams& beams, const BeamPassInput& input);

/// Sums the beams' end forces into the nodal forces and their end moments into the nodal
/// moments (gather over Nodes::beam_ends).
void gather_beam_forces(const State& state, const Beams& beams, NodalForces& f);

/// The element's local axes at the current geometry, as columns r s t.
Mat3 beam_axes(const State& state, const Beams& beams, Index element);

}  // namespace mcdyna::solver
