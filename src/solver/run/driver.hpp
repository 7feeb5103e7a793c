#pragma once
/// The explicit time loop (central difference, LS-DYNA step semantics) and the hooks through
/// which io/ and the command line watch it. The solver never writes files itself.
#include <Eigen/Core>

#include <array>
#include <functional>
#include <string>

#include "solver/nodal_forces.hpp"
#include "solver/state.hpp"
#include "solver/step_times.hpp"

namespace mcdyna::solver {

/// Why the run ended.
enum class StopReason {
  end_time,
  end_cycle,
  interrupted,
  inverted_element,
  non_finite,
  step_collapse
};

struct RunResult {
  StopReason reason = StopReason::end_time;
  std::string message;  ///< diagnostic for the abnormal stops (names element/node, part, time)
  PhaseTimes phases;
  double wall_seconds = 0.0;
  /// Wall time x OpenMP threads, summed over the parts of a restarted run (which may have run on
  /// different thread counts); wall x threads for a run in one piece.
  double core_seconds = 0.0;
  long element_cycles = 0;   ///< deformable element updates performed
  long particle_cycles = 0;  ///< SPG particle updates performed
};

/// The time loop's own values at the top of a cycle, beside the State: what a restart dump needs
/// to continue the loop exactly where it was (the forces at t^n are already computed).
struct ResumePoint {
  NodalForces forces;          ///< at t^n, as the last force pass left them
  double critical_step = 0.0;  ///< of the last force pass, before TSSFAC
  Index controlling_element = -1;
  std::size_t controlling_domain = 0;
  Index controlling_particle = -1;
  double first_step = 0.0;  ///< the run's first step (DTMIN is relative to it)
  PhaseTimes phases;        ///< accumulated so far, as the loop keeps them (SPG not split out)
  double wall_seconds = 0.0;
  double core_seconds = 0.0;  ///< wall x threads, summed over the run's parts
  long element_cycles = 0, particle_cycles = 0;
};

/// LS-DYNA's sense switches: what a user asks of a running job by a file d3kil in its directory
/// (cli/sense_switch.hpp reads it). Over several processes one process reads the file and every
/// process acts on the same cycle.
struct SenseSwitches {
  bool stop = false;    ///< sw1: a restart dump, then stop
  bool status = false;  ///< sw2: print where the run stands and its time estimate
  bool dump = false;    ///< sw3: a restart dump, and go on
  bool state = false;   ///< sw4: a d3plot state, and go on
  [[nodiscard]] bool any() const { return stop || status || dump || state; }
};

struct RunHooks {
  /// Asked at t^n before the velocities advance: is an output state due now?
  std::function<bool(const State&)> output_due;
  /// Asked with output_due: is a d3plot state among it? Over several processes only the fields
  /// the due outputs read are gathered to process 0 (the element fields for a state).
  std::function<bool(const State&)> state_due;
  /// Writes the state at t^n. The state holds v^{n+1/2}; `previous` holds v^{n-1/2} (energies
  /// use both, see solver/energy.hpp). `final` is set for the last state of the run (normal end,
  /// interruption or error stop).
  std::function<void(const State&, const Eigen::Matrix3Xd& previous, bool final)> write;
  /// Called every cycle once the velocities have advanced to n+1/2 (constraints applied), before
  /// the positions move: the state holds x^n and v^{n+1/2}, the forces are f^n
  /// (spg/angular_budget.hpp).
  std::function<void(const State&, const NodalForces&, const StepTimes&)> velocities_advanced;
  /// Over several processes, once at the start: the decomposition summary (process 0).
  std::function<void(const std::string&)> decomposed;
  /// Polled every cycle (signals).
  std::function<bool()> stop_requested;
  /// Polled every cycle: the sense switches the user set since the last poll.
  std::function<SenseSwitches()> sense_switches;
  /// sw2, on every process at the same cycle: where the run stands.
  std::function<void(const State&)> status;
  /// sw4, on every process at the same cycle before the outputs are asked what is due: the next
  /// output is to write a d3plot state whatever its schedule says.
  std::function<void()> request_state;
  /// Called every cycle after the step (progress display decides how often to print).
  std::function<void(const State&)> progress;
  /// Asked at the top of every cycle but the first of this run (and when a stop signal or a
  /// sense switch came): is a restart dump due now? `interrupted`: the run stops here (a signal,
  /// sw1); `requested`: the user asked for one (sw1, sw3). `dump` then writes the state and the
  /// loop's resume point.
  std::function<bool(const State&, bool interrupted, bool requested)> dump_due;
  std::function<void(const State&, const ResumePoint&)> dump;
};

/// Runs the state from its current time to ENDTIM / ENDCYC or until something stops it.
/// `resume`: continue a run read from a restart dump (its forces are in the resume point).
RunResult run(State& state, const RunHooks& hooks, const ResumePoint* resume = nullptr);

}  // namespace mcdyna::solver
