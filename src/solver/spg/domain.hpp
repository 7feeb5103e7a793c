#pragma once
/// The state of one SPG part (*SECTION_SOLID_SPG, ELFORM 47): its particles, their kernels and
/// shape functions in the current reference configuration, the unsmoothed velocities of MC-SPG,
/// the bonds of the initial configuration, and the material state of the one integration point
/// each particle carries. Indices are particle indices 0..count-1 unless named `node`.
#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

#include "solver/material/material.hpp"
#include "solver/material/point_kinematics.hpp"
#include "solver/spg/kernel.hpp"
#include "solver/spg/neighbours.hpp"
#include "solver/spg/shape_functions.hpp"

namespace mcdyna::solver::spg {

/// `--spg-stabilization`: how particle velocities are stabilised.
enum class Stabilization {
  none,                 ///< plain direct nodal integration (Eq. 5), no smoothing
  direct,               ///< a direct smoothing of Eq. 7 (not momentum-consistent), for studies
  momentum_consistent,  ///< MC-SPG, Eqs. 13-31 (ITB = 3, the default)
  /// The original SPG (ITB = 1, Eqs. 8-12): nodal integration of the unsmoothed field plus the
  /// non-residual strain-gradient stabilisation at a second point per particle
  /// (gradient_stabilization.cpp)
  strain_gradient
};

/// Whether the particles move with a smoothed velocity (Eq. 7 or Eq. 13); otherwise each
/// particle's node velocity is integrated plainly, as for nodal integration.
inline bool smooths_velocity(Stabilization s) {
  return s == Stabilization::direct || s == Stabilization::momentum_consistent;
}

/// ITB 1's strain-gradient stabilisation (Eqs. 9-12, gradient_stabilization.cpp), per
/// particle. Tensors are 6-vectors xx yy zz xy yz zx (tensor shear components).
struct GradientStabilization {
  /// lambda^b of Eq. 10: the second moment of the smoothing function (Eq. 7) about the
  /// particle, M_J = sum_K phi_K(X_J) (X_K - X_J) (X_K - X_J)^T in the row's reference,
  /// xx yy zz xy yz zx, taken at the row's renewal (negative eigenvalues cut to zero).
  Eigen::Matrix<double, 6, Eigen::Dynamic> moment;
  /// The strain gradients e_a = dE/dX_a = sym(F-hat^T dF-hat/dX_a) along the reference
  /// directions a = X, Y, Z of the row's last renewal (E the Green-Lagrange strain since then),
  /// 6 components each, as the last pass left them.
  Eigen::Matrix<double, 18, Eigen::Dynamic> strain;
  /// The stabilisation stresses sigma-tilde_a (Eq. 10) in the row's reference, work conjugate
  /// to e_a, updated in rate form from the increments of e and carried into the new reference
  /// at a renewal.
  Eigen::Matrix<double, 18, Eigen::Dynamic> stress;
  /// Factor of the particles' nearest-neighbour steps: the critical step of the initial
  /// arrangement with the stabilisation over that without (both by power iteration,
  /// frequency.cpp), at most 1.
  double step_scale = 1.0;
  // Of the last stress pass (rebuilt every cycle):
  std::vector<double> bulk;   ///< K = rho c^2 - 4/3 G
  std::vector<double> shear;  ///< G-tilde of Eqs. 11-12
  /// The moduli (K, G-tilde) of each particle's last stabilisation update: a stored stress is
  /// scaled down with them when they fall.
  std::vector<double> applied_bulk, applied_shear;
  // Workspace of the force pass (not dumped): V0 F-hat sigma-tilde_a (27) and
  // V0 sum_a dF/dX_a sigma-tilde_a (9) per row, and per row the sums of its second-derivative
  // functions and gradients over the active neighbours.
  Eigen::Matrix<double, 27, Eigen::Dynamic> work_stress;
  Eigen::Matrix<double, 9, Eigen::Dynamic> curvature_stress;
  Eigen::Matrix<double, 6, Eigen::Dynamic> own_hessian;
  Eigen::Matrix3Xd own_gradient, force;  ///< and the particles' stabilisation forces
};

/// Bonds: neighbour pairs of the initial configuration (either particle's support containing
/// the other), stored for both ends in CSR form with the partner ascending. A broken bond is
/// permanent and keeps the pair out of every later neighbour list (Eq. 36).
struct Bonds {
  std::vector<Index> offsets, partners;
  std::vector<std::uint8_t> broken;
  std::vector<double> length;  ///< |X_J - X_I| in the initial configuration
  [[nodiscard]] bool is_broken(Index i, Index j) const;
  [[nodiscard]] double damage(Index i) const;  ///< broken fraction of particle i's bonds
};

/// The transpose of the neighbour relation: for particle I, the pairs (J, I) of the row lists,
/// i.e. the J whose evaluation point lies in I's support (X_J in supp(phi_I)), J ascending.
/// The gather sums of the smoothing (Eqs. 13, 19, 20) and of the internal force run over it.
struct Transpose {
  std::vector<Index> offsets;
  std::vector<Index> pairs;  ///< index into the row list (NeighbourList::neighbours)
  std::vector<Index> rows;   ///< J, the row the pair belongs to
  // Per pair, in this order (contiguous for the per-step gathers):
  std::vector<double> gather;  ///< psi_I(X_J) = m-hat_J phi_I(X_J) / m_I (Eq. 14), MC-SPG
  Eigen::Matrix3Xd gradient;   ///< grad phi_I(X_J), for the internal force
};

// Rows under compression are renewed at this share of the renewal strain. Measured on the
// coarse Taylor bar (manual/verification.md): at 0.1 for every row, the kernels at the impact
// end stay Lagrangian through ~10 % compression steps, the axis layers pair up (gaps 0.028 /
// 0.027 / 0.040 / 0.034 mm at 20 us) and the step collapses to 2e-10 s by 40 us (final length
// 15.45 mm); at 0.02 they compress smoothly. At 0.02 in tension as well, the notched h = 0.5 bar
// fails away from the notch.
inline constexpr double kCompressionRenewalShare = 0.2;

/// MSC = 1: the coefficient c of the low-energy-mode stiffness c rho c^2 h (mode_control.cpp).
/// Chosen on the h = 0.5 notched bar at 0.15 ms (layer gaps beside the notch): 0.05 still
/// alternates (0.45/0.69 mm), 0.2 nearly smooth, 0.5 smooth and close to hex FE, 1.0 smooth but
/// the neck spreads (gap at the notch 0.79 mm; FE 0.99, 0.5: 0.85).
inline constexpr double kModeControl = 0.5;

/// `--spg-step`: how a particle's stable step is estimated (particle_pass.cpp step_length).
enum class StepEstimate {
  nearest_neighbour,  ///< nearest-neighbour distance at the renewal x smallest stretch
  eigenvalue  ///< stiffness length scaled every cycle to the largest eigenvalue (power iteration)
};

/// The step estimate a part gets unless `--spg-step` says otherwise: the eigenvalue estimate for
/// ITB 1, whose renewals can make a row's stabilisation far stiffer than any row of the initial
/// arrangement (FDS h 0.3 with the nearest-neighbour steps and one factor from the initial
/// arrangement: a row renewed at 0.36 ms, and a neighbour's velocity alternated and grew 2.5 x
/// per cycle until the plate inverted; the power iteration restarted on renewed rows follows
/// such modes), the nearest-neighbour one otherwise.
inline StepEstimate default_step_estimate(Stabilization s) {
  return s == Stabilization::strain_gradient ? StepEstimate::eigenvalue
                                             : StepEstimate::nearest_neighbour;
}

/// The stable step of an SPG part: the stiffness lengths of `--spg-step eigen`, the largest
/// eigenvalue tracked by power iteration (stiffness_length.cpp, frequency.cpp), and what the last
/// particle pass found (for the step log and the run summary).
struct StepBound {
  /// Per particle, the length whose step bounds its frequencies by the stiffness of its shape
  /// functions (Gershgorin), at the renewal; the step uses it times the smallest stretch since.
  /// Includes `scale`.
  std::vector<double> lengths;
  double scale = 1.0;              ///< factor of `lengths` from the eigenvalue
  double initial_critical = 0.0;   ///< 2 / omega_max of the initial arrangement (0: none)
  double critical = 0.0;           ///< 2 / omega_max at the last pass (one iteration)
  double smallest_critical = 0.0;  ///< the smallest of the run, where the mode was, when
  Index smallest_critical_particle = -1;
  double smallest_critical_time = 0.0;
  Eigen::Matrix3Xd mode;   ///< the power iteration's last vector (warm start)
  double pass_step = 0.0;  ///< shortest particle step of the last pass, with masses, no TSSFAC
  /// The smallest particle step of the last pass at the physical masses (before DT2MS mass
  /// scaling, before TSSFAC) and its particle: what the step would be without mass scaling.
  double physical = 0.0;
  Index physical_particle = -1;
};

/// KERNEL 0: each row's kernel follows its particles and is renewed when they have strained
/// (updated Lagrangian); KERNEL 1: every row renewed at every check (Eulerian).
enum class KernelUpdate { updated_lagrangian, eulerian };

struct SpgSettings {
  KernelShape shape = KernelShape::cubic_box;
  KernelUpdate kernel_update = KernelUpdate::updated_lagrangian;
  int renewal_interval = 15;  ///< SMSTEP: steps between kernel checks (bonds, distortion)
  /// KERNEL 0: at a check, the rows of the particles whose Green strain relative to their
  /// reference (norm of 1/2 (F-hat^T F-hat - I)) exceeds this (a fifth of it under compression)
  /// are renewed, and the rows holding a pair whose bond broke; 0 renews every row at every
  /// check (see renewal.cpp for why not by default). KERNEL 1 renews every row at every check.
  double renewal_strain = 0.1;
  Stabilization stabilization = Stabilization::momentum_consistent;
  /// *CONTROL_ACCURACY OSU 1 (or the part in PIDOSU): mid-step velocity gradient and
  /// Hughes-Winget stress rotation (particle_kinematics, point_kinematics.hpp).
  bool objective = false;
  bool bond_failure = false;
  double failure_strain = 1.0e11;   ///< bond: mean effective plastic strain (FS)
  double failure_stretch = 1.0e10;  ///< bond: stretch ratio (STRETCH)
  double damping = 0.0;             ///< |PDAMP|: share of neighbour velocity differences per step
  double surface_factor = 1.0;      ///< MSFAC: quadrature weight factor of surface particles
  /// MSC = 1: coefficient of the low-energy-mode stiffness (mode_control.cpp); 0 (MSC = 0): the
  /// paper's MC-SPG alone.
  double mode_control = 0.0;
  BulkViscosityParams bulk_viscosity;
  StepEstimate step_estimate = StepEstimate::nearest_neighbour;
};

/// Wall seconds per part of the particle work, for the phase table, in PhaseTimes' order
/// (spg_neighbours ...).
struct SpgTimes {
  double neighbours = 0.0, shape_functions = 0.0, smoothing = 0.0, stress = 0.0;
  double stabilization = 0.0;  ///< ITB 1: the strain-gradient stabilisation (Eqs. 8-12)
  double force = 0.0;
  double bonds = 0.0;          ///< bond failure (Eqs. 33-36) at a check
  double step_estimate = 0.0;  ///< eigenvalue step: power iteration and stiffness lengths
};

/// Wall seconds since `start`, for SpgTimes.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Buffers the per-cycle passes reuse instead of allocating them at every call. Not dumped:
/// every call fills what it reads.
struct Workspace {
  Eigen::Matrix3Xd acceleration;  ///< advance_velocities: a_J of the smoothed particles
  Eigen::Matrix3Xd change;  ///< absorb_constraints: what conditions changed, own and row ghosts
  std::vector<double> mass_factor;  ///< particle_pass with DT2MS: m / (m - added) per particle
  /// advance_velocities with PDAMP, per particle: x, the previous u-hat, m-hat and |PDAMP| / n of
  /// its row, packed in one column for the pairs that read them (smoothing.cpp PairEnd).
  Eigen::Matrix<double, 8, Eigen::Dynamic> damping_ends;
  std::vector<double> damping_removed;  ///< the same: kinetic energy PDAMP took per particle
  Eigen::Matrix<double, 9, Eigen::Dynamic> stress;  ///< frequency.cpp: linearised w sigma F^-T
  Eigen::Matrix3Xd force, hat, vector, product;     ///< frequency.cpp: f, u-hat, x and A x
};

/// What the particles are: their nodes, masses, flags and initial arrangement.
struct ParticleSet {
  std::vector<Index> nodes;          ///< node of each particle, ascending
  std::vector<double> mass;          ///< m-hat: lumped mass, constant (Eq. 20) but for DT2MS
  std::vector<double> base_mass;     ///< the node's lumped mass incl. FE elements sharing it
  std::vector<double> added_mass;    ///< DT2MS mass scaling: part of `mass` (and base_mass) added
  std::vector<double> mass_request;  ///< mass factor a row asked for this cycle (0: none)
  std::vector<std::uint8_t> shared;  ///< node also moved by FE elements, SPC or prescribed motion
  std::vector<std::uint8_t> surface;
  std::vector<double> initial_volume;
  Eigen::Matrix3Xd initial_position;  ///< X, for bond stretch (Eq. 35)
  Eigen::Matrix<double, 9, Eigen::Dynamic>
      initial_support;  ///< A0: DX/DY/DZ x spacing (particles.hpp)
};

/// The kernel: each row in its own reference configuration (renewed per row, renewal.cpp), what
/// the rows give (shape functions, transpose, smoothed masses), the bonds between particles and
/// what the particles' stable step is estimated from.
struct Kernel {
  Supports support;  ///< at the last renewal or check (S = (F A0^2 F^T)^(1/2), Eq. 34)
  Eigen::Matrix<double, 9, Eigen::Dynamic> reference_deformation;  ///< F^n (Eq. 32), col-major
  NeighbourList list;
  ShapeFunctions shape;
  Transpose transpose;
  std::vector<double> smoothed_mass;  ///< m_I (Eq. 20)
  std::vector<std::uint8_t> pinned;   ///< velocity integrated plainly, not smoothed (see smoothing)
  std::vector<double> length;         ///< characteristic length at the renewal
  /// Row I's mobility: the largest, over the particles J of row I, of m-hat_J times the
  /// Gershgorin bound of row J of MC-SPG's effective inverse mass (smoothing.cpp), relative to
  /// the largest at the first renewal, at least 1.
  /// A force on J accelerates J's smoothed velocity through 1 / m_J twice (a_J = f_J / m_J,
  /// then the gather weights m-hat_K phi_J(X_K) / m_J), so a smoothed mass m_J well below m-hat_J
  /// can raise the frequencies of every row J is in; the row's stable step is divided by the
  /// square root of this bound (renewal.cpp, smooth_masses).
  std::vector<double> mobility;
  double mobility_scale = 1.0;         ///< the largest Gershgorin bound at the first renewal
  std::vector<double> renewal_volume;  ///< volume at the renewal
  /// Largest nearest-neighbour distance x gradient norm (sum_K |grad phi_K|^2)^(1/2) of the rows
  /// at the first renewal: a row whose gradients later grow past it (an ill-conditioned, torn
  /// neighbourhood) gets the shorter length kappa / |grad phi| (renewal.cpp).
  double gradient_length_scale = 0.0;
  int steps_since_renewal = 0;
  std::vector<std::uint8_t> isolated;  ///< the same as flags: no shape functions, no stress
  Bonds bonds;
  StepBound step_bound;  ///< what the particles' stable step is estimated from and found
};

/// The particles' state: velocities, one integration point each, the stabilisation's state.
struct ParticleFields {
  std::vector<double> volume;
  /// The particle's stable step at its last stress update (with the mass it has; before
  /// TSSFAC), 0 for a particle that carries no stress: written to d3plot as `time_step`.
  std::vector<double> step;

