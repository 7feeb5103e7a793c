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
  if (g.moment.cols() != n) {
    g.moment.setZero(6, n);
    g.stress.setZero(18, n);
    g.step_factor.assign(static_cast<std::size_t>(n), 1.0);
  }
  g.spin.setZero(3, n);
  g.bulk.assign(static_cast<std::size_t>(n), 0.0);
  g.shear.assign(static_cast<std::size_t>(n), 0.0);
  const Eigen::Matrix3Xd& x = s.nodes.position;
#pragma omp parallel for schedule(static, 256) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (!rows.empty() && rows[jj] == 0) continue;
    const Vec3 xj = x.col(d.nodes[jj]);
    Mat3 m = Mat3::Zero();
    double first = 0.0, second = 0.0;  // sum |grad phi_K|, sum |psi_K| (Frobenius)
    for (Index p = d.list.offsets[jj]; p < d.list.offsets[jj + 1]; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      const Vec3 r = x.col(d.nodes[static_cast<std::size_t>(d.list.neighbours[pp])]) - xj;
      m.noalias() += d.shape.value[pp] * r * r.transpose();
      first += d.shape.gradient.col(p).norm();
      const Eigen::Matrix<double, 6, 1> psi = d.shape.hessian.col(p);
      second += std::sqrt(psi.head<3>().squaredNorm() + 2.0 * psi.tail<3>().squaredNorm());
    }
    // RK functions may be negative near a surface: keep the moment positive semi-definite.
    Eigen::SelfAdjointEigenSolver<Mat3> eig;
    eig.computeDirect(m);
    const Vec3 lambda = eig.eigenvalues().cwiseMax(0.0);
    m = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
    const double moment[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(2, 0)};
    for (int c = 0; c < 6; ++c)
      g.moment(c, j) = moment[c];
    // Row J's nodal-integration stiffness goes as C (sum |grad phi|)^2, the stabilisation's as
    // C M (sum |psi|)^2 (Gershgorin on B^T C B and B-tilde^T C M B-tilde): the step shrinks by
    // the square root of 1 + their ratio.
    const double ratio = first > 0.0 ? m.trace() * second * second / (first * first) : 0.0;
    g.step_factor[jj] = 1.0 / std::sqrt(1.0 + ratio);
  }
}

