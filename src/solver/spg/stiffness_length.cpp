// The length that bounds a particle's stable step from the stiffness its shape functions give
// it, not from how close its nearest neighbour is.
//
// Direct nodal integration gives f_I = -sum_J V_J sigma_J grad phi_I(X_J) (Eq. 5), whose
// stiffness is K_IK = sum_J V_J grad phi_I(X_J) . C_J . grad phi_K(X_J). With |C_J| <= rho c^2
// and V_J rho_J = m_J, Gershgorin bounds the frequencies of particle I by
//   omega_I^2 <= (1 / m_I) sum_K |K_IK| <= c^2 (1 / m_I) sum_J m_J |g_IJ| G_J,
//   g_IJ = grad phi_I(X_J),  G_J = sum_K |g_KJ|  (the row J's gradients),
// so l_I = (m_I / sum_J m_J |g_IJ| G_J)^(1/2) is a length with omega_I <= c / l_I. It follows
// the kernel's support and the shape of the neighbourhood (a torn row with one-sided neighbours
// has large gradients and a short l), but not the distance of two particles squeezed together:
// two nearly coincident particles share the weight of the support and their relative motion
// meets almost no stiffness. Measured on the FDS plate at h 0.15 (manual/verification.md):
// particles pressed against the screw to 0.02 mm against 0.13 mm spacing held the step at
// 2.9e-9 s by their nearest neighbour while the state's true critical step was 1.08e-8 s.
//
// Gershgorin is loose, and by how much changes with the state (about 3.3 on the initial FDS
// plate, whose free surfaces have shape functions with negative lobes; much less under the
// screw tip), so l only ranks the particles and follows their changes from cycle to cycle; its
// scale comes from the true critical step of the particles: the largest eigenvalue of the
// linearised MC-SPG equations (frequency.cpp), by power iteration to convergence at the first
// renewal and then one iteration every second cycle from the last mode, which tracks the dominant
// mode as the state evolves. The scale is set so that the shortest particle step, with the masses
// it has and without the bulk viscosity's shortening, is 2 / omega_max; it may grow by 0.5 % per
// recalibration (a mode growing elsewhere takes the iteration a few cycles to find) and falls at
// once.
// Measured on the FDS plate at h 0.15 (manual/verification.md): nearest-neighbour lengths held
// the step at 2.6e-9 s at 24 us where bisection found the state's critical step at 1.08e-8 s,
// and Gershgorin lengths scaled once at the start blew the plate up at 9.5 us, when the critical
// step under the tip fell from 3.1e-8 to 1.9e-8 s within 30 cycles.

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/material/constitutive.hpp"
#include "solver/spg/distribution.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

