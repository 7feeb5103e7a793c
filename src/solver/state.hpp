#pragma once
/// The solver state: compiled once from the model database (solver/compile.hpp), holding only what
/// the deck uses, as structs of arrays indexed by dense solver indices. User IDs are kept beside
/// the arrays for output and diagnostics only.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/entities.hpp"
#include "solver/curve.hpp"
#include "solver/material/material.hpp"
#include "solver/material/point_kinematics.hpp"
#include "solver/parallel/ownership.hpp"
#include "solver/spg/domain.hpp"

namespace mcdyna::solver {

using Index = std::int32_t;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Nodal arrays. Velocities live at half steps (central difference), everything else at t^n.
/// The forces and moments are the time loop's (nodal_forces.hpp), not the state's.
struct Nodes {
  std::vector<model::Id> ids;
  Eigen::Matrix3Xd initial, position, velocity, acceleration;
  std::vector<double> mass;        ///< lumped physical mass
  std::vector<double> added_mass;  ///< DT2MS mass scaling (zero without it)
  std::vector<Index> rigid_body;   ///< owning rigid body or -1
  /// SPG particles whose velocity comes from smoothing, not from f / m: 1 MC-SPG (Eq. 13; its
  /// momentum is carried by the unsmoothed velocity), 2 direct smoothing (Eq. 7); 0 otherwise
  std::vector<std::uint8_t> smoothed;
  /// Node -> (element * 8 + corner) of the deformable solids that touch it, in element order:
  /// the fixed summation order that makes the force gather bitwise reproducible.
  std::vector<Index> corner_offsets, corners;
  /// Rotations: the nodes of deformable shells and beams carry three rotational degrees of freedom.
  /// rotary_inertia 0 means none (solid, particle and rigid-body nodes). Angular velocities
  /// live at half steps like the velocities; previous_angular_velocity is one half step back
  /// (the kinetic energy's 1/2 I w^{n-1/2} . w^{n+1/2}).
  Eigen::Matrix3Xd angular_velocity, previous_angular_velocity;
  std::vector<double> rotary_inertia;
  /// Node -> (element * 4 + corner) of the deformable shells that touch it, in element order
  /// (the gather of their forces and moments, fixed order as for the solids).
  std::vector<Index> shell_corner_offsets, shell_corners;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
  /// Some node carries rotational degrees of freedom (and the step's forces carry moments).
  [[nodiscard]] bool rotates() const { return !rotary_inertia.empty(); }
};

enum class SolidFormulation {
  one_point,          ///< ELFORM 1: one-point quadrature + Flanagan-Belytschko hourglass control
  selective_reduced,  ///< ELFORM 2: 2x2x2 deviatoric, mean volumetric strain rate (B-bar)
};

/// How the hourglass modes are resisted: IHQ 1-3 by viscous forces, 4-5 by stiffness.
enum class HourglassForm { viscous, stiffness };

struct HourglassParams {
  HourglassForm form = HourglassForm::viscous;  ///< from IHQ
  double coefficient = 0.1;                     ///< QM
  [[nodiscard]] bool stiffness() const { return form == HourglassForm::stiffness; }
};

/// Solid elements of one part: a contiguous range [begin, end) of the element arrays.
struct SolidBlock {
  Index part = 0;
  Index begin = 0, end = 0;
  Index point_begin = 0;       ///< first integration point of the block
  int points_per_element = 1;  ///< 1 (ELFORM 1) or 8 (ELFORM 2)
  SolidFormulation formulation = SolidFormulation::one_point;
  Index material = 0;
  HourglassParams hourglass;
  BulkViscosityParams bulk_viscosity;
  /// *CONTROL_ACCURACY OSU 1 (or the part in PIDOSU): mid-step strain rates and Hughes-Winget
  /// stress rotation (solid_elements.cpp, point_kinematics.hpp).
  bool objective = false;
};

/// Deformable 8-node solids (rigid-part elements only contribute mass properties).
struct Solids {
  std::vector<model::Id> ids;
  std::vector<std::array<Index, 8>> nodes;
  std::vector<Index> part;
  std::vector<double> initial_volume, volume, mass;
  std::vector<double> pressure;          ///< element pressure (compression positive), stress
  std::vector<double> eos_energy;        ///< internal energy per initial volume (EOS materials)
  std::vector<double> temperature;       ///< JC adiabatic temperature (room temperature otherwise)
  std::vector<double> internal_energy;   ///< absolute, energy
  std::vector<double> hourglass_energy;  ///< absolute, energy
  std::vector<double> hourglass_force;   ///< 12 per element: hourglass resistance of the last pass
  std::vector<double> viscosity;         ///< bulk viscosity q of the last pass, stress
  std::vector<double> time_step;         ///< last critical step estimate (before TSSFAC)
  std::vector<double> added_mass;        ///< DT2MS mass given to the element so far
  std::vector<std::uint8_t> eroded;
  std::vector<double> corner_force;  ///< 24 per element: force on each corner node, this cycle
  std::vector<SolidBlock> blocks;
  MaterialPoints points;  ///< integration-point state (stress, plastic strain, ...)
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

enum class ShellFormulation {
  belytschko_tsay,   ///< ELFORM 2: one in-plane point, corotational, hourglass control
  fully_integrated,  ///< ELFORM 16: 2x2 in-plane points, assumed transverse shear strain
  c0_triangle,       ///< ELFORM 4: three-node Mindlin triangle, MITC3 shear (shell_c0_triangle.hpp)
};

/// How a shell's thickness follows its strain (*CONTROL_SHELL ISTUPD).
enum class ThicknessUpdate { none, membrane, plastic };

/// Shell elements of one part: a contiguous range [begin, end) of the shell arrays.
/// Integration points are numbered element by element, in-plane point by in-plane point, layer
/// by layer (bottom to top).
struct ShellBlock {
  Index part = 0;
  Index begin = 0, end = 0;
  Index point_begin = 0;
  int in_plane_points = 1;  ///< 1 (ELFORM 2) or 4 (ELFORM 16)
  int layers = 2;           ///< NIP: points through the thickness
  ShellFormulation formulation = ShellFormulation::belytschko_tsay;
  /// *CONTROL_SHELL ESORT >= 1: the block's triangles run as C0 triangles, not as degenerate
  /// quadrilaterals of its formulation.
  bool sort_triangles = false;
  Index material = 0;
  HourglassParams hourglass;       ///< IHQ, QM (membrane)
  double bending_hourglass = 0.1;  ///< QB
  double warping_hourglass = 0.1;  ///< QW
  double shear_factor = 1.0;       ///< SHRF
  /// *CONTROL_SHELL ISTUPD: constant (0), from the membrane thickness strain (1, 3) or from its
  /// plastic part only (4).
  ThicknessUpdate thickness_update = ThicknessUpdate::none;
  int plane_stress_iterations = 3;  ///< secant steps of the plane-stress return (MITER)
  /// NLOC: where the nodes sit through the thickness, 0 mid-surface, 1 top, -1 bottom (the
  /// layers sit at z = (zeta - NLOC) t / 2 from the nodes' surface).
  double reference_surface = 0.0;
  /// Layer positions through the thickness in [-1, 1] (bottom to top) and their weights
  /// (summing to 2): Gauss (QR 0) or trapezoidal (QR 1).
  std::array<double, 10> layer_z{}, layer_weight{};
};

/// The points of the shells: the full Cauchy stress in the element's corotational frame (z the
/// normal; sigma_zz = 0, plane stress), rows xx yy zz xy yz zx.
struct ShellPoints {
  Eigen::Matrix<double, 6, Eigen::Dynamic> stress;
  Eigen::Matrix<double, 6, Eigen::Dynamic> back_stress;  ///< MAT_003 kinematic part, or empty
  std::vector<double> plastic_strain, damage;
};

/// Deformable 3- and 4-node shells (a triangle repeats its third node).
struct Shells {
  std::vector<model::Id> ids;
  std::vector<std::array<Index, 4>> nodes;
  std::vector<Index> part;
  std::vector<double> initial_thickness, thickness;  ///< length
  std::vector<double> initial_area, mass;
  /// Rotary inertia each corner gives its node: the corner's mass times max(t^2 / 12, A / 8)
  /// (Belytschko, Lin and Tsay 1984) times *CONTROL_SHELL ROTASCL.
  std::vector<double> corner_inertia;
  std::vector<double> temperature;       ///< JC adiabatic temperature
  std::vector<double> internal_energy;   ///< absolute
  std::vector<double> hourglass_energy;  ///< absolute
  /// 5 per element: the hourglass resistances of the last pass, membrane x y, bending x y and
  /// warping (Belytschko-Tsay's Q^M, Q^B, Q^W).
  std::vector<double> hourglass_force;
  std::vector<double> time_step, added_mass;
  std::vector<std::uint8_t> eroded;
  /// 24 per element: force (3) then moment (3) on each corner node, global axes, this cycle.
  std::vector<double> corner_force;
  std::vector<ShellBlock> blocks;
  ShellPoints points;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

struct PartInfo {
  model::Id id = 0;
  std::string heading;
  Index material = -1;    ///< compiled deformable material, -1 for rigid parts
  Index rigid_body = -1;  ///< for MAT_020 parts
  model::Id material_id = 0;
};

/// What a prescribed motion's curve gives (VAD 0, 1, 2).
enum class MotionKind { velocity, acceleration, displacement };

/// Prescribed motion of a rigid body: one *BOUNDARY_PRESCRIBED_MOTION_RIGID line.
struct RigidMotion {
  bool rotation = false;      ///< DOF 5-8: about `axis`; DOF 1-4: along it
  Vec3 axis = Vec3::UnitX();  ///< x, y, z (DOF 1-3, 5-7) or the VID direction (4, 8), unit
  MotionKind kind = MotionKind::velocity;
  Index curve = -1;
  double scale = 1.0;
  double birth = 0.0, death = 1.0e28;
  double rotated = 0.0;  ///< angle turned under this motion so far (VAD 2 rotations)
};

struct RigidBody {
  model::Id part_id = 0;
  double mass = 0.0;
  Vec3 center = Vec3::Zero();          ///< current centre of mass
  Vec3 initial_center = Vec3::Zero();  ///< at t = 0
  Mat3 inertia0 = Mat3::Zero();        ///< about the centre, global axes at t = 0
  Mat3 rotation = Mat3::Identity();    ///< current orientation relative to t = 0
  Vec3 velocity = Vec3::Zero();        ///< centre velocity, half step
  Vec3 angular_momentum = Vec3::Zero();
  Vec3 omega = Vec3::Zero();  ///< angular velocity, half step
  Vec3 previous_velocity = Vec3::Zero(), previous_omega = Vec3::Zero();  ///< one half step back
  std::vector<Index> nodes;
  Eigen::Matrix3Xd offsets;  ///< node position - centre at t = 0
  std::array<bool, 3> fixed_translation{}, fixed_rotation{};
  std::vector<RigidMotion> motions;
  Vec3 body_force = Vec3::Zero();  ///< *LOAD_BODY on the whole mass, at the centre, this cycle
  /// *LOAD_RIGID_BODY and *DAMPING_GLOBAL at the centre, this cycle (zeroed once taken)
  Vec3 load_force = Vec3::Zero(), load_moment = Vec3::Zero();
  Vec3 force = Vec3::Zero();   ///< resultant of element, contact and wall forces on the body
  Vec3 moment = Vec3::Zero();  ///< about the centre
  Vec3 constraint_force = Vec3::Zero();  ///< supplied by constraints / prescribed motion
  Vec3 constraint_moment = Vec3::Zero();
  double constraint_work = 0.0;
  /// A failed spot weld's body: its nodes are free again (nodes cleared), it moves no more.
  bool released = false;
  [[nodiscard]] Mat3 inertia() const { return rotation * inertia0 * rotation.transpose(); }
};

/// Elements drawn but not integrated: those of rigid parts (solids and shells).
struct DisplayCells {
  std::vector<std::array<Index, 8>> solids;
  std::vector<Index> solid_parts;
  std::vector<std::array<Index, 4>> shells;  ///< triangle: nodes[3] == nodes[2]
  std::vector<Index> shell_parts;
};

struct TimeControl {
  double end_time = 0.0;
  long end_cycle = 0;
  double scale_factor = 0.9;  ///< TSSFAC
  double initial_step = 0.0;  ///< DTINIT
  double min_step_factor = 0.0;
  double mass_scaling_step = 0.0;  ///< DT2MS (signed as in the deck)
  Index max_step_curve = -1;       ///< LCTM
  /// `mcdyna run --fixed-step`: every cycle takes this step whatever the stable-step estimate
  /// says (a probe for the true critical step, tools/verify/critical_step.py; run_command also
  /// sets mass_scaling_dt to 0 so that no mass is added).
  double fixed_step = 0.0;
};

class Block;  // block.hpp
using Blocks = std::vector<std::unique_ptr<Block>>;

struct State {
  State();
  ~State();  // formulations.cpp, where a Block is complete
  State(const State&) = delete;
  State& operator=(const State&) = delete;
  State(State&&) noexcept;
  State& operator=(State&&) noexcept;

