// ITB 1, the original SPG stabilisation (paper §2, Eqs. 7-12): nodal integration of the
// unsmoothed field (Eqs. 5-6) and, at a second point per particle, a non-residual
// stabilisation in the first-order gradient of the strain,
//   M u-dd = f_ext - f_int - f_stab,  f_stab_I = sum_J B-tilde_I(X_J)^T sigma-tilde(X_J) V_J
//   (Eqs. 8-9),  sigma-tilde = C-tilde : (grad eps . lambda^b)  (Eq. 10),
// with C-tilde isotropic from the bulk modulus and the modified shear modulus G-tilde of
// Eqs. 11-12 in place of the elasto-plastic tangent. The paper gives the structure; mcdyna's
// reading of its pieces (manual/theory.md, "ITB 1"):
// - B-tilde holds second derivatives of the shape functions (ShapeFunctions::hessian, the
//   quadratic reproducing kernel's psi^ab, exactly zero on every linear field): the curvature
//   of the motion in row J's reference (its last renewal), dF/dX_a with
//   (dF/dX_a)_cb = sum_K psi^ab_K(X_J) (x_K - x_J)_c. The particles' own strains cannot serve:
//   the spurious modes of nodal integration are those with zero strain at every particle, so
//   any gradient of the particles' strains is blind to them; second derivatives are not;
// - Eq. 10 is written for small strain. In the row's reference (its last renewal) the strain
//   gradient is that of the Green-Lagrange strain, e_a = dE/dX_a = sym(F^T dF/dX_a): zero for
//   every affine motion, unchanged by any rotation (objective without a stress rotation), and
//   the small-strain grad eps where F = I. lambda^b is the second moment of the smoothing
//   function of Eq. 7 about the particle, M_J = sum_K phi_K(X_J) (X_K - X_J)(X_K - X_J)^T: the
//   Taylor expansion of the smoothed displacement u-bar(X_J) = sum_K phi_K(X_J) u_K brings the
//   strain gradient in with this weight (the first moment is zero by linear reproduction);
// - sigma-tilde_a is updated in rate form, += C-tilde : M (e_a^{n+1} - e_a^n), as the paper's
//   stress update with G-tilde implies, in the row's reference (so work conjugate to e_a). At a
//   renewal it is carried into the new reference: with X' = F X, e_a = sum_d F_da F^T e'_d F
//   to first order, so sigma-tilde'_d = (V0 / V0') sum_a F_da F sigma-tilde_a F^T keeps the
//   work rate. Where G-tilde (or K) falls, the stored stress is first scaled down with it: a
//   stress built at a high modulus and released at a far lower one (plastic flow drops G-tilde
//   by orders of magnitude) would otherwise return more work than it took and feed the motion
//   (measured on the coarse Taylor bar before this scaling: -2.1e5 N mm of stabilisation work,
//   as large as the internal energy, by 5.6 us, and an inversion at 5.8 us). With it the
//   stored energy 1/2 sigma-tilde : C-tilde^-1 : sigma-tilde never exceeds the work done, so
//   the stabilisation only stores or dissipates;
// - f_stab follows from the work rate V0 sum_a sigma-tilde_a : e-dot_a, which is
//   sum_K (v_K - v_J) . [sum_ab psi^ab_K P_a col b + Q grad phi_K(X_J)], P_a = V0 F
//   sigma-tilde_a, Q = V0 sum_a dF/dX_a sigma-tilde_a: equal and opposite between each row and
//   its particles, so linear momentum is kept to round-off. The work is reported as hourglass
//   energy;
// - only rows are gated by state (an inactive row carries no stress); every neighbour of a row
//   enters its sums whatever its state. A row keeps inactive neighbours until its next renewal,
//   and skipping them breaks the sum-to-zero of the psi^ab on linear fields: on FDS h 0.3 a row
//   with a newly isolated neighbour jumped from |e| 0 to 8.1 in one cycle, its 1.0e3 N push
//   threw a particle to 7e5 mm/s and the plate inverted at 23.6 us.
#include <Eigen/Eigenvalues>

#include <cmath>

#include "solver/material/constitutive.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {

bool active(const Domain& d, Index j) {
  const auto jj = static_cast<std::size_t>(j);
  return d.kernel.isolated[jj] == 0 && d.fields.debris[jj] == 0;
}

// The inverse of symmetric_tensor(): a symmetric t as xx yy zz xy yz zx into `out`.
void store_symmetric(const Mat3& t, double* out) {
  const double comps[6] = {t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0)};
  std::copy(comps, comps + 6, out);
}

}  // namespace

void stabilization_moments(const State& s, Domain& d, const std::vector<std::uint8_t>& rows) {
  const Index n = d.count();
  GradientStabilization& g = d.fields.gradient;
  if (g.moment.cols() != n) {  // the first renewal; the stress pass fills bulk and shear
    g.moment.setZero(6, n);
    g.strain.setZero(18, n);
    g.stress.setZero(18, n);
    g.bulk.assign(static_cast<std::size_t>(n), 0.0);
    g.shear.assign(static_cast<std::size_t>(n), 0.0);
    g.applied_bulk.assign(static_cast<std::size_t>(n), 0.0);
    g.applied_shear.assign(static_cast<std::size_t>(n), 0.0);
  }
  const Eigen::Matrix3Xd& x = s.nodes.position;
#pragma omp parallel for schedule(static, 256) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (!rows.empty() && rows[jj] == 0) continue;
    // A new reference: e = 0 exactly (the second-derivative functions vanish on the linear
    // field of the present positions); sigma-tilde was carried over (carry_stabilization).
    g.strain.col(j).setZero();
    const Vec3 xj = x.col(d.particles.nodes[jj]);
    Mat3 m = Mat3::Zero();
    for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      const Vec3 r =
          x.col(d.particles.nodes[static_cast<std::size_t>(d.kernel.list.neighbours[pp])]) - xj;
      m.noalias() += d.kernel.shape.value[pp] * r * r.transpose();
    }
    // RK functions may be negative near a surface: keep the moment positive semi-definite.
    Eigen::SelfAdjointEigenSolver<Mat3> eig;
    eig.computeDirect(m);
    const Vec3 lambda = eig.eigenvalues().cwiseMax(0.0);
    m = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
    store_symmetric(m, g.moment.col(j).data());
  }
}

namespace {

const int kPairA[6] = {0, 1, 2, 0, 1, 2}, kPairB[6] = {0, 1, 2, 1, 2, 0};

// The curvature of the particle field u (positions, or a displacement for the linearised
// operator) in row j's reference: (G_a)_cb = sum_K psi^ab_K (u_K - u_j)_c over all its
// neighbours. Adds the row's sums of psi and of grad phi over them to `own_psi`, `own_grad`.
void curvature(const Domain& d, const Eigen::Matrix3Xd& u, Index j, Mat3 g[3],
               Eigen::Ref<Eigen::Matrix<double, 6, 1>> own_psi, Eigen::Ref<Vec3> own_grad) {
  const auto jj = static_cast<std::size_t>(j);
  Eigen::Matrix<double, 6, 3> hu = Eigen::Matrix<double, 6, 3>::Zero();  // (ab, component)
  for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
    const Index k = d.kernel.list.neighbours[static_cast<std::size_t>(p)];
    if (k == j) continue;
    const Eigen::Matrix<double, 6, 1> psi = d.kernel.shape.hessian.col(p);
    own_psi += psi;
    own_grad += d.kernel.shape.gradient.col(p);
    hu.noalias() += psi * (u.col(k) - u.col(j)).transpose();
  }
  for (int q = 0; q < 6; ++q) {
    g[kPairA[q]].col(kPairB[q]) = hu.row(q).transpose();
    g[kPairB[q]].col(kPairA[q]) = hu.row(q).transpose();
  }
}

// e_a = sym(F^T G_a) as 6-vectors.
void strain_gradients(const Mat3& f, const Mat3 g[3], double e[18]) {
  for (int a = 0; a < 3; ++a) {
    const Mat3 t = f.transpose() * g[a];
    store_symmetric(0.5 * (t + t.transpose()), e + 6 * a);
  }
}