void strain_gradient_stabilization(State& s, Domain& d, double dt) {
  const Index n = d.count();
  GradientStabilization& g = d.gradient;
  if (!(dt > 0.0)) return;  // the first pass: nothing has moved, sigma-tilde stays as it is
  const Eigen::Matrix3Xd& v = s.nodes.velocity;
  // Per particle: P_a = V sigma-tilde_a F-hat^-T (a = X, Y, Z), and the sum of its row's
  // second-derivative functions over the active neighbours (for its own force term).
  Eigen::Matrix<double, 27, Eigen::Dynamic>& work_stress = g.work_stress;
  work_stress.setZero(27, n);
  Eigen::Matrix<double, 6, Eigen::Dynamic>& own = g.own_hessian;
  own.setZero(6, n);
  const int pa[6] = {0, 1, 2, 0, 1, 2}, pb[6] = {0, 1, 2, 1, 2, 0};
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    double* sigma = g.stress.col(j).data();
    if (!active(d, j)) {
      for (int c = 0; c < 18; ++c)
        sigma[c] = 0.0;
      continue;
    }
    // Second material derivatives of the velocity over the row, H_ab(v) = sum_K psi^ab_K
    // (v_K - v_J), then the rate-of-deformation gradient along X_a:
    // e_a = sym(sum_b H_ab(v) (x) (F-hat^-1 row b)).
    const Vec3 vj = v.col(d.nodes[jj]);
    Eigen::Matrix<double, 6, 3> hv = Eigen::Matrix<double, 6, 3>::Zero();  // (ab, component)
    for (Index p = d.list.offsets[jj]; p < d.list.offsets[jj + 1]; ++p) {
      const Index k = d.list.neighbours[static_cast<std::size_t>(p)];
      if (k == j || !active(d, k)) continue;
      const Eigen::Matrix<double, 6, 1> psi = d.shape.hessian.col(p);
      own.col(j) += psi;
      hv.noalias() += psi * (v.col(d.nodes[static_cast<std::size_t>(k)]) - vj).transpose();
    }
    const Eigen::Map<const Mat3> f_hat(d.deformation.col(j).data());
    const Mat3 f_inv = f_hat.inverse();
    double e[3][6];
    for (int a = 0; a < 3; ++a) {
      Mat3 grad = Mat3::Zero();  // d(grad_x v)/dX_a: grad(c, b') = sum_b H_ab(v_c) F^-1(b, b')
      for (int q = 0; q < 6; ++q) {
        int b = -1;
        if (pa[q] == a) b = pb[q];
        if (pb[q] == a && pa[q] != pb[q]) b = pa[q];
        if (b < 0) continue;
        grad.noalias() += hv.row(q).transpose() * f_inv.row(b);
      }
      const Mat3 sym = 0.5 * (grad + grad.transpose());
      const double comps[6] = {sym(0, 0), sym(1, 1), sym(2, 2), sym(0, 1), sym(1, 2), sym(2, 0)};
      std::copy(comps, comps + 6, e[a]);
    }
    // sigma-tilde_a += dt C-tilde : sum_b M_ab e_b, turned with the particle's spin.
    const double* mo = g.moment.col(j).data();
    const double m[3][3] = {{mo[0], mo[3], mo[5]}, {mo[3], mo[1], mo[4]}, {mo[5], mo[4], mo[2]}};
    const double shear = g.shear[jj];
    const double lame = g.bulk[jj] - 2.0 / 3.0 * shear;
    const Kinematics spin = spin_of(d, j);
    const double turn = spin.objective ? 0.5 * dt : dt;
    double work = 0.0;
    const double volume = d.volume[jj];
    for (int a = 0; a < 3; ++a) {
      double me[6];
      for (int c = 0; c < 6; ++c)
        me[c] = m[a][0] * e[0][c] + m[a][1] * e[1][c] + m[a][2] * e[2][c];
      double* sa = sigma + 6 * a;
      rotate_stress(sa, spin, turn);
      double old[6];
      std::copy(sa, sa + 6, old);
      const double trace = me[0] + me[1] + me[2];
      for (int c = 0; c < 6; ++c)
        sa[c] += dt * (2.0 * shear * me[c] + (c < 3 ? lame * trace : 0.0));
      double mid[6];
      for (int c = 0; c < 6; ++c)
        mid[c] = 0.5 * (old[c] + sa[c]);
      work += contract(mid, e[a]) * dt;
      if (spin.objective) rotate_stress(sa, spin, turn);
      Mat3 t;
      t << sa[0], sa[3], sa[5], sa[3], sa[1], sa[4], sa[5], sa[4], sa[2];
      Eigen::Map<Mat3>(work_stress.col(j).data() + 9 * a) = volume * t * f_inv.transpose();
    }
    d.mode_energy[jj] += volume * work;
  }
  // Forces: the work rate is sum_J sum_K (v_K - v_J) . sum_ab psi^ab_K(X_J) P_aJ col b, so row J
  // pushes K by -sum_ab psi^ab_K(X_J) P_aJ col b and itself by the sum of those over K.
  auto pushed = [&](const Eigen::Matrix<double, 6, 1>& psi, Index j) {
    Vec3 f = Vec3::Zero();
    for (int q = 0; q < 6; ++q) {
      const Eigen::Map<const Mat3> p_a(work_stress.col(j).data() + 9 * pa[q]);
      const Eigen::Map<const Mat3> p_b(work_stress.col(j).data() + 9 * pb[q]);
      f += psi[q] * p_a.col(pb[q]);
      if (pa[q] != pb[q]) f += psi[q] * p_b.col(pa[q]);
    }
    return f;
  };
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (!active(d, k)) continue;
    Vec3 f = pushed(own.col(k), k);
    for (Index t = d.transpose.offsets[kk]; t < d.transpose.offsets[kk + 1]; ++t) {
      const Index j = d.transpose.rows[static_cast<std::size_t>(t)];
      if (j == k || !active(d, j)) continue;
      f -= pushed(d.shape.hessian.col(d.transpose.pairs[static_cast<std::size_t>(t)]), j);
    }
    s.nodes.force.col(d.nodes[kk]) += f;
  }
}

}  // namespace mcdyna::solver::spg
