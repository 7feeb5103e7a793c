// ITB 1, the original SPG stabilisation (paper §2, Eqs. 7-12): nodal integration of the
// unsmoothed field (Eqs. 5-6) and, at a second point per particle, a non-residual
// stabilisation in the first-order gradient of the strain,
//   M u-dd = f_ext - f_int - f_stab,  f_stab_I = sum_J B-tilde_I(X_J)^T sigma-tilde(X_J) V_J
//   (Eqs. 8-9),  sigma-tilde = C-tilde : (grad eps . lambda^b)  (Eq. 10),
// with C-tilde isotropic from the bulk modulus and the modified shear modulus G-tilde of
// Eqs. 11-12 in place of the elasto-plastic tangent. The paper gives the structure; mcdyna's
// reading of its pieces (manual/theory.md, "ITB 1"):
// - B-tilde holds second derivatives of the shape functions (ShapeFunctions::hessian, the
//   quadratic reproducing kernel's psi^ab): e_a = d(D)/dX_a at particle J from
//   H_ab(v) = sum_K psi^ab_K(X_J) (v_K - v_J). The particles' own strain rates cannot serve:
//   the spurious modes of nodal integration are those with zero strain rate at every particle,
//   so any gradient of the particles' D is blind to them. Second derivatives are not, and they
//   vanish for every affine motion (translation, rotation, uniform stretch and shear);
// - lambda^b is the second moment of the smoothing function of Eq. 7 about the particle,
//   M_J = sum_K phi_K(X_J) (X_K - X_J)(X_K - X_J)^T: the Taylor expansion of the smoothed
//   displacement u-bar(X_J) = sum_K phi_K(X_J) u_K brings the strain gradient in with this
//   weight (the first moment is zero by linear reproduction). The stored energy is
//   1/2 sum_J V_J sum_ab M_ab e_a : C-tilde : e_b, and sigma-tilde_a = C-tilde : sum_b M_ab e_b
//   is updated in rate form like a stress (turned with the particle's spin, objectively under
//   OSU 1);
// - f_stab is the exact derivative of that work rate, V sum_a sigma-tilde_a : e_a
//   = sum_K (v_K - v_J) . sum_ab psi^ab_K(X_J) P_a col b with P_a = V sigma-tilde_a F-hat^-T:
//   equal and opposite between each row and its particles, so linear momentum is kept to
//   round-off. The work is reported as hourglass energy.
#include <Eigen/Eigenvalues>

#include <cmath>

#include "solver/material/constitutive.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

bool active(const Domain& d, Index j) {
  const auto jj = static_cast<std::size_t>(j);
  return d.isolated[jj] == 0 && d.debris[jj] == 0;
}

// The stress rotation of a particle's spin over `dt` (Jaumann, or Hughes-Winget under OSU 1).
Kinematics spin_of(const Domain& d, Index j) {
  Kinematics k{};
  for (int c = 0; c < 3; ++c)
    k.w[c] = d.gradient.spin(c, j);
  k.objective = d.settings.objective;
  return k;
}

}  // namespace

void stabilization_moments(const State& s, Domain& d, const std::vector<std::uint8_t>& rows) {
  const Index n = d.count();
  GradientStabilization& g = d.gradient;
  if (g.moment.cols() != n) {  // the first renewal; the stress pass fills spin, bulk, shear
    g.moment.setZero(6, n);
    g.stress.setZero(18, n);
    g.spin.setZero(3, n);
    g.bulk.assign(static_cast<std::size_t>(n), 0.0);
    g.shear.assign(static_cast<std::size_t>(n), 0.0);
  }
  const Eigen::Matrix3Xd& x = s.nodes.position;
#pragma omp parallel for schedule(static, 256) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (!rows.empty() && rows[jj] == 0) continue;
    const Vec3 xj = x.col(d.nodes[jj]);
    Mat3 m = Mat3::Zero();
    for (Index p = d.list.offsets[jj]; p < d.list.offsets[jj + 1]; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      const Vec3 r = x.col(d.nodes[static_cast<std::size_t>(d.list.neighbours[pp])]) - xj;
      m.noalias() += d.shape.value[pp] * r * r.transpose();
    }
    // RK functions may be negative near a surface: keep the moment positive semi-definite.
    Eigen::SelfAdjointEigenSolver<Mat3> eig;
    eig.computeDirect(m);
    const Vec3 lambda = eig.eigenvalues().cwiseMax(0.0);
    m = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
    const double moment[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(2, 0)};
    for (int c = 0; c < 6; ++c)
      g.moment(c, j) = moment[c];
  }
}

