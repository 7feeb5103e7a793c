#pragma once
/// `mcdyna run DECK`: read and check the deck, compile the solver state, run the explicit time
/// loop and write d3plot.pvd (+ states), the ASCII/CSV histories and d3hsp.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "core/source.hpp"

namespace mcdyna::cli {

struct RunOptions {
  std::filesystem::path deck;
  std::filesystem::path out_dir;  ///< empty: the working directory, as LS-DYNA
  bool allow_unsupported = false;
  int threads = 0;  ///< 0: OpenMP default
  bool quiet = false;
  std::size_t max_messages = 50;
  /// --spg-stabilization: "none", "direct" or "mc"; empty: as the deck says (MC-SPG)
  std::string spg_stabilization;
  /// --spg-renewal-strain: Green strain that renews an updated-Lagrangian kernel (0: at every
  /// SMSTEP check); negative: the default of the solver
  double spg_renewal_strain = -1.0;
  double spg_mode_control = -1.0;  ///< < 0: from the deck (MSC)
  /// --spg-step: "nn" (nearest-neighbour length) or "eigen" (stiffness length scaled to the
  /// largest eigenvalue by power iteration); empty: spg::default_step_estimate
  std::string spg_step;
  /// --spg-angular-budget: record each SPG part's angular-momentum budget every cycle and report
  /// it at the end (spg/angular_budget.hpp; costs about one gather per particle and cycle)
  bool spg_angular_budget = false;
  /// --fixed-step: every cycle takes this step, no mass scaling, no restart dumps (a probe for
  /// the true critical step; not part of the dump fingerprint so it can start from any dump)
  double fixed_step = 0.0;
  long cycles = 0;                 ///< --cycles: stop after this many cycles of this run
  double end_time = 0.0;           ///< --end-time: stop at this time instead of ENDTIM
  std::filesystem::path step_log;  ///< --step-log: per-cycle CSV of what sets the step
  /// --restart / r=: continue the run from this dump (written by the same deck and options)
  std::filesystem::path restart;
  /// --case: run this *CASE of the deck; 0: a deck with *CASE runs each case in turn, each into
  /// OUT/JOBID (as `lsdyna case` runs them)
  long case_id = 0;
};

/// Exit codes of `run` (README and manual list them).
enum RunExit : int {
  kRunOk = 0,
  kRunDeckErrors = 1,
  kRunUsage = 2,         ///< a missing deck, an --out that cannot be a directory
  kRunUnstable = 4,      ///< stopped by NaN, negative volume or step collapse
  kRunInterrupted = 5,   ///< SIGINT / SIGTERM: final state written, files closed (none in set-up)
  kRunOutputFailed = 6,  ///< a write failed (disk full ...): stopped, the files on disk whole
};

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err);

/// The fingerprint a run's restart dumps carry: the deck's files and the options that change
/// the physics (cli/restart_dump.hpp deck_fingerprint).
std::string run_fingerprint(const core::SourceFiles& files, const RunOptions& options,
                            int processes = 1);

}  // namespace mcdyna::cli
