#include "cli/run_session.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <omp.h>
#include <unistd.h>

#include <cerrno>
#include <iostream>
#include <system_error>

#include "cli/launcher.hpp"
#include "cli/processes.hpp"
#include "cli/report.hpp"
#include "cli/run_timing.hpp"
#include "cli/spg_summary.hpp"
#include "cli/state_summary.hpp"
#include "cli/wait_policy.hpp"
#include "io/checked_file.hpp"
#include "solver/block.hpp"
#include "solver/energy.hpp"
#include "solver/run/run_overrides.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::cli {

namespace {

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

}  // namespace

RunSession::RunSession(const RunOptions& options, const core::Communicator& comm, std::ostream& out,
                       std::ostream& err, const volatile std::sig_atomic_t& stop_signal)
    : options_(options),
      comm_(comm),
      out_(out),
      err_(err),
      stop_signal_(stop_signal),
      writer_(comm.rank() == 0),
      dir_(options.out_dir.empty() ? "." : options.out_dir) {}

std::optional<int> RunSession::fail(int code, const std::string& message) {
  std::ostream& to = writer_ ? err_ : std::cerr;
  fmt::print(to, "mcdyna: {}\nmcdyna: {} not run\n", message, options_.deck.string());
  return stop_all(comm_, code, to);
}

std::optional<int> RunSession::open(CompiledDeck& compiled) {
  state_ = compiled.state.get();
  if (auto code = open_directory()) return code;
  if (options_.threads > 0) omp_set_num_threads(options_.threads);
  fingerprint_ = run_fingerprint(compiled.deck.deck.files, options_, comm_.size());
  if (auto code = read_restart()) return code;
  solver::apply_run_limits(*state_, {options_.fixed_step, options_.cycles, options_.end_time});
  if (!options_.step_log.empty() && writer_) {
    try {
      step_log_.emplace(options_.step_log);
    } catch (const std::exception& e) {
      return fail(kRunUsage, fmt::format("error: --step-log: {}", e.what()));
    }
  }
  if (auto code = open_log(compiled)) return code;
  if (auto code = open_outputs(compiled)) return code;
  const double end_time = state_->time_control.end_time;
  // Open MPI gives every process a pseudo-terminal, whatever mpirun's own output goes to: over
  // several processes the progress takes the log's form, a line every 5 %.
  const bool terminal = isatty(STDOUT_FILENO) != 0 && launched_processes().size == 1;
  progress_.emplace(out_, log_, terminal, options_.quiet,
                    end_time > 0.0 ? std::min(1.0, state_->time / end_time) : 0.0);
  switches_.emplace(dir_, writer_, out_);
  if (options_.spg_angular_budget) budgets_.resize(solver::spg::domains_of(*state_).size());
  start_ = std::chrono::steady_clock::now();
  start_cycle_ = state_->cycle;
  return std::nullopt;
}

// Process 0 writes every output; the others only their restart dumps into the same directory.
std::optional<int> RunSession::open_directory() {
  if (!writer_) return std::nullopt;
  if (const std::string problem = prepare_output_directory(dir_); !problem.empty())
    return fail(kRunUsage, "error: --out: " + problem);
  lock_.emplace(dir_);
  if (!lock_->problem().empty()) return fail(kRunUsage, "error: --out: " + lock_->problem());
  return std::nullopt;
}

// Each process reads its own dump: the one that fails says so, and stops them all.
std::optional<int> RunSession::read_restart() {
  if (options_.restart.empty()) return std::nullopt;
  try {
    dump_ = read_dump(process_file(options_.restart, comm_), fingerprint_, *state_);
  } catch (const std::exception& e) {
    return fail(kRunDeckErrors, fmt::format("error: {}", e.what()));
  }
  return std::nullopt;
}

