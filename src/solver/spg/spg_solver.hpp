#pragma once
/// The MC-SPG particle solver, called by the time loop (solver/run/driver.cpp) beside the FE
/// element pass. Per cycle, from t^n to t^{n+1}:
///   advance_velocities   Eqs. 29-30 (scatter of accelerations into unsmoothed velocities) and
///                        Eqs. 13/25 (gather smoothing into the node velocity that moves the
///                        particle, Eq. 28)
///   absorb_constraints   velocity changes made by SPC, prescribed motion and rigid walls go
///                        back into the unsmoothed velocities, momentum-consistently
///   particle_pass        kernel renewal when due (Eqs. 32-34, bond failure Eqs. 35-36), then
///                        direct nodal integration (Eqs. 5-6, 26-27): stress and internal forces
///
/// Particles whose node is shared with FE elements or carries a constraint are "pinned": their
/// velocity is integrated like an FE node's (one velocity for the node), they take part in the
/// smoothing of their neighbours as an unsmoothed value, and receive their share of the
/// neighbours' accelerations so that total momentum is kept exactly (see smoothing.cpp).
#include "solver/parallel/particle_subset.hpp"
#include "solver/spg/spg_parts.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::spg {

using parallel::member;  // particle subsets: parallel/particle_subset.hpp
using parallel::members;
using parallel::ParticleSubset;

/// First kernel, bonds of the initial configuration, unsmoothed velocities = initial velocities.
void initialise(State& s, Domain& d);

struct ParticlePassResult {
  double critical_step = 0.0;  ///< min over particles (before TSSFAC), +inf without particles
  Index controlling = -1;      ///< particle giving it
  Index inverted = -1;         ///< particle with a non-positive Jacobian or volume
  Index non_finite = -1;       ///< particle with a NaN/Inf state
};

/// Renews the kernel when due, then stress update and internal forces (added to `force`, the
/// cycle's nodal forces). `step` is the step the current velocities were integrated over (0 at
/// the start).
ParticlePassResult particle_pass(State& s, Domain& d, double step, Eigen::Matrix3Xd& force);

/// The particles' node positions, in particle order (3 x count).
Eigen::Matrix3Xd particle_positions(const State& s, const Domain& d);

/// F-hat (Eq. 33) and the velocity gradient of the node velocities (the smoothed velocity) at
/// particle j, over its current row of the neighbour list. With `half_step` = dt / 2 > 0
/// (*CONTROL_ACCURACY OSU 1) the gradient is that of the mid-step configuration,
/// L = F-hat-dot (F-hat - dt/2 F-hat-dot)^-1: a rigid rotation then gives a skew L exactly (the
/// Cayley form of the step's rotation), where L = F-hat-dot F-hat^-1 of the end of the step has
/// a symmetric part of order omega^2 dt that strains a spinning body.
struct ParticleKinematics {
  Mat3 deformation = Mat3::Identity();
  Mat3 inverse = Mat3::Identity();
  Mat3 velocity_gradient = Mat3::Zero();
  bool invertible = true;  ///< det F-hat > 0
};
ParticleKinematics particle_kinematics(const State& s, const Domain& d, Index j,
                                       double half_step = 0.0);

/// Velocity update of the domain's particles over `dt` from the nodal forces `force`, after the
/// FE velocity update (which integrated the pinned particles' own force). Returns the lowest
/// node with a non-finite velocity, or -1.
Index advance_velocities(State& s, Domain& d, const Eigen::Matrix3Xd& force, double dt);

/// After constraints and walls changed node velocities: carry the change into the unsmoothed
/// velocities (MC-SPG: m_I / m-hat_I times the change, so momentum is the wall's impulse).
void absorb_constraints(State& s, Domain& d);

/// Kernel renewal (also called by particle_pass when due): reference = current positions,
/// supports (KERNEL 0: deformed with F, Eq. 34; KERNEL 1: initial), neighbours without broken
/// bonds, shape functions, transpose, smoothed masses, pinned set.
void renew_kernel(State& s, Domain& d);

/// Smoothed masses (Eq. 20), gather weights (Eq. 14), pinning and node masses from the particle
/// masses and the current shape functions (at renewals, and after mass scaling).
void smooth_masses(State& s, Domain& d);

/// The same for the rows flagged in `rows` only (size count()), right after rows_to_renew, whose
/// current supports it uses: their neighbours and shape functions are rebuilt in the current
/// configuration and their F^n takes up F-hat; the other
/// rows keep their own reference. The transpose, smoothed masses and gather weights, which mix
/// rows, are rebuilt for all. Each row is consistent in its own reference (sum_J phi_J(X_I) = 1
/// per row), which is all Eqs. 21-23 need.
void renew_kernel(State& s, Domain& d, const std::vector<std::uint8_t>& rows);

/// A symmetric 3 x 3 tensor from its six components stored as xx yy zz xy yz zx (ITB 1's
/// moments and stabilisation stresses).
inline Mat3 symmetric_tensor(const double* s) {
  Mat3 t;
  t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return t;
}

/// The largest eigenvalue omega^2 of the part's linearised MC-SPG equations of motion (power
/// iteration, frequency.cpp): dt < 2 / omega is the critical step of the particles alone.
struct FrequencyEstimate {
  double omega_squared = 0.0;
  int iterations = 0;
  double change = 1.0;     ///< relative change of omega^2 in the last iteration
  Index particle = -1;     ///< where the mode's amplitude is largest
  int patch_products = 0;  ///< products formed on a patch only (`on_support`)
};
/// `mode`: start vector (used when it has the right size) and the mode found.
/// Uses the domain's workspace (Domain::scratch).
/// ITB 1's stabilisation is part of the operator unless `without_stabilization`.
/// `on_support`: the start vector is nonzero on a few particles (frequency_start with rows);
/// each product is then formed where it can be nonzero only (the same bits, see ProductPatch).
FrequencyEstimate largest_frequency(State& s, Domain& d, int iterations,
                                    Eigen::Matrix3Xd* mode = nullptr,
                                    bool without_stabilization = false, bool on_support = false);
