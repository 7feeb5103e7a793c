#pragma once
/// Penalty contact state (*CONTACT_[AUTOMATIC_]NODES_TO_SURFACE / SURFACE_TO_SURFACE,
/// keywords.md §2.15): slave nodes (FE nodes or SPG particles) against master segments (shell
/// elements or the free faces of solid elements), compiled by solver/compile_contact.cpp and
/// run by interface_pass (contact.hpp) once per cycle after the internal forces.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::solver::contact {

using Index = std::int32_t;
using Vec3 = Eigen::Vector3d;

/// Segments of a contact surface: 4 nodes (a triangle repeats its third), normal by the right-hand
/// rule over the node order (outward for the free faces of solids).
struct Surface {
  std::vector<std::array<Index, 4>> segments;
  std::vector<double> stiffness;  ///< SOFT 0 penalty per segment, scale factors included
  /// Half the contact thickness: two-sided shells (automatic contact) are touched on either side
  /// at this distance from the mid-surface; 0 for one-sided segments.
  std::vector<double> half_thickness;
  std::vector<std::uint8_t> two_sided;
  std::vector<double> smallest_node_mass;  ///< for SOFT 1; +inf on rigid bodies
  std::vector<double> area;                ///< initial, for VC
};

/// One direction of a contact: nodes of one side checked against the segments of the other.
/// A surface-to-surface contact has two (A nodes on B segments, B nodes on A segments).
struct Pass {
  std::vector<Index> nodes;       ///< slave nodes, ascending
  std::vector<double> stiffness;  ///< SOFT 0 penalty per slave node, scale factors included
  /// Half the contact thickness of each slave node (automatic contacts: half the thickest shell
  /// on it, or SST), added to the segment's: a shell node touches at the two half thicknesses.
  std::vector<double> node_half_thickness;
  bool nodes_on_side_a = true;  ///< for the resultants: which side the nodes belong to
  Surface surface;
  // Search (contact_search.cpp): candidate segments per node (CSR over `nodes`), and the nodes
  // that have any (indices into `nodes`, ascending): only they are checked each cycle.
  std::vector<Index> candidate_offsets, candidates;
  std::vector<Index> near;
  // Friction state per node: the tangential force carried over from the last cycle.
  Eigen::Matrix3Xd friction;
  // Per node, the direction the node was pushed last cycle (zero when not in contact): a node on
  // a two-sided segment stays on the side it came from however deep it goes (as LS-DYNA's
  // automatic contacts track it), instead of being pushed through once past the mid-surface.
  Eigen::Matrix3Xd side;
  // Per node, the depth it started inside the surface and was left at (IGNORE 1/2, and SPG
  // particles or rigid nodes under IGNORE 0): contact pushes only beyond it, and it shrinks as
  // the node moves out (resolve_initial_penetrations).
  std::vector<double> initial_penetration;
};

/// A force of the last pass. `Interface::applied`: the forces this process added to the nodes
/// it owns, kept to charge their work over the following step. `Interface::computed`: the whole
/// hits this process computed (its slave nodes'), for the force transducers: the forces of one
/// hit (the slave node's, slot 0, then its segment nodes', slot 1 + the corner) share `hit`, the
/// slave node's index in its pass plus the node counts of the passes before.
struct AppliedForce {
  Index node = 0;
  Index hit = 0;
  Index slot = 0;
  Vec3 force = Vec3::Zero();
};

/// *CONTACT_FORCE_TRANSDUCER_PENALTY: the nodes whose contact forces it sums (ascending).
struct Transducer {
  bool active = false;  ///< this interface is a transducer
  std::vector<Index> nodes_a;
  std::vector<Index> nodes_b;  ///< empty: every other contact's force on side A counts
};

/// The penalty stiffness of a node on a segment (PENOPT 1, 2, 3).
enum class PenaltyScale { smaller, segment, node };
/// Slave nodes that start inside a master surface (IGNORE): moved onto it (0), or their depth
/// kept as an offset that contact pushes only beyond (1, 2).
enum class InitialPenetration { move, keep_offset };

struct Interface {
  model::Id id = 0;
  std::string heading;
  std::vector<Pass> passes;
  double static_friction = 0.0, dynamic_friction = 0.0, decay = 0.0;  ///< FS, FD, DC (x FSF)
  double viscous_friction = 0.0;  ///< VC (x VSF): limit of the friction stress
  double damping = 0.0;           ///< VDC / 100: share of critical damping on the normal force
  double birth = 0.0, death = 1.0e20;
  bool switched_off = false;  ///< by *SENSOR_CONTROL (sensors/)
  /// Between its birth and death and not switched off.
  [[nodiscard]] bool acting(double t) const { return !switched_off && t >= birth && t <= death; }
  /// SOFT 1: the stiffness is at least that of a spring whose period matches the initial step
  /// for the smaller mass.
  bool soft_constraint = false;
  double soft_scale = 0.1;  ///< SOFSCL
  PenaltyScale penalty_scale = PenaltyScale::smaller;
  int sort_interval = 10;     ///< cycles between bucket sorts (NSBCS; sooner if nodes moved far)
  double initial_step = 0.0;  ///< the first solution step, for SOFT 1 (0 until known)
  /// SOFT 2 (segment-based penalty): k = scale m1 m2 / (m1 + m2) / dt^2 with the current step,
  /// m1 the node's mass and m2 the segment's (the mean of its nodes'); `segment_based_scale`
  /// per pass is 0.5 SLSFAC times the segment side's SFS or SFM.
  bool segment_based = false;
  std::array<double, 2> segment_based_scale{};
  InitialPenetration initial_penetration = InitialPenetration::move;
  /// A force transducer has no passes and this active: transducer_pass fills its resultants.
  Transducer sensor;

  // Search state.
  long last_sort = -1;
  Eigen::Matrix3Xd sorted_positions;  ///< of all nodes at the last sort (slave and master)
  std::vector<Index> tracked;         ///< nodes whose motion triggers an early sort
  double capture = 0.0;               ///< search margin; a node moving half of it re-sorts

  // Results of the last pass (rcforc) and the work done so far (glstat sliding energy).
  Vec3 force_a = Vec3::Zero(), force_b = Vec3::Zero();    ///< on side A / side B nodes
  Vec3 moment_a = Vec3::Zero(), moment_b = Vec3::Zero();  ///< about the origin
  double mass_in_contact = 0.0;                           ///< of the A nodes in contact
  double energy = 0.0;                 ///< work the contact forces took from the structure
  std::vector<AppliedForce> applied;   ///< on the nodes this process owns
  std::vector<AppliedForce> computed;  ///< the hits of the slave nodes this process owns
};

}  // namespace mcdyna::solver::contact