namespace {
// Power iterations for the calibration: the largest eigenvalue of the initial arrangement to
// well under 1 % (measured on the FDS h 0.15 plate: relative change 1.9e-3 after 20 iterations,
// 2.2e-5 after 40, 2.4e-9 after 80).
constexpr int kCalibrationIterations = 60;
// Every kRecalibrationInterval cycles: power iterations from the last mode, and the largest
// growth of the step lengths per recalibration. One iteration costs about what the particles'
// own stress, force and smoothing passes cost together with the FE work of a cycle (17 % of a
// cycle of the FDS plate at h 0.15, perf); every second cycle halves that, and the lag is well
// inside TSSFAC: the fastest fall of the critical step seen on the FDS plate is 1.6 % per cycle
// (3.1e-8 to 1.9e-8 s within 30 cycles under the tip at 9.5 us), 3 % per interval against a
// margin of 10 %. The rows a renewal changes are checked at the cycle of the renewal.
constexpr int kRecalibrationIterations = 1;
constexpr int kRecalibrationInterval = 2;
// At a check that renewed some rows: iterations started on those rows. A renewal can make a mode
// of its own within one cycle, away from the tracked one (measured on the spinning test block
// of spg_solver_test.cpp at its mass-scaled step: 2 / omega fell from 1.59 to 1.01 x the initial
// step at one renewed surface row while the warm-started iteration stayed at 1.68, and the block
// inverted 16 cycles later).
constexpr int kRenewalIterations = 4;
constexpr double kLargestRecalibrationGrowth = 1.005;

void rescale(StepBound& b, double factor) {
  b.scale *= factor;
  for (double& l : b.lengths)
    l *= factor;
}

// |psi|, the Frobenius norm of the symmetric 3 x 3 second derivatives stored as xx yy zz xy yz zx.
double hessian_norm(const Eigen::Matrix<double, 6, 1>& psi) {
  return std::sqrt(psi.head<3>().squaredNorm() + 2.0 * psi.tail<3>().squaredNorm());
}

// ITB 1's stabilisation (gradient_stabilization.cpp) in the same bound. Linearised, row J's
// stabilisation stiffness between particles K and L is V0_J sum_ab M_ab psi_a(K) C psi_b(L)
// with psi_a(K) the row of K's second derivatives psi^ab_K(X_J) (the row's own entry carrying
// minus their sum), so |K^J_KL| <= V0_J lambda_max(M_J) rho c^2 |psi_K| |psi_L| and the
// stiffness particle I meets through the rows it belongs to is bounded by
//   sum_J m_J (V0_J / V_J) lambda_max(M_J) |psi_I(X_J)| P_J,  P_J = sum_K |psi_K(X_J)|.
// Without it the one scale of the lengths is set by the rows the stabilisation makes stiffest
// (renewed surface rows under the screw), every particle's step falls with it, and DT2MS adds
// mass everywhere: measured on FDS h 0.15, 59 x the plate's mass (manual/verification.md).
void add_stabilization_stiffness(const Domain& d, std::vector<double>& stiffness) {
  const Index n = d.count();
  const GradientStabilization& g = d.fields.gradient;
  if (d.kernel.shape.hessian.cols() != d.kernel.shape.gradient.cols() || g.moment.cols() != n)
    return;
  std::vector<double> row_weight(static_cast<std::size_t>(n), 0.0);  // m V0/V lambda_max(M) P
  std::vector<double> own(static_cast<std::size_t>(n), 0.0);         // |psi_J(X_J)|
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (d.kernel.isolated[jj] || d.fields.debris[jj]) continue;
    Eigen::Matrix<double, 6, 1> own_psi = Eigen::Matrix<double, 6, 1>::Zero();
    double sum = 0.0;
    for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
      if (d.kernel.list.neighbours[static_cast<std::size_t>(p)] == j) continue;
      own_psi += d.kernel.shape.hessian.col(p);
      sum += hessian_norm(d.kernel.shape.hessian.col(p));
    }
    own[jj] = hessian_norm(own_psi);
    Eigen::SelfAdjointEigenSolver<Mat3> eig;
    eig.computeDirect(symmetric_tensor(g.moment.col(j).data()), Eigen::EigenvaluesOnly);
    const double physical = d.particles.mass[jj] - d.particles.added_mass[jj];
    row_weight[jj] = physical * d.kernel.renewal_volume[jj] / d.fields.volume[jj] *
                     std::max(eig.eigenvalues().maxCoeff(), 0.0) * (sum + own[jj]);
  }
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    double sum = own[ii] * row_weight[ii];
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const Index j = d.kernel.transpose.rows[static_cast<std::size_t>(t)];
      if (j == i) continue;
      const auto pair = d.kernel.transpose.pairs[static_cast<std::size_t>(t)];
      sum +=
          hessian_norm(d.kernel.shape.hessian.col(pair)) * row_weight[static_cast<std::size_t>(j)];
    }
    stiffness[ii] += sum;
  }
}
}  // namespace

void update_stiffness_length(State& s, Domain& d) {
  const Index n = d.count();
  std::vector<double> row_gradient(static_cast<std::size_t>(n), 0.0);  // G_J
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index j = 0; j < n; ++j) {
    double sum = 0.0;
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(j)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(j) + 1]; ++p)
      sum += d.kernel.shape.gradient.col(p).norm();
    row_gradient[static_cast<std::size_t>(j)] = sum;
  }
  std::vector<double> stiffness(static_cast<std::size_t>(n), 0.0);  // sum_J m_J |g_IJ| G_J
#pragma omp parallel for schedule(static) if (n > 4096)
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    double sum = 0.0;  // physical masses
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto j = static_cast<std::size_t>(d.kernel.transpose.rows[static_cast<std::size_t>(t)]);
      sum += (d.particles.mass[j] - d.particles.added_mass[j]) *
             d.kernel.transpose.gradient.col(t).norm() * row_gradient[j];
    }
    stiffness[ii] = sum;
  }
  if (d.settings.stabilization == Stabilization::strain_gradient)
    add_stabilization_stiffness(d, stiffness);
  d.kernel.step_bound.lengths.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const double own = d.particles.mass[ii] - d.particles.added_mass[ii];
    d.kernel.step_bound.lengths[ii] =
        stiffness[ii] > 0.0 ? d.kernel.step_bound.scale * std::sqrt(own / stiffness[ii])
                            : std::numeric_limits<double>::infinity();
  }
  // Over several processes a particle's transpose is whole on its owner only, and the cycle's
  // step reads the lengths of every stressed row (particle_pass.cpp).
  const std::size_t domain = d.index;
  if (s.ownership.split_part(domain) != nullptr)
    timed_exchange(s, domain,
                   [&] { share_columns(s, domain, d.kernel.step_bound.lengths.data(), 1); });
}

