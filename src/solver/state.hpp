#pragma once
/// The solver state: compiled once from the model database (solver/run/compile.hpp), holding only
/// what the deck uses, as structs of arrays indexed by dense solver indices. User IDs are kept
/// beside the arrays for output and diagnostics only.
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
  /// Rotations: the nodes of deformable shells and beams carry three rotational degrees of freedom.
  /// rotary_inertia 0 means none (solid, particle and rigid-body nodes). Angular velocities
  /// live at half steps like the velocities; previous_angular_velocity is one half step back
  /// (the kinetic energy's 1/2 I w^{n-1/2} . w^{n+1/2}).
  Eigen::Matrix3Xd angular_velocity, previous_angular_velocity;
  std::vector<double> rotary_inertia;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
  /// Some node carries rotational degrees of freedom (and the step's forces carry moments).
  [[nodiscard]] bool rotates() const { return !rotary_inertia.empty(); }
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
  std::vector<model::Id> solid_ids;
  std::vector<std::array<Index, 4>> shells;  ///< triangle: nodes[3] == nodes[2]
  std::vector<Index> shell_parts;
  std::vector<model::Id> shell_ids;
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
  std::size_t controlling_domain = 0;  ///< SPG domain (spg_parts.hpp) of controlling_particle
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
