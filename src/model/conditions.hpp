#pragma once
/// Contacts, boundary conditions, initial conditions and rigid walls.
#include <array>
#include <string>

#include "model/entities.hpp"

namespace mcdyna::model {

enum class ContactKind {
  automatic_nodes_to_surface,
  automatic_surface_to_surface,
  automatic_single_surface,
  nodes_to_surface,
  surface_to_surface,
  /// *CONTACT_FORCE_TRANSDUCER_PENALTY: applies nothing; reports the other contacts' forces on
  /// side A (only those from side B when B is given).
  force_transducer,
  /// *CONTACT_TIED_NODES_TO_SURFACE / _SURFACE_TO_SURFACE: side A's nodes held on side B.
  tied
};

/// Side of a contact: SURFA/SURFB with its type code (keywords.md §2.15).
struct ContactSide {
  Id id = 0;
  int type = 0;  ///< 0 segment set, 1 shell set, 2 part set, 3 part, 4 node set, 5 all, 6 exempted
  Id box = 0;
};

struct Contact {
  Id id = 0;  ///< from the _ID card; 0 = numbered in deck order
  std::string heading;
  ContactKind kind = ContactKind::automatic_nodes_to_surface;
  /// The keyword's canonical name after "CONTACT_" ("TIED_NODES_TO_SURFACE"), as the reports
  /// name the contact.
  std::string keyword;
  ContactSide a, b;                                                   ///< A = slave, B = master
  double static_friction = 0.0, dynamic_friction = 0.0, decay = 0.0;  ///< FS, FD, DC
  double viscous_friction = 0.0, viscous_damping = 0.0;               ///< VC, VDC (% of critical)
  double birth = 0.0, death = 1.0e20;
  double penalty_scale_a = 1.0, penalty_scale_b = 1.0;  ///< SFSA, SFSB
  double thickness_a = 0.0, thickness_b = 0.0;          ///< SAST, SBST
  double friction_scale = 1.0, viscous_friction_scale = 1.0;
  int soft = 0;  ///< card A SOFT
  double soft_scale = 0.1;
  double depth = 2;
  int ignore_penetration = 0;  ///< card C IGNORE
  core::SourceLoc loc;
};

/// *CONSTRAINED_EXTRA_NODES_NODE / _SET: a node (or a node set's nodes) moving with a rigid part.
struct ExtraNodes {
  Id part = 0;
  Id target = 0;  ///< node or node set
  bool is_set = false;
  core::SourceLoc loc;
};

/// *CONSTRAINED_RIGID_BODIES: rigid part `constrained` merged into rigid part `lead`.
struct RigidMerge {
  Id lead = 0, constrained = 0;
  core::SourceLoc loc;
};

/// *CONSTRAINED_NODAL_RIGID_BODY: a rigid body made of a node set's nodes.
struct NodalRigidBody {
  Id id = 0;  ///< PID: the body's ID where a rigid part ID is asked for
  Id node_set = 0;
  std::string title;
  core::SourceLoc loc, set_loc;
};

/// *CONSTRAINED_SPOTWELD (a node pair) and *CONSTRAINED_GENERALIZED_WELD_SPOT (a node set): a
/// massless rigid link, released when (max(f_n, 0) / SN)^N + (|f_s| / SS)^M >= 1, at TF, or
/// when an element at its nodes reaches the plastic strain EP.
struct SpotWeld {
  Id id = 0;                  ///< WID, 0 = numbered in deck order
  std::array<Id, 2> nodes{};  ///< _SPOTWELD N1 N2
  Id node_set = 0;            ///< _GENERALIZED_WELD_SPOT NSID (then `nodes` is unused)
  double normal_force = 0.0, shear_force = 0.0;           ///< SN, SS (0: no term)
  double normal_exponent = 0.0, shear_exponent = 0.0;     ///< N, M
  double failure_time = 1.0e20, plastic_strain = 1.0e20;  ///< TF, EP
  core::SourceLoc loc;
};

enum class JointKind { spherical, revolute, cylindrical, translational };

/// *CONSTRAINED_JOINT_SPHERICAL / REVOLUTE / CYLINDRICAL / TRANSLATIONAL: node pairs (N1, N2),
/// (N3, N4), (N5, N6), the first of each in body A.
struct Joint {
  Id id = 0;  ///< JID of the _ID card, 0 = numbered in deck order
  std::string heading;
  JointKind kind = JointKind::spherical;
  std::array<Id, 6> nodes{};
  double relative_stiffness = 1.0;  ///< RPS
  double damping = 1.0;             ///< DAMP
  core::SourceLoc loc;
};

enum class LoadTarget { node, node_set, rigid_part };

/// *LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY: SF x curve(t), a force along DOF 1-3 or a moment
/// about DOF 5-7 (global axes).
struct PointLoad {
  LoadTarget target_kind = LoadTarget::node;
  Id target = 0;
  int dof = 1;
  Id curve = 0;
  double scale = 1.0;
  core::SourceLoc loc, curve_loc;
};

/// *LOAD_SEGMENT / _SET: pressure SF x curve(t - AT) on segments, positive against their normal.
struct SegmentLoad {
  bool is_set = false;
  Id set = 0;
  std::array<Id, 4> nodes{};
  Id curve = 0;
  double scale = 1.0, arrival = 0.0;
  core::SourceLoc loc, curve_loc;
};

/// *DEFINE_COORDINATE_NODE: origin N1, x towards N2, x-y plane through N3.
struct CoordinateSystem {
  Id id = 0;
  std::array<Id, 3> nodes{};
  core::SourceLoc loc;
};

/// *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: rotational springs between rigid parts A and B about
/// the axes (phi x, theta y, psi z) of their local systems.
struct JointStiffness {
  Id id = 0;
  Id part_a = 0, part_b = 0, system_a = 0, system_b = 0;
  std::array<Id, 3> curves{};                   ///< LCIDPH, LCIDT, LCIDPS
  std::array<double, 3> elastic{}, friction{};  ///< ESPH EST ESPS, FMPH FMT FMPS
  core::SourceLoc loc;
};

/// *LOAD_BODY_X / _Y / _Z: a base acceleration SF x curve(t) along an axis; the body force on a
/// node is -m a (gravity down -z is LOAD_BODY_Z with +9.81).
struct BodyLoad {
  int axis = 2;  ///< 0 x, 1 y, 2 z
  Id curve = 0;
  double scale = 1.0;
  core::SourceLoc loc, curve_loc;
};

/// *BOUNDARY_SPC_NODE / _SET: one line.
struct SpcConstraint {
  Id id = 0;
  bool is_set = false;
  Id target = 0;  ///< node or node set
  Id coordinate_system = 0;
  std::array<bool, 6> fixed{};  ///< x, y, z, rx, ry, rz
  double birth = 0.0, death = 1.0e20;
  core::SourceLoc loc;
};

enum class MotionTarget { node, node_set, rigid_part };

/// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID: one line (+ card 2).
struct PrescribedMotion {
  Id id = 0;
  std::string heading;
  MotionTarget target_kind = MotionTarget::node;
  Id target = 0;
  int dof = 0;   ///< 1-3 translation, 4 along VID, 5-7 rotation, 8 about VID, 9-11 about axis
  int kind = 0;  ///< VAD: 0 velocity, 1 acceleration, 2 displacement, 3, 4
  Id curve = 0;
  double scale = 1.0;
  Id vector = 0;
  double death = 1.0e28, birth = 0.0;
  double offset1 = 0.0, offset2 = 0.0;
  Id lead_rigid_body = 0, node1 = 0, node2 = 0;
  core::SourceLoc loc;
  core::SourceLoc curve_loc, vector_loc;
};

enum class InitialVelocityKind { by_set, per_node, generation };

struct InitialVelocity {
  InitialVelocityKind kind = InitialVelocityKind::by_set;
  Id target = 0;        ///< node set (0 = all) / node / part set, part or node set (generation)
  Id exempted_set = 0;  ///< NSIDEX
  Id box = 0;
  int target_type = 1;      ///< generation STYP: 1 part set, 2 part, 3 node set
  Vec3 velocity{};          ///< length/time
  Vec3 angular_velocity{};  ///< VXR.. (nodal rotations)
  Vec3 exempted_velocity{};
  double omega = 0.0;  ///< generation: angular velocity about the axis (rad/time)
  Vec3 axis_point{}, axis_direction{};
  int irigid = 0;
  core::SourceLoc loc;
};

/// *RIGIDWALL_PLANAR, or one of *RIGIDWALL_GEOMETRIC's shapes.
enum class WallShape { planar, flat, prism, cylinder, sphere };

struct RigidWall {
  WallShape shape = WallShape::planar;
  Id id = 0;
  std::string heading;
  Id node_set = 0;  ///< 0 = all nodes
  Id exempted_set = 0;
  Id box = 0;
  double offset = 0.0, birth = 0.0, death = 1.0e20;
  double penalty_scale = 1.0;
  Vec3 tail{}, head{};  ///< wall point and normal head (normal into the allowed side)
  double friction = 0.0;
  double weld_velocity = 0.0;
  bool finite = false;
  Vec3 edge_head{};
  double length_l = 0.0, length_m = 0.0;
  bool moving = false;
  double mass = 0.0, initial_velocity = 0.0;
  /// Geometric walls: the prism's LENP, the cylinder's and sphere's radius, the cylinder's
  /// length (0: infinite).
  double length_p = 0.0, radius = 0.0, cylinder_length = 0.0;
  /// _MOTION: the wall translates along `motion_direction` by the curve's velocity (or, with
  /// OPT 1, displacement) at t - BIRTH.
  Id motion_curve = 0;
  bool motion_is_displacement = false;
  Vec3 motion_direction{};
  core::SourceLoc loc, motion_loc;
};

}  // namespace mcdyna::model