// sigma-tilde_a = C-tilde : sum_b M_ab e_b = 2 G (M e)_a + lambda tr((M e)_a) I for a = X, Y, Z.
void stabilization_stresses(const Domain& d, Index j, double shear, double lame, const double e[18],
                            double sigma[18]) {
  const double* mo = d.fields.gradient.moment.col(j).data();
  const double m[3][3] = {{mo[0], mo[3], mo[5]}, {mo[3], mo[1], mo[4]}, {mo[5], mo[4], mo[2]}};
  for (int a = 0; a < 3; ++a) {
    double me[6];
    for (int c = 0; c < 6; ++c)
      me[c] = m[a][0] * e[c] + m[a][1] * e[6 + c] + m[a][2] * e[12 + c];
    const double trace = me[0] + me[1] + me[2];
    for (int c = 0; c < 6; ++c)
      sigma[6 * a + c] = 2.0 * shear * me[c] + (c < 3 ? lame * trace : 0.0);
  }
}

// P_a = V0 F sigma-tilde_a into column j of `p` (27), and Q = V0 sum_a G_a sigma-tilde_a into
// column j of `q` (9; left out by the linearised operator, `g` null).
void store_work_stresses(const double* sigma, double volume, const Mat3& f, const Mat3* g,
                         Eigen::Matrix<double, 27, Eigen::Dynamic>& p,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& q, Index j) {
  Mat3 curv = Mat3::Zero();
  for (int a = 0; a < 3; ++a) {
    const Mat3 t = symmetric_tensor(sigma + 6 * a);
    Eigen::Map<Mat3>(p.col(j).data() + 9 * a) = volume * f * t;
    if (g != nullptr) curv.noalias() += volume * g[a] * t;
  }
  Eigen::Map<Mat3>(q.col(j).data()) = curv;
}

// What row j pushes its particle K with (K's functions psi, grad phi in the row):
// sum_ab psi^ab P_a col b + Q grad phi (q null: without the Q term).
Vec3 pushed(const Eigen::Matrix<double, 27, Eigen::Dynamic>& p,
            const Eigen::Matrix<double, 9, Eigen::Dynamic>* q,
            const Eigen::Matrix<double, 6, 1>& psi, const Vec3& grad, Index j) {
  Vec3 f = q != nullptr ? Vec3(Eigen::Map<const Mat3>(q->col(j).data()) * grad) : Vec3::Zero();
  for (int c = 0; c < 6; ++c) {
    const Eigen::Map<const Mat3> p_a(p.col(j).data() + 9 * kPairA[c]);
    const Eigen::Map<const Mat3> p_b(p.col(j).data() + 9 * kPairB[c]);
    f += psi[c] * p_a.col(kPairB[c]);
    if (kPairA[c] != kPairB[c]) f += psi[c] * p_b.col(kPairA[c]);
  }
  return f;
}

// The forces of the work stresses: the work rate is sum_J sum_K (v_K - v_J) . pushed(K, J), so
// row J pushes K by -pushed(K, J) and itself by pushed(its own sums, J). Per particle into
// `force` (3 x count), ascending over each transpose: the same bits on any thread count. With
// `particles`, those only and zero elsewhere.
void stabilization_forces(const Domain& d, const Eigen::Matrix<double, 27, Eigen::Dynamic>& p,
                          const Eigen::Matrix<double, 9, Eigen::Dynamic>* q,
                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& own_psi,
                          const Eigen::Matrix3Xd& own_grad, Eigen::Matrix3Xd& force,
                          const ParticleSubset* particles = nullptr) {
  const Index n = d.count();
  if (particles != nullptr)
    force.setZero(3, n);
  else
    force.resize(3, n);
  const auto count = static_cast<std::int64_t>(members(particles, n));
#pragma omp parallel for schedule(static, 256) if (count > 512)
  for (std::int64_t r = 0; r < count; ++r) {
    const Index k = member(particles, static_cast<std::size_t>(r));
    const auto kk = static_cast<std::size_t>(k);
    Vec3 f = pushed(p, q, own_psi.col(k), own_grad.col(k), k);
    for (Index t = d.kernel.transpose.offsets[kk]; t < d.kernel.transpose.offsets[kk + 1]; ++t) {
      const Index j = d.kernel.transpose.rows[static_cast<std::size_t>(t)];
      if (j == k || !active(d, j)) continue;
      const auto pair = d.kernel.transpose.pairs[static_cast<std::size_t>(t)];
      f -= pushed(p, q, d.kernel.shape.hessian.col(pair), d.kernel.transpose.gradient.col(t), j);
    }
    force.col(k) = f;
  }
}