namespace {

const int kPairA[6] = {0, 1, 2, 0, 1, 2}, kPairB[6] = {0, 1, 2, 1, 2, 0};

// e_a = d(D)/dX_a, a = X, Y, Z, at row j of the particle field u (velocities, or displacements
// for the linearised operator): H_ab(u) = sum_K psi^ab_K (u_K - u_j) over the active
// neighbours, e_a = sym(sum_b H_ab(u) (x) (F-hat^-1 row b)). Adds the row's sum of psi to `own`.
void strain_gradient(const Domain& d, const Eigen::Matrix3Xd& u, Index j, const Mat3& f_inv,
                     double e[3][6], Eigen::Ref<Eigen::Matrix<double, 6, 1>> own) {
  const auto jj = static_cast<std::size_t>(j);
  Eigen::Matrix<double, 6, 3> hu = Eigen::Matrix<double, 6, 3>::Zero();  // (ab, component)
  for (Index p = d.list.offsets[jj]; p < d.list.offsets[jj + 1]; ++p) {
    const Index k = d.list.neighbours[static_cast<std::size_t>(p)];
    if (k == j || !active(d, k)) continue;
    const Eigen::Matrix<double, 6, 1> psi = d.shape.hessian.col(p);
    own += psi;
    hu.noalias() += psi * (u.col(k) - u.col(j)).transpose();
  }
  for (int a = 0; a < 3; ++a) {
    Mat3 grad = Mat3::Zero();  // d(grad_x u)/dX_a: grad(c, b') = sum_b H_ab(u_c) F^-1(b, b')
    for (int q = 0; q < 6; ++q) {
      int b = -1;
      if (kPairA[q] == a) b = kPairB[q];
      if (kPairB[q] == a && kPairA[q] != kPairB[q]) b = kPairA[q];
      if (b < 0) continue;
      grad.noalias() += hu.row(q).transpose() * f_inv.row(b);
    }
    const Mat3 sym = 0.5 * (grad + grad.transpose());
    const double comps[6] = {sym(0, 0), sym(1, 1), sym(2, 2), sym(0, 1), sym(1, 2), sym(2, 0)};
    std::copy(comps, comps + 6, e[a]);
  }
}

// M e_a (the stabilisation strain along X_a) of row j.
void moment_times(const Domain& d, Index j, const double e[3][6], double me[3][6]) {
  const double* mo = d.gradient.moment.col(j).data();
  const double m[3][3] = {{mo[0], mo[3], mo[5]}, {mo[3], mo[1], mo[4]}, {mo[5], mo[4], mo[2]}};
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 6; ++c)
      me[a][c] = m[a][0] * e[0][c] + m[a][1] * e[1][c] + m[a][2] * e[2][c];
}

// C-tilde : M e_a = 2 G (M e_a) + lambda tr(M e_a) I, the rate (or, linearised, the value) of
// sigma-tilde_a for a = X, Y, Z into `sigma` (18).
void isotropic_stresses(double shear, double lame, const double me[3][6], double sigma[18]) {
  for (int a = 0; a < 3; ++a) {
    const double trace = me[a][0] + me[a][1] + me[a][2];
    for (int c = 0; c < 6; ++c)
      sigma[6 * a + c] = 2.0 * shear * me[a][c] + (c < 3 ? lame * trace : 0.0);
  }
}

// P_a = V sigma-tilde_a F-hat^-T into column j of `p` (27 per particle).
void store_work_stress(const double* sigma, double volume, const Mat3& f_inv,
                       Eigen::Matrix<double, 27, Eigen::Dynamic>& p, Index j) {
  for (int a = 0; a < 3; ++a) {
    const double* sa = sigma + 6 * a;
    Mat3 t;
    t << sa[0], sa[3], sa[5], sa[3], sa[1], sa[4], sa[5], sa[4], sa[2];
    Eigen::Map<Mat3>(p.col(j).data() + 9 * a) = volume * t * f_inv.transpose();
  }
}

// sum_ab psi^ab P_a col b of row j.
Vec3 pushed(const Eigen::Matrix<double, 27, Eigen::Dynamic>& p,
            const Eigen::Matrix<double, 6, 1>& psi, Index j) {
  Vec3 f = Vec3::Zero();
  for (int q = 0; q < 6; ++q) {
    const Eigen::Map<const Mat3> p_a(p.col(j).data() + 9 * kPairA[q]);
    const Eigen::Map<const Mat3> p_b(p.col(j).data() + 9 * kPairB[q]);
    f += psi[q] * p_a.col(kPairB[q]);
    if (kPairA[q] != kPairB[q]) f += psi[q] * p_b.col(kPairA[q]);
  }
  return f;
}

