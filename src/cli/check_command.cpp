#include "cli/check_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <chrono>
#include <ostream>
#include <sstream>

#include "cli/report.hpp"
#include "core/diagnostics.hpp"
#include "deck/build_model.hpp"
#include "deck/deck.hpp"
#include "deck/registry.hpp"
#include "model/checks.hpp"

namespace mcdyna::cli {

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  core::Diagnostics diags;
  const deck::Registry registry;
  deck::Deck deck = deck::read_deck(options.deck, diags);
  const auto t_read = Clock::now();
  deck::BuildResult built = deck::build_model(deck, registry, diags);
  const auto t_build = Clock::now();
  model::check(built.model, diags);
  const auto t_check = Clock::now();

  core::print_diagnostics(err, diags, deck.files, options.max_messages);
  std::size_t physics = 0;
  if (!options.quiet) {
    print_summary(out, deck, built.model, count_model(built.model));
  }
  {
    std::ostringstream report;
    physics = print_migration_report(report, deck, built.keywords);
    if (!options.quiet) out << report.str();
  }
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  fmt::print(out, "\nTiming: read {:.0f} ms, build {:.0f} ms, checks {:.0f} ms\n", ms(t0, t_read),
             ms(t_read, t_build), ms(t_build, t_check));
  const bool blocked = physics > 0 && !options.allow_unsupported;
  if (blocked) {
    fmt::print(err,
               "mcdyna: error: {} unsupported keyword{} change{} the physics (see the "
               "migration report); --allow-unsupported runs without them\n",
               physics, physics == 1 ? "" : "s", physics == 1 ? "s" : "");
  }
  const bool failed = diags.has_errors() || blocked;
  fmt::print(out, "{}: {} error{}, {} warning{}{}\n", options.deck.string(),
             diags.error_count() + (blocked ? 1 : 0), diags.error_count() + blocked == 1 ? "" : "s",
             diags.warning_count(), diags.warning_count() == 1 ? "" : "s",
             failed ? "" : " - ready to run");
  return failed ? 1 : 0;
}

}  // namespace mcdyna::cli
