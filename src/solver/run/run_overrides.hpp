#pragma once
/// What a run changes of the compiled deck (`mcdyna run`'s options; cli/ parses them, the
/// solver applies them): the SPG parts' settings, and the run's limits.
#include <optional>

#include "solver/spg/domain.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// In place of the SPG sections' own settings, for every SPG part.
struct SpgOverrides {
  /// --spg-stabilization; sets the part's step estimate to the stabilization's default too.
  std::optional<spg::Stabilization> stabilization;
  std::optional<double> renewal_strain;            ///< --spg-renewal-strain
  std::optional<double> mode_control;              ///< --spg-mode-control (MSC)
  std::optional<spg::StepEstimate> step_estimate;  ///< --spg-step
};

/// Applied after compile(), before a restart dump is read over the state (the dump's
/// fingerprint holds the options, cli/restart_dump.hpp).
void apply_spg_overrides(State& s, const SpgOverrides& overrides);

/// The run's limits, from where it starts (t = 0 or a restart dump's cycle).
struct RunLimits {
  /// --fixed-step: every cycle takes this step whatever the estimate, and no mass is added.
  double fixed_step = 0.0;
  long cycles = 0;        ///< --cycles: this many cycles more (0: no limit of its own)
  double end_time = 0.0;  ///< --end-time: in place of ENDTIM (0: the deck's)
};

/// Applied once the state is where the run starts (after a restart dump is read).
void apply_run_limits(State& s, const RunLimits& limits);

}  // namespace mcdyna::solver