/// The fixed pseudo-random start of the power iteration (the same for any thread count), on the
/// particles flagged in `rows` only (all of them when `rows` is empty).
Eigen::Matrix3Xd frequency_start(Index count, const std::vector<std::uint8_t>& rows = {});

/// `--spg-step eigen` (stiffness_length.cpp): StepBound::lengths from the current rows, times
/// StepBound::scale. Run at every renewal, after the transpose holds the new gradients; over
/// several processes each computes its own particles' lengths and every process receives all.
void update_stiffness_length(State& s, Domain& d);
/// At the first renewal, after the smoothed masses: the critical step of the initial arrangement
/// (converged power iteration), returned; with `--spg-step eigen` the lengths are scaled so that
/// the shortest particle step equals it.
double calibrate_stiffness_length(State& s, Domain& d);
/// Every cycle with `--spg-step eigen`: one power iteration from the last mode gives the current
/// critical step of the particles; the lengths are scaled so that the shortest particle step
/// (with the masses it has, StepBound::pass_step) matches it. `renewed` flags the rows renewed
/// at this cycle's check (empty: none): a few iterations started on them find a mode the
/// renewal made there before the step is taken.
void recalibrate_stiffness_length(State& s, Domain& d,
                                  const std::vector<std::uint8_t>& renewed = {});

/// The rows due for renewal at a check (every SMSTEP steps), flagged in `rows`; returns how
/// many. All of them for the Eulerian kernel and for renewal_strain 0; else the particles whose
/// Green strain relative to their reference exceeds renewal_strain (a fifth of it when the
/// particle is under compression), the rows with a neighbour that is outside its (current)
/// support by more than that share, debris rows, and, when bonds broke, the rows that hold a
/// broken pair. Measuring brings d.kernel.support to the current configuration.
Index rows_to_renew(const State& s, Domain& d, bool bonds_broke, std::vector<std::uint8_t>& rows);

/// Bonds of the initial configuration from the first neighbour list (both directions).
Bonds initial_bonds(const Domain& d);

/// Breaks the bonds that meet Eq. 36 at the current positions; returns how many broke.
long break_bonds(const State& s, Domain& d);

/// The particles split into pieces that no longer interact: connected components of the
/// current neighbour lists (pairs in each other's support with an unbroken bond). A particle
/// without neighbours is a piece of its own.
struct Pieces {
  Index pieces = 0;   ///< all components
  Index single = 0;   ///< of them, single particles
  Index largest = 0;  ///< particles in the largest
};
Pieces count_pieces(const NeighbourList& list);

/// Low-energy-mode control (MSC = 1): residual and force g_J of particle j into d.fields.mode_force
/// (the internal-force gather applies -(D^T g)), their work into d.fields.mode_energy. Run by the
/// stress pass right after the particle's stress update (its row is then in cache).
void mode_control_update(const State& s, Domain& d, Index j);

/// The same for every particle.
void mode_control_forces(const State& s, Domain& d);

/// r_J = x_J - sum_K phi_K(X_J) x_K over particle j's row (zero for degenerate rows).
Vec3 mode_residual(const State& s, const Domain& d, Index j);

/// ITB 1 (gradient_stabilization.cpp), at a renewal before F-hat is folded into F^n: the
/// stabilisation stresses of the rows flagged in `rows` (all when empty) carried into their new
/// reference, the present configuration.
void carry_stabilization(const State& s, Domain& d, const std::vector<std::uint8_t>& rows);

/// ITB 1 (gradient_stabilization.cpp): the second moments lambda^b and step factors of the
/// rows flagged in `rows` (all when empty), at their renewal, in the current configuration.
void stabilization_moments(const State& s, Domain& d, const std::vector<std::uint8_t>& rows);

/// ITB 1, after the stress pass (which left F-hat, K and G-tilde per particle): the
/// stabilisation stresses (Eq. 10) from the strain gradient of the current positions in each
/// row's reference, their forces (Eq. 9) added to `force`, their work to d.fields.mode_energy.
void strain_gradient_stabilization(const State& s, Domain& d, Eigen::Matrix3Xd& force);

/// ITB 1's stabilisation linearised with the elastic tangent (for the power iteration of
/// frequency.cpp): the forces of a displacement field x (3 x count, per particle). With `rows`
/// and `particles` (frequency.cpp's ProductPatch) only those rows' stresses and those particles'
/// forces are formed, the rest of `force` is zero: right where x is zero outside the patch.
void stabilization_operator(const Domain& d, const Material& mat, const Eigen::Matrix3Xd& x,
                            Eigen::Matrix3Xd& force, const ParticleSubset* rows = nullptr,
                            const ParticleSubset* particles = nullptr);

/// Kinetic energy (1/2 m u-hat^{n-1/2} . u-hat^{n+1/2}) and momentum of the particles whose
/// velocity is smoothed (the quantities MC-SPG conserves); pinned particles count as nodes.
struct SmoothedKinetic {
  double kinetic = 0.0, mass = 0.0;
  Vec3 momentum = Vec3::Zero();
};
SmoothedKinetic smoothed_kinetic(const State& s, const Domain& d);

}  // namespace mcdyna::solver::spg
