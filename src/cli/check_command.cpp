#include "cli/check_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <chrono>
#include <ostream>
#include <sstream>

#include "cli/load.hpp"
#include "cli/report.hpp"
#include "deck/deck.hpp"
#include "solver/run/compile.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

namespace {

// What `run` finds only when it compiles the model for the solver (the blocks' links: a sensor's
// contact, a control's wall; what the solver cannot run of a keyword it reads): compiled here
// too, so that `check` says all that `run` would. Returns the milliseconds it took.
double compile_check(const LoadedDeck& d, core::Diagnostics& diags) {
  const auto start = std::chrono::steady_clock::now();
  (void)solver::compile(d.built.model, diags);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

int check_one(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  std::ostringstream report;
  LoadedDeck d = load_deck(options.deck, report, options.case_id);
  core::print_diagnostics(err, d.diags, d.deck.files, options.max_messages);
  core::Diagnostics compile_diags;
  const double compile_ms = d.diags.has_errors() ? 0.0 : compile_check(d, compile_diags);
  core::print_diagnostics(err, compile_diags, d.deck.files, options.max_messages);
  if (!options.quiet) {
    print_summary(out, d.deck, d.built.model, count_model(d.built.model));
    out << report.str();
  }
  fmt::print(out,
             "\nTiming: read {:.0f} ms, build {:.0f} ms, checks {:.0f} ms, compile {:.0f} ms\n",
             d.read_ms, d.build_ms, d.check_ms, compile_ms);
  const std::size_t physics = d.unsupported_physics;
  const bool blocked = physics > 0 && !options.allow_unsupported;
  if (blocked) {
    fmt::print(err,
               "mcdyna: error: {} unsupported keyword{} change{} the physics (see the "
               "migration report); --allow-unsupported runs without them\n",
               physics, physics == 1 ? "" : "s", physics == 1 ? "s" : "");
  }
  const std::size_t errors =
      d.diags.error_count() + compile_diags.error_count() + (blocked ? 1 : 0);
  const std::size_t warnings = d.diags.warning_count() + compile_diags.warning_count();
  const bool failed = errors > 0;
  fmt::print(out, "{}: {} error{}, {} warning{}{}\n", options.deck.string(), errors,
             errors == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s",
             failed ? "" : " - ready to run");
  return failed ? 1 : 0;
}

}  // namespace

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  if (const std::string problem = deck::file_problem(options.deck); !problem.empty()) {
    fmt::print(err, "mcdyna: error: deck {}: {}\n", options.deck.string(), problem);
    return 2;  // a usage error, as for `run`
  }
  const std::vector<deck::Case> cases =
      options.case_id == 0 ? deck_cases(options.deck) : std::vector<deck::Case>{};
  if (cases.empty()) return check_one(options, out, err);
  // Each case is its own model: checked one after the other, as `run` runs them.
  int result = 0;
  for (const deck::Case& c : cases) {
    CheckOptions one = options;
    one.case_id = c.id;
    fmt::print(out, "{}Case {} ({})\n", &c == &cases.front() ? "" : "\n", c.id, c.job);
    result = std::max(result, check_one(one, out, err));
  }
  return result;
}

}  // namespace mcdyna::cli