void recalibrate_stiffness_length(State& s, Domain& d, const std::vector<std::uint8_t>& renewed) {
  if (!(d.kernel.step_bound.pass_step > 0.0) || !std::isfinite(d.kernel.step_bound.pass_step))
    return;
  if (renewed.empty() && s.cycle % kRecalibrationInterval != 0) return;
  FrequencyEstimate f =
      largest_frequency(s, d, kRecalibrationIterations, &d.kernel.step_bound.mode);
  if (!renewed.empty()) {
    Eigen::Matrix3Xd local = frequency_start(d.count(), renewed);
    const FrequencyEstimate g = largest_frequency(s, d, kRenewalIterations, &local, false, true);
    if (g.omega_squared > f.omega_squared) {  // the renewal's mode is the highest: follow it
      f = g;
      d.kernel.step_bound.mode = local;
    }
  }
  if (!(f.omega_squared > 0.0)) return;
  const double critical = 2.0 / std::sqrt(f.omega_squared);
  // Longer steps only a little at a time (the warm-started iteration may lag a mode that is
  // growing elsewhere); shorter at once.
  // pass_step carries the bulk viscosity's shortening (element_step), at least its linear term's:
  // matched to 2 / omega without it, so the step keeps that margin.
  const double damped = element_step(d.settings.bulk_viscosity, 1.0, 1.0, 0.0);
  const double ratio =
      std::min(critical * damped / d.kernel.step_bound.pass_step, kLargestRecalibrationGrowth);
  d.kernel.step_bound.critical = critical;
  if (d.kernel.step_bound.smallest_critical == 0.0 ||
      critical < d.kernel.step_bound.smallest_critical) {
    d.kernel.step_bound.smallest_critical = critical;
    d.kernel.step_bound.smallest_critical_time = s.time;
    d.kernel.step_bound.smallest_critical_particle = f.particle;
  }
  rescale(d.kernel.step_bound, ratio);
}

double calibrate_stiffness_length(State& s, Domain& d) {
  d.kernel.step_bound.mode.resize(3, 0);
  const FrequencyEstimate f =
      largest_frequency(s, d, kCalibrationIterations, &d.kernel.step_bound.mode);
  if (!(f.omega_squared > 0.0)) return 0.0;
  const double critical = 2.0 / std::sqrt(f.omega_squared);
  if (d.settings.stabilization == Stabilization::strain_gradient &&
      d.settings.step_estimate != StepEstimate::eigenvalue) {
    // ITB 1: the nearest-neighbour steps follow what the stabilisation does to the critical
    // step of the arrangement (measured on the coarse elastic-wave rod: 0.17-0.20 with it,
    // 0.199 without; a per-row Gershgorin ratio took the step to 0.061).
    Eigen::Matrix3Xd plain;
    const FrequencyEstimate g = largest_frequency(s, d, kCalibrationIterations, &plain, true);
    if (g.omega_squared > 0.0)
      d.fields.gradient.step_scale = std::min(1.0, std::sqrt(g.omega_squared / f.omega_squared));
  }
  if (d.settings.step_estimate != StepEstimate::eigenvalue) return critical;  // reported only
  const Material& mat = s.materials[static_cast<std::size_t>(d.material)];
  // Over several processes each takes its own particles (their volumes are current there).
  const parallel::ParticleShare* share = s.ownership.split_part(d.index);
  const ParticleSubset* own = share != nullptr ? &share->owned : nullptr;
  double shortest = std::numeric_limits<double>::infinity();  // min l / (c sqrt(mobility))
  for (std::size_t k = 0; k < members(own, d.count()); ++k) {
    const auto ii = static_cast<std::size_t>(member(own, k));
    if (d.kernel.isolated[ii] || !std::isfinite(d.kernel.step_bound.lengths[ii])) continue;
    const double c =
        std::sqrt(wave_speed_squared(mat, d.fields.volume[ii] / d.particles.initial_volume[ii]));
    shortest = std::min(shortest,
                        d.kernel.step_bound.lengths[ii] / (c * std::sqrt(d.kernel.mobility[ii])));
  }
  if (share != nullptr) shortest = s.ownership.comm.min(shortest);
  if (std::isfinite(shortest)) rescale(d.kernel.step_bound, critical / shortest);
  return critical;
}

}  // namespace mcdyna::solver::spg