// The forces of the work stresses: the work rate is sum_J sum_K (u_K - u_J) . pushed(psi_K, J),
// so row J pushes K by -pushed(psi^ab_K(X_J), J) and itself by pushed(its own sum, J). Per
// particle into `force` (3 x count), ascending over each transpose: the same bits on any thread
// count.
void stabilization_forces(const Domain& d, const Eigen::Matrix<double, 27, Eigen::Dynamic>& p,
                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& own,
                          Eigen::Matrix3Xd& force) {
  const Index n = d.count();
  force.resize(3, n);
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    force.col(k).setZero();
    if (!active(d, k)) continue;
    Vec3 f = pushed(p, own.col(k), k);
    for (Index t = d.transpose.offsets[kk]; t < d.transpose.offsets[kk + 1]; ++t) {
      const Index j = d.transpose.rows[static_cast<std::size_t>(t)];
      if (j == k || !active(d, j)) continue;
      f -= pushed(p, d.shape.hessian.col(d.transpose.pairs[static_cast<std::size_t>(t)]), j);
    }
    force.col(k) = f;
  }
}

}  // namespace

void strain_gradient_stabilization(State& s, Domain& d, double dt) {
  const Index n = d.count();
  GradientStabilization& g = d.gradient;
  if (!(dt > 0.0)) return;  // the first pass: nothing has moved, sigma-tilde stays as it is
  Eigen::Matrix3Xd& v = g.field;
  v.resize(3, n);
  for (Index j = 0; j < n; ++j)
    v.col(j) = s.nodes.velocity.col(d.nodes[static_cast<std::size_t>(j)]);
  g.work_stress.setZero(27, n);
  g.own_hessian.setZero(6, n);
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    double* sigma = g.stress.col(j).data();
    if (!active(d, j)) {
      for (int c = 0; c < 18; ++c)
        sigma[c] = 0.0;
      continue;
    }
    const Mat3 f_inv = Eigen::Map<const Mat3>(d.deformation.col(j).data()).inverse();
    double e[3][6], me[3][6];
    strain_gradient(d, v, j, f_inv, e, g.own_hessian.col(j));
    moment_times(d, j, e, me);
    // sigma-tilde_a += dt C-tilde : M e_a, turned with the particle's spin.
    const double shear = g.shear[jj];
    const double lame = g.bulk[jj] - 2.0 / 3.0 * shear;
    const Kinematics spin = spin_of(d, j);
    const double turn = spin.objective ? 0.5 * dt : dt;
    double rate[18];
    isotropic_stresses(shear, lame, me, rate);
    double work = 0.0;
    for (int a = 0; a < 3; ++a) {
      double* sa = sigma + 6 * a;
      rotate_stress(sa, spin, turn);
      double old[6];
      std::copy(sa, sa + 6, old);
      for (int c = 0; c < 6; ++c)
        sa[c] += dt * rate[6 * a + c];
      double mid[6];
      for (int c = 0; c < 6; ++c)
        mid[c] = 0.5 * (old[c] + sa[c]);
      work += contract(mid, e[a]) * dt;
      if (spin.objective) rotate_stress(sa, spin, turn);
    }
    store_work_stress(sigma, d.volume[jj], f_inv, g.work_stress, j);
    d.mode_energy[jj] += d.volume[jj] * work;
  }
  stabilization_forces(d, g.work_stress, g.own_hessian, g.force);
  for (Index k = 0; k < n; ++k)
    s.nodes.force.col(d.nodes[static_cast<std::size_t>(k)]) += g.force.col(k);
}

void stabilization_operator(const Domain& d, const Material& mat, const Eigen::Matrix3Xd& x,
                            Eigen::Matrix3Xd& force) {
  const Index n = d.count();
  Eigen::Matrix<double, 27, Eigen::Dynamic> p =
      Eigen::Matrix<double, 27, Eigen::Dynamic>::Zero(27, n);
  Eigen::Matrix<double, 6, Eigen::Dynamic> own =
      Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n);
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (!active(d, j)) continue;
    const Mat3 f_inv = Eigen::Map<const Mat3>(d.deformation.col(j).data()).inverse();
    double e[3][6], me[3][6];
    strain_gradient(d, x, j, f_inv, e, own.col(j));
    moment_times(d, j, e, me);
    // The elastic C (as frequency.cpp takes for nodal integration): K from the wave speed.
    const double physical = d.mass[jj] - d.added_mass[jj];
    const double rc2 =
        physical / d.volume[jj] * wave_speed_squared(mat, d.volume[jj] / d.initial_volume[jj]);
    const double shear = d.failed[jj] ? 0.0 : mat.shear_modulus;
    const double lame = rc2 - 2.0 * shear;
    double sigma[18];
    isotropic_stresses(shear, lame, me, sigma);
    store_work_stress(sigma, d.volume[jj], f_inv, p, j);
  }
  stabilization_forces(d, p, own, force);
}

}  // namespace mcdyna::solver::spg
