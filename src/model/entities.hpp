#pragma once
/// Plain-data entities of the model database, one struct per deck concept, keyed by user IDs.
/// Units are the deck's own consistent set. Every entity keeps the deck location it came from so
/// cross-checks can point at it.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/source.hpp"

namespace mcdyna::model {

using Id = std::int64_t;  ///< user ID as written in the deck (I10 allows 10 digits)
using Vec3 = std::array<double, 3>;

struct Node {
  Id id = 0;
  Vec3 position{};                          ///< length
  std::uint8_t translation_constraint = 0;  ///< TC code 0..7 (0 free, 7 x+y+z)
  std::uint8_t rotation_constraint = 0;     ///< RC code 0..7
  core::SourceLoc loc;
};

/// 8-node solid; tetrahedra and pentahedra are degenerate hexes with repeated nodes.
struct SolidElement {
  Id id = 0;
  Id part = 0;
  std::array<Id, 8> nodes{};
  core::SourceLoc loc;
};

/// 3- or 4-node shell (triangle: n4 == n3).
struct ShellElement {
  Id id = 0;
  Id part = 0;
  std::array<Id, 4> nodes{};
  std::array<double, 4> thickness{};  ///< _THICKNESS option, else 0 (section thickness applies)
  core::SourceLoc loc;
};

/// 2-node beam. Its local s axis lies in the plane of N1, N2 and the orientation node N3 (or the
/// _ORIENTATION vector from N1); t = r x s.
struct BeamElement {
  Id id = 0;
  Id part = 0;
  std::array<Id, 2> nodes{};
  Id orientation_node = 0;  ///< N3, 0 none
  Vec3 orientation{};       ///< _ORIENTATION VX VY VZ, all 0 when not given
  /// _THICKNESS PARM1..5: TS1 TS2 TT1 TT2 (ELFORM 1) or A ISS ITT J SA (ELFORM 2); 0 takes the
  /// section's value.
  std::array<double, 5> parameters{};
  core::SourceLoc loc;
};

/// *ELEMENT_DISCRETE: a spring or damper between two nodes, acting along N1 -> N2.
struct DiscreteElement {
  Id id = 0;
  Id part = 0;
  std::array<Id, 2> nodes{};
  double scale = 1.0;   ///< S, on the force
  double offset = 0.0;  ///< OFFSET, added to the change of length (length)
  core::SourceLoc loc;
};

/// *PART_INERTIA: a rigid part's mass properties and initial velocity, given.
struct PartInertia {
  Vec3 centre{};                        ///< XC YC ZC
  Id node = 0;                          ///< NODEID: the centre is this node (0: `centre`)
  double mass = 0.0;                    ///< TM
  std::array<double, 6> tensor{};       ///< IXX IXY IXZ IYY IYZ IZZ, global axes
  Vec3 velocity{}, angular_velocity{};  ///< VTX..VTZ, VRX..VRZ
  core::SourceLoc loc;
};

struct Part {
  Id id = 0;
  std::string heading;
  Id section = 0;
  Id material = 0;
  Id eos = 0;        ///< 0: none
  Id hourglass = 0;  ///< 0: *CONTROL_HOURGLASS defaults
  Id thermal_material = 0;
  std::optional<PartInertia> inertia;  ///< *PART_INERTIA
  core::SourceLoc loc;
  core::SourceLoc section_loc, material_loc, eos_loc, hourglass_loc;
};

enum class SectionKind { solid, solid_spg, shell, beam, discrete };

/// *SECTION_SOLID_SPG cards 2 and 3 (keywords.md §2.6).
struct SpgSettings {
  Vec3 support_scale{1.6, 1.6, 1.6};  ///< DX, DY, DZ: support size / nodal spacing (>= 1)
  int kernel_function = 0;            ///< ISPLINE: 0 cubic box, 1 quadratic box, 2 cubic sphere
  int kernel_update = 0;          ///< KERNEL: 0 updated Lagrangian, 1 Eulerian, 2 pseudo-Lagrangian
  int smoothing_interval = 15;    ///< SMSTEP: steps between kernel/smoothing updates
  double smoothing_scheme = 0.0;  ///< MSC (R13+) / SWTIME (R10)
  int damage_criterion = 1;       ///< IDAM
  double failure_strain = 1.0e11;          ///< FS (huge: no failure)
  double failure_stretch = 1.0e10;         ///< STRETCH: critical bond stretch ratio
  int stabilization = 3;                   ///< ITB: 3 = MC-SPG
  double surface_quadrature_factor = 1.0;  ///< MSFAC
  int self_contact = 0;                    ///< ISC
  Id box = 0;                              ///< BOXID
  double particle_damping = -0.001;        ///< PDAMP
};

struct ShellSettings {
  double shear_factor = 1.0;          ///< SHRF
  int integration_points = 2;         ///< NIP
  double quadrature = 0.0;            ///< QR/IRID: 0 Gauss, 1 trapezoidal, < 0 user rule
  int composite = 0;                  ///< ICOMP
  std::array<double, 4> thickness{};  ///< T1..T4, length
  double reference_surface = 0.0;     ///< NLOC: 0 mid, 1 top, -1 bottom
  double nonstructural_mass = 0.0;    ///< MAREA, mass per area
  core::SourceLoc formulation_loc, points_loc, quadrature_loc, composite_loc, thickness_loc,
      reference_loc;
};

/// *SECTION_BEAM: the integrated cross section (ELFORM 1: TS/TT, CST) or the resultant one
/// (ELFORM 2: A, ISS, ITT, J, SA).
struct BeamSettings {
  double shear_factor = 1.0;          ///< SHRF
  double quadrature = 2.0;            ///< QR/IRID
  int cross_section = 0;              ///< CST: 0 rectangular, 1 tubular, 2 user rule
  double nonstructural_mass = 0.0;    ///< NSM, mass per length
  std::array<double, 4> thickness{};  ///< TS1 TS2 TT1 TT2 (tube: outer, outer, inner, inner)
  double reference_s = 0.0, reference_t = 0.0;                               ///< NSLOC, NTLOC
  double area = 0.0, iss = 0.0, itt = 0.0, torsion = 0.0, shear_area = 0.0;  ///< A ISS ITT J SA
  double product_of_inertia = 0.0;                                           ///< IST
  core::SourceLoc formulation_loc, quadrature_loc, cross_section_loc, dimensions_loc;
};

struct Section {
  Id id = 0;
  std::string title;
  SectionKind kind = SectionKind::solid;
  int element_formulation = 1;  ///< ELFORM (47 = SPG)
  /// What `mcdyna check` shows after its ID ("shell ELFORM 16", "SPG ITB 3 KERNEL 1"): set by
  /// the keyword's builder, so a new section kind adds no case to the report.
  std::string summary;
  SpgSettings spg;
  ShellSettings shell;
  BeamSettings beam;
  core::SourceLoc loc;
};

struct ElasticMaterial {
  double youngs_modulus = 0.0;  ///< stress
  double poisson_ratio = 0.0;
};

struct PlasticKinematicMaterial {
  double youngs_modulus = 0.0, poisson_ratio = 0.0;
  double yield_stress = 0.0, tangent_modulus = 0.0;       ///< stress
  double hardening_mix = 0.0;                             ///< BETA: 0 kinematic, 1 isotropic
  double cowper_symonds_c = 0.0, cowper_symonds_p = 0.0;  ///< SRC (1/time), SRP
  double failure_strain = 0.0;                            ///< FS: 0 none
  double viscoplastic = 0.0;                              ///< VP
};

struct PiecewiseLinearPlasticityMaterial {
  double youngs_modulus = 0.0, poisson_ratio = 0.0;
  double yield_stress = 0.0, tangent_modulus = 0.0;
  double failure_strain = 1.0e21;     ///< FAIL
  double min_time_step_delete = 0.0;  ///< TDEL
  double cowper_symonds_c = 0.0, cowper_symonds_p = 0.0;
  Id stress_strain_curve = 0;  ///< LCSS
  Id strain_rate_curve = 0;    ///< LCSR
  double viscoplastic = 0.0;
  std::vector<std::pair<double, double>> points;  ///< EPS1..8 / ES1..8 pairs given
};

struct JohnsonCookMaterial {
  double shear_modulus = 0.0, youngs_modulus = 0.0, poisson_ratio = 0.0;
  double min_shell_time_step = 0.0;
  double viscoplastic = 0.0;
  int rate_option = 0;
  double a = 0.0, b = 0.0, n = 0.0, c = 0.0, m = 0.0;     ///< A, B (stress), N, C, M
  double melt_temperature = 0.0, room_temperature = 0.0;  ///< TM, TR
  double reference_strain_rate = 1.0;                     ///< EPSO, 1/time
  double specific_heat = 0.0;                             ///< CP
  double pressure_cutoff = 0.0;                           ///< PC (<= 0)
  double spall_type = 2.0;
  int iterate_plasticity = 0;      ///< IT
  std::array<double, 5> damage{};  ///< D1..D5
  double c2 = 0.0;
  double erode_flag = 0.0;             ///< EROD: 0 erosion allowed
  double min_failure_strain = 1.0e-6;  ///< EFMIN
  int damage_model = 0;                ///< DMODEL
};

struct RigidMaterial {
  double youngs_modulus = 0.0, poisson_ratio = 0.0;  ///< for contact stiffness
  int constraint_option = 0;                         ///< CMO
  int translation_constraint = 0;                    ///< CON1
  int rotation_constraint = 0;                       ///< CON2
  Id constraint_node = 0;                            ///< SPCNID
  Vec3 constraint_point{};
  int local_output = 0;  ///< BNDLCO
};

/// *MAT_NULL: no deviatoric strength; the EOS gives the pressure.
struct NullMaterial {
  double pressure_cutoff = 0.0;                      ///< PC (<= 0; 0: none)
  double youngs_modulus = 0.0, poisson_ratio = 0.0;  ///< YM, PR (null shells and beams)
};

/// *MAT_SPOTWELD (MAT_100) on spot-weld beams (ELFORM 9): elastic-plastic with isotropic
/// hardening and the weld's failure criteria.
struct SpotweldMaterial {
  double youngs_modulus = 0.0, poisson_ratio = 0.0;
  double yield_stress = 0.0, hardening_modulus = 0.0;  ///< SIGY, EH (plastic modulus)
  double mass_scaling_step = 0.0;                      ///< DT
  double failure_time = 0.0;                           ///< TFAIL (0: none)
  double failure_strain = 0.0;                         ///< EFAIL (0: none)
  /// NRR NRS NRT MRR MSS MTT: the resultants at failure (0: that term is not considered).
  std::array<double, 6> failure_resultants{};
  double filter_vectors = 0.0;  ///< NF
};

enum class MaterialKind {
  elastic,
  plastic_kinematic,
  johnson_cook,
  rigid,
  piecewise_linear,
  null_material,
  spotweld,
  spring_elastic,            ///< *MAT_SPRING_ELASTIC (discrete elements)
  damper_viscous,            ///< *MAT_DAMPER_VISCOUS
  spring_nonlinear_elastic,  ///< *MAT_SPRING_NONLINEAR_ELASTIC
};

/// The discrete elements' materials: one of a stiffness, a damping constant or a force curve.
struct DiscreteMaterial {
  double stiffness = 0.0;  ///< K, force per length
  double damping = 0.0;    ///< DC, force per velocity
  Id force_curve = 0;      ///< LCD: force against change of length
  Id rate_curve = 0;       ///< LCR: scale on the force against rate of change of length (0: none)
  core::SourceLoc force_curve_loc, rate_curve_loc;
};

struct Material {
  Id id = 0;
  std::string title;
  MaterialKind kind = MaterialKind::elastic;
  /// The keyword's canonical name after "MAT_" ("PIECEWISE_LINEAR_PLASTICITY" for *MAT_024 too),
  /// as the reports name the material.
  std::string keyword;
  double density = 0.0;
  ElasticMaterial elastic;
  PlasticKinematicMaterial plastic_kinematic;
  JohnsonCookMaterial johnson_cook;
  RigidMaterial rigid;
  PiecewiseLinearPlasticityMaterial piecewise_linear;
  NullMaterial null_material;
  SpotweldMaterial spotweld;
  DiscreteMaterial discrete;
  core::SourceLoc loc;
};

/// *MAT_ADD_EROSION criteria for one material (0 = criterion not used).
struct Erosion {
  Id material = 0;
  double exclusion = 0.0;
  double max_pressure = 0.0, min_principal_strain = 0.0, effective_plastic_strain = 0.0;
  double volumetric_strain = 0.0;
  double failed_points = 1.0, conditions_to_fail = 1.0;  ///< NUMFIP, NCS
  double min_pressure = 0.0, max_principal_stress = 0.0, equivalent_stress = 0.0;
  double max_principal_strain = 0.0, shear_strain = 0.0, failure_time = 0.0;
  core::SourceLoc loc;
};

enum class EosKind { linear_polynomial, gruneisen };

struct Eos {
  Id id = 0;
  std::string title;
  EosKind kind = EosKind::linear_polynomial;
  std::array<double, 7> c{};                                   ///< linear polynomial C0..C6
  double sound_speed = 0.0;                                    ///< Grüneisen C
  std::array<double, 3> s{};                                   ///< S1..S3
  double gamma0 = 0.0, volume_correction = 0.0;                ///< GAMMA0, A
  double initial_energy = 0.0, initial_relative_volume = 1.0;  ///< E0, V0
  core::SourceLoc loc;
};

struct Hourglass {
  Id id = 0;
  std::string title;
  int type = 1;                                                         ///< IHQ
  double coefficient = 0.1;                                             ///< QM
  double quadratic_bulk_viscosity = 1.5, linear_bulk_viscosity = 0.06;  ///< Q1, Q2
  double qb = 0.1, qw = 0.1;
  core::SourceLoc loc;
};

struct Curve {
  Id id = 0;
  std::string title;
  int dynamic_relaxation = 0;                           ///< SIDR
  double abscissa_scale = 1.0, ordinate_scale = 1.0;    ///< SFA, SFO
  double abscissa_offset = 0.0, ordinate_offset = 0.0;  ///< OFFA, OFFO
  std::vector<std::pair<double, double>> points;        ///< as written (scales not applied)
  core::SourceLoc loc;
};

struct Vector {
  Id id = 0;
  Vec3 tail{}, head{};
  Id coordinate_system = 0;
  core::SourceLoc loc;
};

struct Box {
  Id id = 0;
  Vec3 min{}, max{};
  core::SourceLoc loc;
};

/// One rule of *SET_NODE_GENERAL: OPTION and its IDs (zeros dropped).
struct SetRule {
  std::string option;
  std::vector<Id> ids;
  core::SourceLoc loc;
};

struct NodeSet {
  Id id = 0;
  std::vector<Id> nodes;
  /// *SET_NODE_GENERAL: the rules `nodes` was built from once the deck was read (in order).
  std::vector<SetRule> rules;
  bool collect = false;  ///< a _COLLECT set: later _COLLECT sets of its ID add to it
  core::SourceLoc loc;
};

enum class ElementSetKind { shell, solid, beam };

/// *SET_SHELL_LIST / *SET_SOLID / *SET_BEAM and their _GENERATE(_INCREMENT), _COLUMN and
/// _GENERAL forms.
struct ElementSet {
  Id id = 0;
  ElementSetKind kind = ElementSetKind::shell;
  std::vector<Id> elements;
  /// _GENERAL: the rules `elements` is built from once the deck is read (in order).
  std::vector<SetRule> rules;
  bool collect = false;  ///< a _COLLECT set: later _COLLECT sets of its ID and kind add to it
  core::SourceLoc loc;
};

struct PartSet {
  Id id = 0;
  std::vector<Id> parts;
  bool collect = false;  ///< a _COLLECT set: later _COLLECT sets of its ID add to it
  core::SourceLoc loc;
};

struct SegmentSet {
  Id id = 0;
  std::vector<std::array<Id, 4>> segments;
  core::SourceLoc loc;
};

}  // namespace mcdyna::model
