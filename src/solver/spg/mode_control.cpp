// Low-energy-mode control of MC-SPG (MSC = 1, "better control of low-energy modes in slow
// deformation", keywords.md §2.6; LS-DYNA's own scheme is not published, this one is mcdyna's).
//
// Why: direct nodal integration measures the strain at particle I from its neighbours only
// (grad phi_I(X_I) = 0 on a symmetric stencil). On a lattice with the support reaching one
// layer (DX <= 2), the layers split into two interleaved sets: the positions of one set give
// the strains of the other, whose stresses in turn move the first. The two sets then behave as
// two bars that share only their ends, and under slow plastic tension each necks on its own:
// the layer gaps alternate. The MC-SPG smoothing (Eqs. 13-30) changes how fast particles move,
// not which configurations are in equilibrium, so it cannot prevent this. Measured on the
// h = 0.5 notched bar (tools/decks/tension_fracture.py) at 0.15 ms: gaps 0.32/0.86 mm beside
// the notch with plain DNI, direct or MC smoothing alike (hex FE: smooth 0.54/0.56 mm).
//
// What: the part of a particle's position that its own row does not reproduce from the
// neighbours, r_J = x_J - sum_K phi_K(X_J) x_K = (D x)_J, D = I - Phi. It vanishes for every
// affine configuration (the shape functions are linearly complete in the row's reference, so
// stretch, shear and rigid rotation of any size give r = 0) and is largest for the alternating
// layers. A stiffness on it, energy W = 1/2 sum_J c k_J |r_J|^2 with k_J = m_J c_J^2 / h_J^2
// (rho c^2 h: the element stiffness scale of FE hourglass control, c like QM), gives the
// forces f = -D^T g, g_J = c k_J r_J. sum_I f_I = 0 (the columns of D sum to zero, Eq. 21's
// partition of unity) and sum_I x_I x f_I = -sum_J r_J x g_J = 0, so linear and angular
// momentum are untouched. Its work is reported as hourglass energy.
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

Vec3 mode_residual(const State& s, const Domain& d, Index j) {
  const auto jj = static_cast<std::size_t>(j);
  const Eigen::Matrix3Xd& x = s.nodes.position;
  const Vec3 xj = x.col(d.particles.nodes[jj]);
  Vec3 r = Vec3::Zero();  // sum_K phi_K (x_J - x_K): the same as r_J by the partition of unity
  for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    r += d.kernel.shape.value[pp] *
         (xj - x.col(d.particles.nodes[static_cast<std::size_t>(d.kernel.list.neighbours[pp])]));
  }
  return r;
}

void mode_control_update(const State& s, Domain& d, Index j) {
  const auto jj = static_cast<std::size_t>(j);
  if (d.kernel.isolated[jj] ||
      d.fields.debris[jj]) {  // no row to measure with: no force, energy kept
    d.fields.mode_force.col(j).setZero();
    return;
  }
  const Vec3 r = mode_residual(s, d, j);
  const Vec3 g = d.settings.mode_control * d.fields.mode_stiffness[jj] * r;
  // Work of the forces from the last residual to this one (midpoint rule).
  d.fields.mode_energy[jj] +=
      0.5 * (d.fields.mode_force.col(j) + g).dot(r - d.fields.mode_residual.col(j));
  d.fields.mode_residual.col(j) = r;
  d.fields.mode_force.col(j) = g;
}

void mode_control_forces(const State& s, Domain& d) {
#pragma omp parallel for schedule(static, 256) if (d.count() > 512)
  for (Index j = 0; j < d.count(); ++j)
    mode_control_update(s, d, j);
}

}  // namespace mcdyna::solver::spg