  std::string title;
  Nodes nodes;
  Solids solids;
  Shells shells;
  std::vector<spg::Domain> spg;  ///< one per SPG part
  std::vector<PartInfo> parts;
  std::vector<Material> materials;
  std::vector<RigidBody> rigid_bodies;
  DisplayCells rigid_cells;
  std::vector<LoadCurve> curves;
  TimeControl time_control;

  double time = 0.0;
  long cycle = 0;
  double step = 0.0;                   ///< last step dt^{n-1/2}
  double critical_step = 0.0;          ///< stable-step estimate of the last force pass (no TSSFAC)
  Index controlling_element = -1;      ///< solid giving the step, or -1
  std::size_t controlling_domain = 0;  ///< SPG domain of controlling_particle
  Index controlling_particle = -1;     ///< particle giving the step, or -1
  double external_work = 0.0;
  double eroded_kinetic = 0.0, eroded_internal = 0.0, eroded_hourglass = 0.0;
  double initial_energy = 0.0;
  double initial_mass = 0.0;
  double mass_scaling_dt = 0.0;  ///< TSSFAC * |DT2MS| or 0
  /// Over several processes: what this one advances and computes (not dumped: rebuilt from the
  /// deck and the process count when a run starts or restarts).
  parallel::Ownership ownership;
  /// The formulations as the time loop runs them, in the registry's order (formulations.cpp),
  /// made by compile().
  Blocks blocks;
};

}  // namespace mcdyna::solver
