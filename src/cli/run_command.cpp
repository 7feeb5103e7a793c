#include "cli/run_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <system_error>

#include "cli/launcher.hpp"
#include "cli/load.hpp"
#include "cli/processes.hpp"
#include "cli/progress.hpp"
#include "cli/report.hpp"
#include "cli/restart_dump.hpp"
#include "cli/run_timing.hpp"
#include "cli/sense_switch.hpp"
#include "cli/spg_summary.hpp"
#include "cli/step_log.hpp"
#include "cli/wait_policy.hpp"
#include "core/communicator.hpp"
#include "deck/deck.hpp"
#include "io/checked_file.hpp"
#include "io/inertia.hpp"
#include "io/output_lock.hpp"
#include "io/outputs.hpp"
#include "solver/compile.hpp"
#include "solver/driver.hpp"
#include "solver/energy.hpp"
#include "solver/spg/angular_budget.hpp"
#include "solver/spg/spg_solver.hpp"

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

const char* reason_text(solver::StopReason r) {
  switch (r) {
    case solver::StopReason::end_time:
      return "normal termination (ENDTIM reached)";
    case solver::StopReason::end_cycle:
      return "normal termination (ENDCYC reached)";
    case solver::StopReason::interrupted:
      return "interrupted by signal";
    case solver::StopReason::inverted_element:
      return "error termination: negative volume";
    case solver::StopReason::non_finite:
      return "error termination: unstable motion (non-finite or runaway values)";
    case solver::StopReason::step_collapse:
      return "error termination: time step collapse";
  }
  return "";
}

// *CONTROL_ACCURACY OSU of a block or SPG part.
const char* stress_update_name(bool objective) {
  return objective ? "second-order objective stress update (OSU 1)"
                   : "first-order stress update (OSU 0)";
}