// Scales the deviatoric and the volumetric parts of the stored sigma-tilde_a down with the
// moduli where they fell since the last update (never up: that would create stored energy).
void soften(double sigma[18], double old_shear, double shear, double old_bulk, double bulk) {
  const double s_dev = old_shear > shear && old_shear > 0.0 ? shear / old_shear : 1.0;
  const double s_vol = old_bulk > bulk && old_bulk > 0.0 ? bulk / old_bulk : 1.0;
  if (s_dev == 1.0 && s_vol == 1.0) return;
  for (int a = 0; a < 3; ++a) {
    double* t = sigma + 6 * a;
    const double mean = (t[0] + t[1] + t[2]) / 3.0;
    for (int c = 0; c < 6; ++c)
      t[c] = s_dev * (t[c] - (c < 3 ? mean : 0.0)) + (c < 3 ? s_vol * mean : 0.0);
  }
}

// Row j's sigma-tilde and e advanced to the positions x (F its F-hat there, curv its
// curvature): sigma-tilde += C-tilde : M (e - e_last), after scaling down with fallen moduli,
// and the step's work, trapezoidal in the stresses the forces saw at either end, into
// d.fields.mode_energy.
void advance_row(Domain& d, Index j, const Mat3& f, const Mat3 curv[3]) {
  GradientStabilization& g = d.fields.gradient;
  const auto jj = static_cast<std::size_t>(j);
  double* sigma = g.stress.col(j).data();
  double* strain = g.strain.col(j).data();
  double e[18], de[18];
  strain_gradients(f, curv, e);
  for (int c = 0; c < 18; ++c)
    de[c] = e[c] - strain[c];
  const double shear = g.shear[jj], bulk = g.bulk[jj];
  double rate[18];
  stabilization_stresses(d, j, shear, bulk - 2.0 / 3.0 * shear, de, rate);
  double work = 0.0;
  for (int a = 0; a < 3; ++a)
    work += 0.5 * contract(sigma + 6 * a, de + 6 * a);
  soften(sigma, g.applied_shear[jj], shear, g.applied_bulk[jj], bulk);
  for (int c = 0; c < 18; ++c)
    sigma[c] += rate[c];
  for (int a = 0; a < 3; ++a)
    work += 0.5 * contract(sigma + 6 * a, de + 6 * a);
  g.applied_shear[jj] = shear;
  g.applied_bulk[jj] = bulk;
  std::copy(e, e + 18, strain);
  d.fields.mode_energy[jj] += d.kernel.renewal_volume[jj] * work;
}

// Sized workspaces of the force pass, zeroed.
void clear_workspace(GradientStabilization& g, Index n) {
  g.work_stress.setZero(27, n);
  g.curvature_stress.setZero(9, n);
  g.own_hessian.setZero(6, n);
  g.own_gradient.setZero(3, n);
}

}  // namespace

