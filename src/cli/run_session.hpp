#pragma once
/// One process's run of a compiled deck, as `mcdyna run` drives it: the output directory and
/// its lock, the restart dump it continues from, d3hsp, the outputs and the restart dumps, the
/// progress and the sense switches, given to the solver as its hooks (solver/run/driver.hpp); then
/// the end-of-run summary and the exit code. run_command.cpp reads and compiles the deck and
/// hands the state here.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/load.hpp"
#include "cli/progress.hpp"
#include "cli/restart_dump.hpp"
#include "cli/run_command.hpp"
#include "cli/sense_switch.hpp"
#include "cli/step_log.hpp"
#include "core/communicator.hpp"
#include "io/inertia.hpp"
#include "io/output_lock.hpp"
#include "io/outputs.hpp"
#include "solver/run/driver.hpp"
#include "solver/spg/angular_budget.hpp"

namespace mcdyna::cli {

/// The deck as read and compiled for a run.
struct CompiledDeck {
  LoadedDeck deck;
  std::string migration_report;
  core::Diagnostics compile_diags;
  std::unique_ptr<solver::State> state;
};

class RunSession {
 public:
  /// `stop_signal`: set by SIGINT / SIGTERM (the session stops the loop at the next cycle).
  RunSession(const RunOptions& options, const core::Communicator& comm, std::ostream& out,
             std::ostream& err, const volatile std::sig_atomic_t& stop_signal);
  /// Everything before the first cycle: the directory, the dump, the limits, d3hsp and the
  /// outputs. Returns an exit code when the run cannot start (said on `err`).
  std::optional<int> open(CompiledDeck& compiled);
  /// The solver's hooks, bound to this session (which must outlive the run).
  solver::RunHooks hooks();
  /// Where a restart continues from, or nullptr.
  [[nodiscard]] const solver::ResumePoint* resume_point() const {
    return dump_ ? &dump_->point : nullptr;
  }
  /// The end of the run: the summary (d3hsp, and the terminal unless quiet) and the exit code.
  int finish(const solver::RunResult& result);

 private:
  std::optional<int> fail(int code, const std::string& message);
  std::optional<int> open_directory();
  std::optional<int> read_restart();
  std::optional<int> open_log(const CompiledDeck& compiled);
  std::optional<int> open_outputs(const CompiledDeck& compiled);
  void add_output_hooks(solver::RunHooks& hooks);
  void add_control_hooks(solver::RunHooks& hooks);
  void write_dumps(const solver::State& s, const solver::ResumePoint& point);
  std::string summary(const solver::RunResult& result) const;
  /// Runs `write` unless an output failed before; remembers the first failure.
  template <class Write>
  void checked(Write&& write);

  const RunOptions& options_;
  const core::Communicator& comm_;
  std::ostream& out_;
  std::ostream& err_;
  const volatile std::sig_atomic_t& stop_signal_;
  const bool writer_;  ///< process 0: every output; the others only their restart dumps
  const std::filesystem::path dir_;
  solver::State* state_ = nullptr;
  std::optional<io::OutputLock> lock_;
  std::string fingerprint_;
  std::optional<LoadedDump> dump_;
  std::optional<StepLog> step_log_;
  std::ofstream log_;
  std::unique_ptr<io::Outputs> outputs_;
  std::optional<DumpSchedule> dumps_;
  std::optional<Progress> progress_;
  std::optional<SenseSwitchFile> switches_;
  io::InertiaRecord inertia_;  ///< process 0: the deformable parts at every output
  std::vector<solver::spg::AngularBudget> budgets_;
  std::chrono::steady_clock::time_point start_;
  long start_cycle_ = 0;  ///< a restart times only its own cycles
  /// The first write that failed (disk full, ...): the run stops at the next cycle, writes
  /// nothing more (no restart dump either: its history sizes would include the failed block)
  /// and exits with kRunOutputFailed; every file on disk stays whole.
  std::string output_failure_;
  std::filesystem::path last_dump_;
};

}  // namespace mcdyna::cli