// A restarted run continues d3hsp after what the earlier runs wrote. The other processes keep a
// closed stream: what they would log, process 0 logs.
std::optional<int> RunSession::open_log(const CompiledDeck& compiled) {
  if (!writer_) return std::nullopt;
  log_.open(dir_ / "d3hsp", dump_ ? std::ios::app : std::ios::trunc);
  if (!log_)
    return fail(kRunUsage,
                fmt::format("error: --out: cannot write {} ({})", (dir_ / "d3hsp").string(),
                            std::generic_category().message(errno)));
  if (dump_) {
    fmt::print(log_, "\nRestart from {} at t = {:.6e}, cycle {} (threads: {}{})\n",
               options_.restart.string(), state_->time, state_->cycle, omp_get_max_threads(),
               processes_text(comm_));
    return std::nullopt;
  }
  const LoadedDeck& d = compiled.deck;
  fmt::print(log_,
             "mcdyna 0.1 - explicit dynamics of LS-DYNA keyword decks\ndeck: {}\nthreads: {}{}, "
             "OpenMP wait policy {}\n\n",
             options_.deck.string(), omp_get_max_threads(), processes_text(comm_),
             wait_policy_description());
  print_summary(log_, d.deck, d.built.model, count_model(d.built.model));
  log_ << compiled.migration_report;
  for (const auto& diag : compiled.compile_diags.all())
    log_ << core::format_diagnostic(diag, d.deck.files);
  print_state_summary(log_, *state_);
  return std::nullopt;
}

std::optional<int> RunSession::open_outputs(const CompiledDeck& compiled) {
  const model::ModelDatabase& model = compiled.deck.built.model;
  std::vector<std::string> notes;
  try {
    if (writer_)
      outputs_ = std::make_unique<io::Outputs>(model, *state_, dir_, notes,
                                               dump_ ? &dump_->outputs : nullptr);
  } catch (const io::WriteError& e) {
    return fail(kRunOutputFailed, fmt::format("error termination: {}", e.what()));
  } catch (const std::exception& e) {
    return fail(kRunDeckErrors, fmt::format("error: {}", e.what()));
  }
  if (!dump_) {
    for (const auto& n : notes)
      fmt::print(log_, "note: {}\n", n);
    fmt::print(log_, "\nTime-step history (every 5 % of ENDTIM)\n");
  }
  dumps_.emplace(model.outputs, dir_);
  log_.flush();  // the model summary is there to read while the run goes on
  return std::nullopt;
}

template <class Write>
void RunSession::checked(Write&& write) {
  if (!output_failure_.empty()) return;
  try {
    write();
  } catch (const io::WriteError& e) {
    output_failure_ = e.what();
  }
}

solver::RunHooks RunSession::hooks() {
  solver::RunHooks hooks;
  if (writer_) add_output_hooks(hooks);
  add_control_hooks(hooks);
  return hooks;
}

// Process 0: the outputs, the progress, the step log and the decomposition's summary.
void RunSession::add_output_hooks(solver::RunHooks& hooks) {
  hooks.output_due = [this](const solver::State& s) { return outputs_->due(s); };
  hooks.state_due = [this](const solver::State& s) { return outputs_->state_due(s); };
  hooks.write = [this](const solver::State& s, const Eigen::Matrix3Xd& previous, bool final) {
    checked([&] {
      const long zone_cycles =
          (s.cycle - start_cycle_) * static_cast<long>(solver::solids_of(s).count());
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      outputs_->write(s, previous, final, zone_cycles > 0 ? 1e9 * elapsed / zone_cycles : 0.0);
    });
    inertia_.add(s, previous);
  };
  hooks.progress = [this](const solver::State& s) {
    progress_->update(s);
    if (step_log_) checked([&] { step_log_->add(s); });
    if (!log_ && output_failure_.empty())
      output_failure_ = fmt::format("cannot write {}", (dir_ / "d3hsp").string());
  };
  hooks.decomposed = [this](const std::string& summary) {
    log_ << '\n' << summary;
    log_.flush();
  };
}

// Every process: the stops (a signal, a failed write, the sense switches) and the dumps.
void RunSession::add_control_hooks(solver::RunHooks& hooks) {
  if (!budgets_.empty())
    hooks.velocities_advanced = [this](const solver::State& s, const solver::NodalForces& f,
                                       const solver::StepTimes& t) {
      for (std::size_t k = 0; k < budgets_.size(); ++k)
        budgets_[k].record(s, solver::spg::domain_of(s, k), f.force, t.step, t.mean);
    };
  hooks.stop_requested = [this] { return stop_signal_ != 0 || !output_failure_.empty(); };
  hooks.sense_switches = [this] { return switches_->poll(); };
  hooks.status = [this](const solver::State& s) {
    if (writer_) progress_->status(s);
  };
  hooks.request_state = [this] {
    if (writer_ && !outputs_->request_state())
      fmt::print(out_, "sw4: the deck asks for no d3plot states (*DATABASE_BINARY_D3PLOT)\n");
  };
  hooks.dump_due = [this](const solver::State& s, bool interrupted, bool requested) {
    // A fixed-step probe leaves no dump: continuing it would not repeat the deck's run.
    return output_failure_.empty() && options_.fixed_step <= 0.0 &&
           dumps_->due(s.cycle, interrupted, requested);
  };
  hooks.dump = [this](const solver::State& s, const solver::ResumePoint& point) {
    write_dumps(s, point);
  };
}

