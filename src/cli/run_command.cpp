#include "cli/run_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <csignal>
#include <optional>
#include <ostream>
#include <sstream>

#include "cli/launcher.hpp"
#include "cli/load.hpp"
#include "cli/processes.hpp"
#include "cli/restart_dump.hpp"
#include "cli/run_session.hpp"
#include "core/communicator.hpp"
#include "deck/deck.hpp"
#include "solver/run/compile.hpp"
#include "solver/run/run_overrides.hpp"

namespace mcdyna::cli {

namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int sig) {
  g_stop_signal = sig;
}

// SIGINT / SIGTERM handlers for the whole of a run, set-up included, restored on return: a
// signal during reading or compiling stops the run before any output exists, one during the
// time loop stops it at the next cycle with a final state and whole files.
class StopSignalGuard {
 public:
  StopSignalGuard() {
    g_stop_signal = 0;
    old_int_ = std::signal(SIGINT, on_stop_signal);
    old_term_ = std::signal(SIGTERM, on_stop_signal);
  }
  ~StopSignalGuard() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
  }
  StopSignalGuard(const StopSignalGuard&) = delete;
  StopSignalGuard& operator=(const StopSignalGuard&) = delete;

 private:
  void (*old_int_)(int) = SIG_DFL;
  void (*old_term_)(int) = SIG_DFL;
};

// Whether a stop signal came during set-up; if so says so on ERR.
bool stopped_in_setup(const RunOptions& options, std::ostream& err) {
  if (g_stop_signal == 0) return false;
  fmt::print(err,
             "mcdyna: interrupted by signal {} during set-up: {} not run, no outputs written\n",
             static_cast<int>(g_stop_signal), options.deck.string());
  return true;
}

}  // namespace

std::string run_fingerprint(const core::SourceFiles& files, const RunOptions& options,
                            int processes) {
  // The options that change the physics go into the dump's fingerprint with the deck's text,
  // and over several processes their number: a process's dump holds its share of the work.
  std::string physics =
      fmt::format("stabilization={};renewal={};msc={};step={}", options.spg_stabilization,
                  options.spg_renewal_strain, options.spg_mode_control, options.spg_step);
  if (processes > 1) physics += fmt::format(";processes={}", processes);
  if (options.case_id > 0) physics += fmt::format(";case={}", options.case_id);
  return deck_fingerprint(files, physics);
}

namespace {

// The directory of a case's outputs: its JOBID, unless that is not a plain file name.
std::string case_directory(const deck::Case& c) {
  const bool plain = !c.job.empty() && c.job != "." && c.job != ".." &&
                     c.job.find_first_of("/\\") == std::string::npos;
  return plain ? c.job : "case" + std::to_string(c.id);
}

// One process's run of the deck (all of it, or its share over several processes).
int run_processes(const RunOptions& options, const core::Communicator& comm, std::ostream& out,
                  std::ostream& err);

}  // namespace

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err) {
  const LaunchedProcesses launched = launched_processes();
  // Started by mpirun over several processes in a build without MPI: each would run the whole
  // deck into the same files. Refused, once.
  if (launched.size > 1 && !core::Communicator::built_with_mpi()) {
    if (launched.rank == 0)
      fmt::print(err,
                 "mcdyna: error: started as {} processes (mpirun -np {}), but this build has no "
                 "MPI (CMake MCDYNA_MPI=OFF, or no MPI found when it was built). Run it without "
                 "mpirun (--threads N uses the cores of one machine), or build with Open MPI "
                 "(Debian: openmpi-bin libopenmpi-dev).\n",
                 launched.size, launched.size);
    return kRunUsage;
  }
  const core::Session mpi(launched.size > 1);
  const core::Communicator comm = core::Communicator::world();
  auto run_one = [&](const RunOptions& one) {
    if (comm.rank() == 0) return run_processes(one, comm, out, err);
    // The other processes compute their share and write only their restart dumps; what they
    // would print, process 0 prints.
    std::ostringstream quiet_out, quiet_err;
    return run_processes(one, comm, quiet_out, quiet_err);
  };
  const std::vector<deck::Case> cases =
      options.case_id == 0 ? deck_cases(options.deck) : std::vector<deck::Case>{};
  if (cases.empty()) return run_one(options);
  // A deck with *CASE and no --case: every case in turn, each into its own directory (LS-DYNA
  // prefixes each case's files with its JOBID). The first failure's exit code is returned; an
  // interrupt stops the rest.
  if (!options.restart.empty()) {
    if (comm.rank() == 0)
      fmt::print(err,
                 "mcdyna: error: --restart: {} defines {} cases (*CASE); name the one the dump "
                 "was written by with --case ID\n",
                 options.deck.string(), cases.size());
    return kRunUsage;
  }
  const std::filesystem::path base = options.out_dir.empty() ? "." : options.out_dir;
  int result = kRunOk;
  for (const deck::Case& c : cases) {
    RunOptions one = options;
    one.case_id = c.id;
    one.out_dir = base / case_directory(c);
    if (comm.rank() == 0)
      fmt::print(out, "mcdyna: case {} ({}), outputs in {}\n", c.id, c.job, one.out_dir.string());
    const int code = run_one(one);
    if (result == kRunOk) result = code;
    if (code == kRunInterrupted) break;
  }
  return result;
}