void carry_stabilization(const State& s, Domain& d, const std::vector<std::uint8_t>& rows) {
  GradientStabilization& g = d.fields.gradient;
  const Index n = d.count();
  if (g.stress.cols() != n) return;  // the first renewal: nothing stored yet
  const Eigen::Matrix3Xd x = particle_positions(s, d);
#pragma omp parallel for schedule(static, 256) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if ((!rows.empty() && rows[jj] == 0) || !active(d, j)) continue;
    // The step that brought the row here is finished in its old reference first (its work and
    // stress increment would otherwise be lost at every renewal).
    const ParticleKinematics k = particle_kinematics(s, d, j, 0.0);
    if (!k.invertible) continue;
    const Mat3& f = k.deformation;
    Mat3 curv[3];
    Eigen::Matrix<double, 6, 1> own_psi = Eigen::Matrix<double, 6, 1>::Zero();  // unused here
    Vec3 own_grad = Vec3::Zero();
    curvature(d, x, j, curv, own_psi, own_grad);
    advance_row(d, j, f, curv);
    const double ratio = 1.0 / f.determinant();  // V0 / V0'
    Mat3 pushed[3];
    for (int a = 0; a < 3; ++a)
      pushed[a] = ratio * f * symmetric_tensor(g.stress.col(j).data() + 6 * a) * f.transpose();
    for (int dd = 0; dd < 3; ++dd) {
      store_symmetric(f(dd, 0) * pushed[0] + f(dd, 1) * pushed[1] + f(dd, 2) * pushed[2],
                      g.stress.col(j).data() + 6 * dd);
    }
  }
}

void strain_gradient_stabilization(const State& s, Domain& d, Eigen::Matrix3Xd& force) {
  const Index n = d.count();
  GradientStabilization& g = d.fields.gradient;
  const Eigen::Matrix3Xd x = particle_positions(s, d);
  clear_workspace(g, n);
#pragma omp parallel for schedule(static, 256) if (n > 512)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    double* sigma = g.stress.col(j).data();
    if (!active(d, j)) {
      std::fill(sigma, sigma + 18, 0.0);
      g.strain.col(j).setZero();
      continue;
    }
    const Mat3 f = Eigen::Map<const Mat3>(d.fields.deformation.col(j).data());
    Mat3 curv[3];
    curvature(d, x, j, curv, g.own_hessian.col(j), g.own_gradient.col(j));
    advance_row(d, j, f, curv);
    store_work_stresses(sigma, d.kernel.renewal_volume[jj], f, curv, g.work_stress,
                        g.curvature_stress, j);
  }
  stabilization_forces(d, g.work_stress, &g.curvature_stress, g.own_hessian, g.own_gradient,
                       g.force);
  for (Index k = 0; k < n; ++k)
    force.col(d.particles.nodes[static_cast<std::size_t>(k)]) += g.force.col(k);
}

void stabilization_operator(const Domain& d, const Material& mat, const Eigen::Matrix3Xd& x,
                            Eigen::Matrix3Xd& force, const ParticleSubset* rows,
                            const ParticleSubset* particles) {
  const Index n = d.count();
  GradientStabilization w;
  clear_workspace(w, n);
  const auto count = static_cast<std::int64_t>(members(rows, n));
#pragma omp parallel for schedule(static, 256) if (count > 512)
  for (std::int64_t r = 0; r < count; ++r) {
    const Index j = member(rows, static_cast<std::size_t>(r));
    const auto jj = static_cast<std::size_t>(j);
    if (!active(d, j)) continue;
    // Linearised about the present state with its curvature neglected: de_a = sym(F^T dG_a).
    const Mat3 f = Eigen::Map<const Mat3>(d.fields.deformation.col(j).data());
    Mat3 curv[3];
    curvature(d, x, j, curv, w.own_hessian.col(j), w.own_gradient.col(j));
    double e[18];
    strain_gradients(f, curv, e);
    // The elastic C (as frequency.cpp takes for nodal integration): K from the wave speed.
    const double physical = d.particles.mass[jj] - d.particles.added_mass[jj];
    const double rc2 =
        physical / d.fields.volume[jj] *
        wave_speed_squared(mat, d.fields.volume[jj] / d.particles.initial_volume[jj]);
    const double shear = d.fields.failed[jj] ? 0.0 : mat.shear_modulus;
    double sigma[18];
    stabilization_stresses(d, j, shear, rc2 - 2.0 * shear, e, sigma);
    store_work_stresses(sigma, d.kernel.renewal_volume[jj], f, nullptr, w.work_stress,
                        w.curvature_stress, j);
  }
  // No Q (null): the linearised curvature stress is left out, so the gradient sums push nothing.
  stabilization_forces(d, w.work_stress, nullptr, w.own_hessian, w.own_gradient, force, particles);
}

}  // namespace mcdyna::solver::spg