void print_state_summary(std::ostream& log, const solver::State& s) {
  double mass = 0.0;
  for (const double m : s.nodes.mass)
    mass += m;
  const double added = solver::total_added_mass(s);
  for (const auto& b : s.rigid_bodies)
    mass += b.mass;
  fmt::print(log,
             "\nSolver state\n  nodes {}, deformable solids {} in {} blocks, rigid bodies {}\n",
             s.nodes.count(), s.solids.count(), s.solids.blocks.size(), s.rigid_bodies.size());
  for (const auto& b : s.solids.blocks) {
    const auto& part = s.parts[static_cast<std::size_t>(b.part)];
    fmt::print(log, "  part {:>8}: {} elements, ELFORM {}, {} hourglass QM {}, Q1 {} Q2 {}, {}\n",
               part.id, b.end - b.begin, b.points_per_element == 1 ? 1 : 2,
               b.hourglass.stiffness() ? "stiffness" : "viscous", b.hourglass.coefficient,
               b.bulk_viscosity.quadratic, b.bulk_viscosity.linear,
               stress_update_name(b.objective));
  }
  for (const auto& b : s.rigid_bodies) {
    fmt::print(log, "  rigid part {:>8}: mass {:.6e}, centre ({:.6g}, {:.6g}, {:.6g}), {} nodes\n",
               b.part_id, b.mass, b.center[0], b.center[1], b.center[2], b.nodes.size());
  }
  fmt::print(log, "  total mass {:.6e}; constrained nodes {}; rigid walls {}\n", mass,
             s.constraints.nodes.size(), s.rigid_walls.size());
  if (s.mass_scaling_dt > 0.0) {
    fmt::print(log, "  mass scaling: target step {:.4e}, added mass so far {:.6e} ({:.3f} %)\n",
               s.mass_scaling_dt, added, mass > 0.0 ? 100.0 * added / mass : 0.0);
  }
  static const char* kModes[] = {"none (plain nodal integration)", "direct smoothing (Eq. 7)",
                                 "MC-SPG (Eqs. 13-31)",
                                 "original SPG, strain-gradient stabilisation (ITB 1, Eqs. 8-12)"};
  static const char* kShapes[] = {"cubic spline, box", "quadratic spline, box",
                                  "cubic spline, sphere"};
  for (const solver::spg::Domain& d : s.spg) {
    const auto& st = d.settings;
    long shared = 0, surface = 0;
    for (std::size_t i = 0; i < d.particles.nodes.size(); ++i) {
      shared += d.particles.shared[i];
      surface += d.particles.surface[i];
    }
    fmt::print(
        log,
        "  SPG part {:>8}: {} particles ({} shared with FE/constraints, {} on the surface); "
        "{}{}; kernel {}, {}, checked every {} steps{}; bond failure {}; {}\n",
        s.parts[static_cast<std::size_t>(d.part)].id, d.count(), shared, surface,
        kModes[static_cast<int>(st.stabilization)],
        st.mode_control > 0.0
            ? fmt::format(" with low-energy-mode control {:g} (MSC 1)", st.mode_control)
            : std::string(),
        kShapes[static_cast<int>(st.shape)],
        st.kernel_update == solver::spg::KernelUpdate::eulerian ? "Eulerian" : "updated Lagrangian",
        st.renewal_interval,
        st.kernel_update == solver::spg::KernelUpdate::eulerian || !(st.renewal_strain > 0.0)
            ? std::string(" and renewed at each check")
            : fmt::format(" and renewed per particle at Green strain {:g} ({:g} under "
                          "compression) or broken bonds",
                          st.renewal_strain,
                          solver::spg::kCompressionRenewalShare * st.renewal_strain),
        st.bond_failure
            ? fmt::format("FS {:g} and STRETCH {:g}", st.failure_strain, st.failure_stretch)
            : std::string("off"),
        stress_update_name(st.objective));
  }
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

// --out DIR: created if missing; a path that is not (and cannot become) a directory one can
// write in is a usage error. Returns the problem, or "".
std::string prepare_output_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    return fmt::format("cannot create the output directory {}: {}", dir.string(), ec.message());
  if (!std::filesystem::is_directory(dir, ec))
    return fmt::format("the output directory {} is not a directory", dir.string());
  return {};
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

int run_processes(const RunOptions& options, const core::Communicator& comm, std::ostream& out,
                  std::ostream& err) {
  const bool writer = comm.rank() == 0;
  if (const std::string problem = deck::file_problem(options.deck); !problem.empty()) {
    fmt::print(err, "mcdyna: error: deck {}: {}\n", options.deck.string(), problem);
    return kRunUsage;
  }
  const StopSignalGuard signals;
  std::ostringstream report;
  LoadedDeck d = load_deck(options.deck, report, options.case_id);
  if (comm.size() == 1 && stopped_in_setup(options, err)) return kRunInterrupted;
  core::print_diagnostics(err, d.diags, d.deck.files, options.max_messages);
  const bool blocked = d.unsupported_physics > 0 && !options.allow_unsupported;
  if (blocked) {
    fmt::print(err,
               "mcdyna: error: {} unsupported keyword(s) change the physics (see `mcdyna "
               "check`); --allow-unsupported runs without them\n",
               d.unsupported_physics);
  }
  if (d.diags.has_errors() || blocked) {
    fmt::print(err, "mcdyna: {} not run: {} error(s)\n", options.deck.string(),
               d.diags.error_count() + (blocked ? 1 : 0));
    return kRunDeckErrors;
  }
  core::Diagnostics compile_diags;
  std::unique_ptr<solver::State> state = solver::compile(d.built.model, compile_diags);
  core::print_diagnostics(err, compile_diags, d.deck.files, options.max_messages);
  if (!state) {
    fmt::print(err, "mcdyna: {} not run: {} error(s)\n", options.deck.string(),
               compile_diags.error_count());
    return kRunDeckErrors;
  }
  if (comm.size() == 1 && stopped_in_setup(options, err)) return kRunInterrupted;
  if (!options.spg_stabilization.empty()) {
    const solver::spg::Stabilization mode =
        options.spg_stabilization == "none"     ? solver::spg::Stabilization::none
        : options.spg_stabilization == "direct" ? solver::spg::Stabilization::direct
        : options.spg_stabilization == "spg"    ? solver::spg::Stabilization::strain_gradient
                                                : solver::spg::Stabilization::momentum_consistent;
    for (solver::spg::Domain& dom : state->spg) {
      dom.settings.stabilization = mode;
      dom.settings.step_estimate = solver::spg::default_step_estimate(mode);
    }
  }
  if (options.spg_renewal_strain >= 0.0)
    for (solver::spg::Domain& dom : state->spg)
      dom.settings.renewal_strain = options.spg_renewal_strain;
  if (options.spg_mode_control >= 0.0)
    for (solver::spg::Domain& dom : state->spg)
      dom.settings.mode_control = options.spg_mode_control;
  if (!options.spg_step.empty())
    for (solver::spg::Domain& dom : state->spg)
      dom.settings.step_estimate = options.spg_step == "eigen"
                                       ? solver::spg::StepEstimate::eigenvalue
                                       : solver::spg::StepEstimate::nearest_neighbour;
  if (const std::string problem =
          process_problem(*state, comm, options.spg_angular_budget, !options.step_log.empty());
      !problem.empty()) {
    fmt::print(err, "mcdyna: error: {}\nmcdyna: {} not run\n", problem, options.deck.string());
    return kRunUsage;
  }
  // Process 0 writes every output; the others only their restart dumps into the same directory.
  const std::filesystem::path dir = options.out_dir.empty() ? "." : options.out_dir;
  std::optional<io::OutputLock> lock;
  if (writer) {
    if (const std::string problem = prepare_output_directory(dir); !problem.empty()) {
      fmt::print(err, "mcdyna: error: --out: {}\nmcdyna: {} not run\n", problem,
                 options.deck.string());
      return stop_all(comm, kRunUsage, err);
    }
    lock.emplace(dir);
    if (!lock->problem().empty()) {
      fmt::print(err, "mcdyna: error: --out: {}\nmcdyna: {} not run\n", lock->problem(),
                 options.deck.string());
      return stop_all(comm, kRunUsage, err);
    }
  }
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const std::string fingerprint = run_fingerprint(d.deck.files, options, comm.size());
  std::optional<LoadedDump> dump;
  if (!options.restart.empty()) {
    const std::filesystem::path path = process_file(options.restart, comm);
    try {
      dump = read_dump(path, fingerprint, *state);
    } catch (const std::exception& e) {
      // Each process reads its own file: the one that fails says so, and stops them all.
      fmt::print(writer ? err : std::cerr, "mcdyna: error: {}\nmcdyna: {} not run\n", e.what(),
                 options.deck.string());
      return stop_all(comm, kRunDeckErrors, writer ? err : std::cerr);
    }
  }

  if (options.fixed_step > 0.0) {
    state->time_control.fixed_step = options.fixed_step;
    state->mass_scaling_dt = 0.0;
  }
  if (options.cycles > 0) state->time_control.end_cycle = state->cycle + options.cycles;
  if (options.end_time > 0.0) state->time_control.end_time = options.end_time;
  std::optional<StepLog> step_log;
  if (!options.step_log.empty() && writer) {
    try {
      step_log.emplace(options.step_log);
    } catch (const std::exception& e) {
      fmt::print(err, "mcdyna: error: --step-log: {}\nmcdyna: {} not run\n", e.what(),
                 options.deck.string());
      return stop_all(comm, kRunUsage, err);
    }
  }

  // A restarted run continues d3hsp after what the earlier runs wrote. The other processes
  // keep a closed stream: what they would log, process 0 logs.
  std::ofstream log;
  if (writer) {
    log.open(dir / "d3hsp", dump ? std::ios::app : std::ios::trunc);
    if (!log) {
      fmt::print(err, "mcdyna: error: --out: cannot write {} ({})\nmcdyna: {} not run\n",
                 (dir / "d3hsp").string(), std::generic_category().message(errno),
                 options.deck.string());
      return stop_all(comm, kRunUsage, err);
    }
  }
  if (dump) {
    fmt::print(log, "\nRestart from {} at t = {:.6e}, cycle {} (threads: {}{})\n",
               options.restart.string(), state->time, state->cycle, omp_get_max_threads(),
               processes_text(comm));
  } else {
    fmt::print(log,
               "mcdyna 0.1 - explicit dynamics of LS-DYNA keyword decks\ndeck: {}\nthreads: {}{}, "
               "OpenMP wait policy {}\n\n",
               options.deck.string(), omp_get_max_threads(), processes_text(comm),
               wait_policy_description());
    print_summary(log, d.deck, d.built.model, count_model(d.built.model));
    log << report.str();
    for (const auto& diag : compile_diags.all())
      log << core::format_diagnostic(diag, d.deck.files);
    print_state_summary(log, *state);
  }

  std::vector<std::string> notes;
  std::unique_ptr<io::Outputs> outputs;
  try {
    if (writer)
      outputs = std::make_unique<io::Outputs>(d.built.model, *state, dir, notes,
                                              dump ? &dump->outputs : nullptr);
  } catch (const io::WriteError& e) {
    fmt::print(err, "mcdyna: error termination: {}\nmcdyna: {} not run\n", e.what(),
               options.deck.string());
    return stop_all(comm, kRunOutputFailed, err);
  } catch (const std::exception& e) {
    fmt::print(err, "mcdyna: error: {}\nmcdyna: {} not run\n", e.what(), options.deck.string());
    return stop_all(comm, kRunDeckErrors, err);
  }
  if (!dump) {
    for (const auto& n : notes)
      fmt::print(log, "note: {}\n", n);
    fmt::print(log, "\nTime-step history (every 5 % of ENDTIM)\n");
  }
  DumpSchedule dumps(d.built.model.outputs, dir);
  log.flush();  // the model summary is there to read while the run goes on

  const double end_time = state->time_control.end_time;
  // Open MPI gives every process a pseudo-terminal, whatever mpirun's own output goes to: over
  // several processes the progress takes the log's form, a line every 5 %.
  const bool terminal = isatty(STDOUT_FILENO) != 0 && launched_processes().size == 1;
  Progress progress(out, log, terminal, options.quiet,
                    end_time > 0.0 ? std::min(1.0, state->time / end_time) : 0.0);
  const auto start = std::chrono::steady_clock::now();
  long zone_cycles = 0;
  const long start_cycle = state->cycle;  // a restart times only its own cycles
  // The first write that failed (disk full, ...): the run stops at the next cycle, writes
  // nothing more (no restart dump either: its history sizes would include the failed block) and
  // exits with kRunOutputFailed; every file on disk stays whole.
  std::string output_failure;
  auto checked = [&output_failure](auto&& write) {
    if (!output_failure.empty()) return;
    try {
      write();
    } catch (const io::WriteError& e) {
      output_failure = e.what();
    }
  };
  solver::RunHooks hooks;
  io::InertiaRecord inertia;  // process 0: the deformable parts at every output
  if (writer) {
    hooks.output_due = [&](const solver::State& s) { return outputs->due(s); };
    hooks.state_due = [&](const solver::State& s) { return outputs->state_due(s); };
    hooks.write = [&](const solver::State& s, const Eigen::Matrix3Xd& previous, bool final) {
      checked([&] {
        zone_cycles = (s.cycle - start_cycle) * static_cast<long>(s.solids.count());
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        outputs->write(s, previous, final, zone_cycles > 0 ? 1e9 * elapsed / zone_cycles : 0.0);
      });
      inertia.add(s, previous);
    };
    hooks.progress = [&](const solver::State& s) {
      progress.update(s);
      if (step_log) checked([&] { step_log->add(s); });
      if (!log && output_failure.empty())
        output_failure = fmt::format("cannot write {}", (dir / "d3hsp").string());
    };
    hooks.decomposed = [&](const std::string& summary) {
      log << '\n' << summary;
      log.flush();
    };
  }
  std::vector<solver::spg::AngularBudget> budgets;
  if (options.spg_angular_budget) {
    budgets.resize(state->spg.size());
    hooks.velocities_advanced = [&](const solver::State& s, const solver::StepTimes& t) {
      for (std::size_t k = 0; k < budgets.size(); ++k)
        budgets[k].record(s, s.spg[k], t.step, t.mean);
    };
  }
  hooks.stop_requested = [&] { return g_stop_signal != 0 || !output_failure.empty(); };
  SenseSwitchFile switches(dir, comm.rank() == 0, out);
  hooks.sense_switches = [&] { return switches.poll(); };
  hooks.status = [&](const solver::State& s) {
    if (writer) progress.status(s);
  };
  hooks.request_state = [&] {
    if (writer && !outputs->request_state())
      fmt::print(out, "sw4: the deck asks for no d3plot states (*DATABASE_BINARY_D3PLOT)\n");
  };
  hooks.dump_due = [&](const solver::State& s, bool interrupted, bool requested) {
    // A fixed-step probe leaves no dump: continuing it would not repeat the deck's run.
    return output_failure.empty() && options.fixed_step <= 0.0 &&
           dumps.due(s.cycle, interrupted, requested);
  };
  std::filesystem::path last_dump;
  hooks.dump = [&](const solver::State& s, const solver::ResumePoint& point) {
    const io::OutputsResume where = writer ? outputs->resume_point() : io::OutputsResume{};
    for (const std::filesystem::path& dump_path : dumps.take()) {
      const std::filesystem::path path = process_file(dump_path, comm);
      try {
        const auto begin = std::chrono::steady_clock::now();
        write_dump(path, fingerprint, s, point, where);
        fmt::print(log, "restart dump {} written at t = {:.6e}, cycle {} ({:.1f} MB in {:.3f} s)\n",
                   path.string(), s.time, s.cycle,
                   1e-6 * static_cast<double>(std::filesystem::file_size(path)),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
        log.flush();
        last_dump = dump_path;  // what --restart takes: each process adds its number
      } catch (const std::exception& e) {
        if (output_failure.empty()) output_failure = e.what();
      }
    }
  };
  const solver::RunResult result = solver::run(*state, hooks, dump ? &dump->point : nullptr);
  progress.finish();
  if (step_log) checked([&] { step_log->flush(); });

  std::ostringstream summary;
  const bool switched_off =
      result.reason == solver::StopReason::interrupted && switches.stop_requested();
  fmt::print(summary, "\n{} at t = {:.6e}, cycle {}\n",
             !output_failure.empty() ? "error termination: an output could not be written"
             : switched_off          ? "stopped by sense switch sw1 (d3kil)"
                                     : reason_text(result.reason),
             state->time, state->cycle);
  if (!output_failure.empty()) fmt::print(summary, "  {}\n", output_failure);
  if (!result.message.empty()) fmt::print(summary, "  {}\n", result.message);
  print_timing(summary, result, *state, comm, dump.has_value());
  print_spg_summary(summary, *state);
  inertia.print(summary, *state);
  print_angular_budgets(summary, *state, budgets);
  if (result.reason == solver::StopReason::interrupted && !last_dump.empty())
    fmt::print(summary,
               "  continue with: mcdyna run {} --out {} --restart {} (and the same options)\n",
               options.deck.string(), dir.string(), last_dump.string());
  if (state->mass_scaling_dt > 0.0) {
    fmt::print(summary, "  added mass (DT2MS) {:.6e}\n", solver::total_added_mass(*state));
  }
  fmt::print(summary, "Outputs in {}:", dir.string());
  if (writer)
    for (const auto& f : outputs->files())
      fmt::print(summary, " {};", f);
  fmt::print(summary, " d3hsp\n");
  log << summary.str();
  log.flush();
  if (writer && !log && output_failure.empty())
    output_failure = fmt::format("cannot write {}", (dir / "d3hsp").string());
  if (!options.quiet || result.reason != solver::StopReason::end_time || !output_failure.empty())
    out << summary.str();
  else
    err << inertia.warning(*state);  // quiet: the summary stays in d3hsp, the warning does not
  if (!output_failure.empty()) {
    fmt::print(err, "mcdyna: error termination: {}\n", output_failure);
    return kRunOutputFailed;
  }
  switch (result.reason) {
    case solver::StopReason::end_time:
    case solver::StopReason::end_cycle:
      return kRunOk;
    case solver::StopReason::interrupted:
      return kRunInterrupted;
    default:
      fmt::print(err, "mcdyna: {}: {}\n", reason_text(result.reason), result.message);
      return kRunUnstable;
  }
}

}  // namespace

}  // namespace mcdyna::cli