  // Velocities (MC-SPG): unsmoothed u-hat at the half step and one step back; the smoothed
  // velocity is the node velocity (it moves the particle, Eq. 28).
  Eigen::Matrix3Xd unsmoothed, unsmoothed_previous;
  Eigen::Matrix3Xd smoothed;  ///< node velocity as smoothing left it, before constraints

  // One integration point per particle.
  MaterialPoints points;
  std::vector<double> pressure, eos_energy, temperature, viscosity;
  std::vector<double> internal_energy;
  std::vector<std::uint8_t> failed;  ///< material failure: no deviatoric stress, no tension
  Eigen::Matrix<double, 9, Eigen::Dynamic> deformation;      ///< F-hat (Eq. 33), last pass
  Eigen::Matrix<double, 9, Eigen::Dynamic> stress_gradient;  ///< w sigma F-hat^-T, last pass
  double damping_energy = 0.0;                               ///< dissipated by PDAMP

  // Low-energy-mode control (MSC = 1, mode_control.cpp), per particle: k_J = m c^2 / h^2 from
  // the last stress update, the residual r_J = x_J - sum_K phi_K(X_J) x_K and g_J = c k_J r_J.
  std::vector<double> mode_stiffness;
  Eigen::Matrix3Xd mode_residual, mode_force;
  std::vector<double> mode_energy;  ///< work of the mode-control or ITB 1 stabilisation forces
                                    ///< (hourglass energy)
  GradientStabilization gradient;   ///< ITB 1 only (empty otherwise)
  /// Particles with broken bonds whose neighbourhood inverted: no stress until their row is
  /// renewed (particle_pass.cpp).
  std::vector<std::uint8_t> debris;
};

/// What the run reports about the part (d3hsp, the summary): counts and where things happened.
struct SpgDiagnostics {
  double largest_mobility = 1.0;  ///< the largest mobility of the run so far, where and when
  Index largest_mobility_particle = -1;
  double largest_mobility_time = 0.0;
  long renewals = 0;            ///< renewal events (all rows or some)
  long renewed_rows = 0;        ///< rows rebuilt over all renewals (count() per full renewal)
  long degenerate_events = 0;   ///< renewals that found a degenerate particle
  Index first_degenerate = -1;  ///< first such particle, and when
  double first_degenerate_time = 0.0;
  long broken_bonds = 0;
  long released = 0;  ///< times a particle became debris
};

/// One SPG part: its settings, its particles, kernel and fields as separate structs, and beside
/// them what the run reports (diagnostics, timers) and a workspace.
struct Domain {
  Index part = 0;      ///< solver part index
  Index material = 0;  ///< compiled material index
  /// Its number among the SPG parts, in the blocks' order (spg_parts.hpp): the index of its
  /// share over several processes and of State::controlling_domain.
  std::size_t index = 0;
  SpgSettings settings;
  ParticleSet particles;
  Kernel kernel;
  ParticleFields fields;
  SpgDiagnostics diagnostics;
  SpgTimes times;
  Workspace scratch;

  [[nodiscard]] Index count() const { return static_cast<Index>(particles.nodes.size()); }
};

/// Eq. 14's gather at particle i of a field held per particle (3 x count): sum over the rows
/// that hold i of psi_i(X_K) field_K. The smoothing (Eq. 13), the power iteration and the
/// angular-momentum budget share it; a pinned particle keeps its own value there, not this.
inline Eigen::Vector3d gathered(const Domain& d, Index i, const Eigen::Matrix3Xd& field) {
  const auto ii = static_cast<std::size_t>(i);
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
    const auto tt = static_cast<std::size_t>(t);
    u += d.kernel.transpose.gather[tt] * field.col(d.kernel.transpose.rows[tt]);
  }
  return u;
}

}  // namespace mcdyna::solver::spg