void RunSession::write_dumps(const solver::State& s, const solver::ResumePoint& point) {
  const io::OutputsResume where = writer_ ? outputs_->resume_point() : io::OutputsResume{};
  for (const std::filesystem::path& dump_path : dumps_->take()) {
    const std::filesystem::path path = process_file(dump_path, comm_);
    try {
      const auto begin = std::chrono::steady_clock::now();
      write_dump(path, fingerprint_, s, point, where);
      fmt::print(log_, "restart dump {} written at t = {:.6e}, cycle {} ({:.1f} MB in {:.3f} s)\n",
                 path.string(), s.time, s.cycle,
                 1e-6 * static_cast<double>(std::filesystem::file_size(path)),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
      log_.flush();
      last_dump_ = dump_path;  // what --restart takes: each process adds its number
    } catch (const std::exception& e) {
      if (output_failure_.empty()) output_failure_ = e.what();
    }
  }
}

std::string RunSession::summary(const solver::RunResult& result) const {
  const solver::State& s = *state_;
  std::ostringstream out;
  const bool switched_off =
      result.reason == solver::StopReason::interrupted && switches_->stop_requested();
  fmt::print(out, "\n{} at t = {:.6e}, cycle {}\n",
             !output_failure_.empty() ? "error termination: an output could not be written"
             : switched_off           ? "stopped by sense switch sw1 (d3kil)"
                                      : reason_text(result.reason),
             s.time, s.cycle);
  if (!output_failure_.empty()) fmt::print(out, "  {}\n", output_failure_);
  if (!result.message.empty()) fmt::print(out, "  {}\n", result.message);
  print_timing(out, result, s, comm_, dump_.has_value());
  print_spg_summary(out, s);
  inertia_.print(out, s);
  print_angular_budgets(out, s, budgets_);
  std::vector<std::string> notes;
  for (const auto& b : s.blocks)
    b->add_notes(s, notes);
  for (const std::string& n : notes)
    fmt::print(out, "  {}\n", n);
  if (result.reason == solver::StopReason::interrupted && !last_dump_.empty())
    fmt::print(out, "  continue with: mcdyna run {} --out {} --restart {} (and the same options)\n",
               options_.deck.string(), dir_.string(), last_dump_.string());
  if (s.mass_scaling_dt > 0.0)
    fmt::print(out, "  added mass (DT2MS) {:.6e}\n", solver::total_added_mass(s));
  fmt::print(out, "Outputs in {}:", dir_.string());
  if (writer_)
    for (const auto& f : outputs_->files())
      fmt::print(out, " {};", f);
  fmt::print(out, " d3hsp\n");
  return out.str();
}

int RunSession::finish(const solver::RunResult& result) {
  progress_->finish();
  if (step_log_) checked([&] { step_log_->flush(); });
  const std::string text = summary(result);
  log_ << text;
  log_.flush();
  if (writer_ && !log_ && output_failure_.empty())
    output_failure_ = fmt::format("cannot write {}", (dir_ / "d3hsp").string());
  if (!options_.quiet || result.reason != solver::StopReason::end_time || !output_failure_.empty())
    out_ << text;
  else
    err_ << inertia_.warning(*state_);  // quiet: the summary stays in d3hsp, the warning not
  if (!output_failure_.empty()) {
    fmt::print(err_, "mcdyna: error termination: {}\n", output_failure_);
    return kRunOutputFailed;
  }
  switch (result.reason) {
    case solver::StopReason::end_time:
    case solver::StopReason::end_cycle:
      return kRunOk;
    case solver::StopReason::interrupted:
      return kRunInterrupted;
    default:
      fmt::print(err_, "mcdyna: {}: {}\n", reason_text(result.reason), result.message);
      return kRunUnstable;
  }
}

}  // namespace mcdyna::cli
