#pragma once
#include <array>
/// *CONTROL_* settings and *DATABASE_* output requests.
#include <optional>
#include <string>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::model {

struct Termination {
  double end_time = 0.0;         ///< ENDTIM
  int end_cycle = 0;             ///< ENDCYC (0 none)
  double min_step_factor = 0.0;  ///< DTMIN (factor on initial dt)
  double energy_change_percent = 0.0, mass_change_percent = 1.0e8;
  int no_solution = 0;
  core::SourceLoc loc;
};

struct TimeStepControl {
  double initial_step = 0.0;       ///< DTINIT (0 automatic)
  double scale_factor = 0.9;       ///< TSSFAC
  int shell_length_option = 0;     ///< ISDO
  double shell_min_step = 0.0;     ///< TSLIMT
  double mass_scaling_step = 0.0;  ///< DT2MS (negative: scale only elements below)
  Id max_step_curve = 0;           ///< LCTM
  int erode = 0;
  int mass_scaling_first_step = 0;  ///< MS1ST
  core::SourceLoc loc;
};

struct HourglassControl {
  int type = 1;              ///< IHQ
  double coefficient = 0.1;  ///< QH
  core::SourceLoc loc;
};

struct ContactControl {
  double penalty_scale = 0.1;       ///< SLSFAC
  double rigid_wall_penalty = 0.0;  ///< RWPNAL
  int initial_penetration_check = 1;
  int shell_thickness = 0;
  int penalty_option = 1;  ///< PENOPT
  int thickness_change = 0;
  int orientation = 1;
  int eroding_mass = 0;
  int bucket_interval = 0;              ///< NSBCS
  double max_penetration_factor = 4.0;  ///< XPENE
  /// SSTHK: 0, single-surface contacts touch shells at min(t, 0.4 shortest edge); 1, at t.
  int single_surface_thickness = 0;
  double default_static_friction = 0.0, default_dynamic_friction = 0.0;
  int ignore_penetration = 0;  ///< card 4 IGNORE
  int friction_energy = 0;     ///< FRCENG
  core::SourceLoc loc;
};

/// *DAMPING_GLOBAL: force -D m v on every deformable node and rigid body (D from a curve or
/// VALDMP), scaled per translation and rotation.
struct GlobalDamping {
  Id curve = 0;
  double value = 0.0;
  std::array<double, 6> scale{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  core::SourceLoc loc, curve_loc;
};

struct SolidControl {
  int sort_degenerate = 0;  ///< ESORT
  int fmatrix = 0;
  int tet_integration_points = 4;
  core::SourceLoc loc;
};

/// *CONTROL_SHELL: the fields that act (the rest are noted by the compile).
struct ShellControl {
  int sort_triangles = 0;         ///< ESORT
  int thickness_update = 0;       ///< ISTUPD
  int theory = 2;                 ///< THEORY
  int warping = 2;                ///< BWC
  int plasticity_iterations = 1;  ///< MITER
  double rotary_scale = 1.0;      ///< ROTASCL
  int lobatto = 0;                ///< INTGRD
  Id thickness_parts = 0;         ///< PSSTUPD
  int contact_offset = 0;         ///< CNTCO
  /// Fields set to what does nothing here: "NAME = value" each, for the notes.
  std::vector<std::string> inactive;
  core::SourceLoc loc;
};

struct EnergyControl {
  int hourglass = 1;  ///< HGEN: 2 = compute hourglass energy
  int rigid_wall = 2;
  int sliding = 1;  ///< SLNTEN: 2 = include sliding energy
  int rayleigh = 1;
  int initial_reference_geometry = 2;
  int material_split = 1;
  core::SourceLoc loc;
};

struct BulkViscosityControl {
  double quadratic = 1.5;  ///< Q1
  double linear = 0.06;    ///< Q2
  int type = 1;
  int beam_type = 0;
  int time_step_type = 0;
  core::SourceLoc loc;
};

/// *CONTROL_ACCURACY.
struct AccuracyControl {
  int objective = 0;               ///< OSU: 1 second-order objective stress update
  int invariant = 1;               ///< INN: invariant node numbering (1 off)
  Id objective_parts = 0;          ///< PIDOSU: part set taking the objective update (OSU ignored)
  int implicit = 0;                ///< IACC
  double explicit_accuracy = 0.0;  ///< EXACC
  core::SourceLoc loc;
};

struct Controls {
  std::optional<Termination> termination;
  std::optional<TimeStepControl> time_step;
  std::optional<HourglassControl> hourglass;
  std::optional<ContactControl> contact;
  std::optional<GlobalDamping> damping;
  std::optional<SolidControl> solid;
  std::optional<ShellControl> shell;
  std::optional<EnergyControl> energy;
  std::optional<BulkViscosityControl> bulk_viscosity;
  std::optional<AccuracyControl> accuracy;
};

/// ASCII history databases mcdyna writes.
enum class AsciiDatabase { glstat, matsum, rcforc, nodout, spcforc, bndout, rwforc };
inline constexpr int kAsciiDatabaseCount = 7;
const char* ascii_database_name(AsciiDatabase d);

struct AsciiRequest {
  AsciiDatabase database = AsciiDatabase::glstat;
  double interval = 0.0;  ///< DT (time)
  int binary = 0;         ///< BINARY: 1 ASCII, 2 binout, 3 both
  Id interval_curve = 0;  ///< LCUR
  int ioopt = 1;
  core::SourceLoc loc;
};

struct D3plotRequest {
  double interval = 0.0;  ///< DT
  Id interval_curve = 0;  ///< LCDT
  int beam = 0;
  int plots = 0;          ///< NPLTC: DT = ENDTIM / NPLTC
  Id excluded_parts = 0;  ///< PSETID
  core::SourceLoc loc;
};

struct HistoryNodes {
  bool is_set = false;
  std::vector<Id> ids;                ///< node IDs or node set IDs
  std::vector<std::string> headings;  ///< _ID variant, parallel to ids
  core::SourceLoc loc;
};

struct ExtentBinary {
  int shell_history_variables = 0, solid_history_variables = 0;  ///< NEIPH, NEIPS
  int max_integration_points = 3;
  int strain_flag = 0, stress_flag = 1, plastic_strain_flag = 1, resultant_flag = 1;
  int energy_flag = 1;
  core::SourceLoc loc;
};

/// *DATABASE_BINARY_D3DUMP / *DATABASE_BINARY_RUNRSF: restart dumps every `cycles` cycles, a
/// numbered family (D3DUMP) or `files` running files written in turn (RUNRSF).
struct RestartDumpRequest {
  long cycles = 0;  ///< CYCL
  int files = 1;    ///< NR (RUNRSF)
  core::SourceLoc loc;
};

struct OutputRequests {
  std::vector<AsciiRequest> ascii;
  std::optional<RestartDumpRequest> d3dump, runrsf;
  std::optional<D3plotRequest> d3plot;
  std::vector<HistoryNodes> history_nodes;
  std::optional<ExtentBinary> extent;
};

}  // namespace mcdyna::model