namespace {

// The run's options that change the SPG parts' settings, as the solver takes them.
solver::SpgOverrides spg_overrides(const RunOptions& o) {
  using solver::spg::Stabilization;
  solver::SpgOverrides s;
  if (!o.spg_stabilization.empty())
    s.stabilization = o.spg_stabilization == "none"     ? Stabilization::none
                      : o.spg_stabilization == "direct" ? Stabilization::direct
                      : o.spg_stabilization == "spg"    ? Stabilization::strain_gradient
                                                        : Stabilization::momentum_consistent;
  if (o.spg_renewal_strain >= 0.0) s.renewal_strain = o.spg_renewal_strain;
  if (o.spg_mode_control >= 0.0) s.mode_control = o.spg_mode_control;
  if (!o.spg_step.empty())
    s.step_estimate = o.spg_step == "eigen" ? solver::spg::StepEstimate::eigenvalue
                                            : solver::spg::StepEstimate::nearest_neighbour;
  return s;
}

// Reads, checks and compiles the deck and applies the run's SPG options. Returns an exit code
// when the deck cannot run (said on `err`).
std::optional<int> compile_for_run(const RunOptions& options, const core::Communicator& comm,
                                   std::ostream& err, CompiledDeck& c) {
  std::ostringstream report;
  c.deck = load_deck(options.deck, report, options.case_id);
  c.migration_report = report.str();
  if (comm.size() == 1 && stopped_in_setup(options, err)) return kRunInterrupted;
  const LoadedDeck& d = c.deck;
  core::print_diagnostics(err, d.diags, d.deck.files, options.max_messages);
  const bool blocked = d.unsupported_physics > 0 && !options.allow_unsupported;
  if (blocked)
    fmt::print(err,
               "mcdyna: error: {} unsupported keyword(s) change the physics (see `mcdyna "
               "check`); --allow-unsupported runs without them\n",
               d.unsupported_physics);
  if (d.diags.has_errors() || blocked) {
    fmt::print(err, "mcdyna: {} not run: {} error(s)\n", options.deck.string(),
               d.diags.error_count() + (blocked ? 1 : 0));
    return kRunDeckErrors;
  }
  c.state = solver::compile(d.built.model, c.compile_diags);
  core::print_diagnostics(err, c.compile_diags, d.deck.files, options.max_messages);
  if (!c.state) {
    fmt::print(err, "mcdyna: {} not run: {} error(s)\n", options.deck.string(),
               c.compile_diags.error_count());
    return kRunDeckErrors;
  }
  if (comm.size() == 1 && stopped_in_setup(options, err)) return kRunInterrupted;
  solver::apply_spg_overrides(*c.state, spg_overrides(options));
  if (const std::string problem =
          process_problem(*c.state, comm, options.spg_angular_budget, !options.step_log.empty());
      !problem.empty()) {
    fmt::print(err, "mcdyna: error: {}\nmcdyna: {} not run\n", problem, options.deck.string());
    return kRunUsage;
  }
  return std::nullopt;
}

int run_processes(const RunOptions& options, const core::Communicator& comm, std::ostream& out,
                  std::ostream& err) {
  if (const std::string problem = deck::file_problem(options.deck); !problem.empty()) {
    fmt::print(err, "mcdyna: error: deck {}: {}\n", options.deck.string(), problem);
    return kRunUsage;
  }
  const StopSignalGuard signals;
  CompiledDeck compiled;
  if (const auto code = compile_for_run(options, comm, err, compiled)) return *code;
  RunSession session(options, comm, out, err, g_stop_signal);
  if (const auto code = session.open(compiled)) return *code;
  const solver::RunResult result =
      solver::run(*compiled.state, session.hooks(), session.resume_point());
  return session.finish(result);
}

}  // namespace

}  // namespace mcdyna::cli
