#include "cli/load.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "cli/report.hpp"
#include "deck/registry.hpp"
#include "model/checks.hpp"

namespace mcdyna::cli {

LoadedDeck load_deck(const std::filesystem::path& path, std::ostream& migration_report,
                     long case_id) {
  using Clock = std::chrono::steady_clock;
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  LoadedDeck d;
  const auto t0 = Clock::now();
  const deck::Registry registry;
  d.deck = deck::read_deck(path, d.diags);
  const std::vector<deck::Case> cases = deck::read_cases(d.deck, d.diags);
  if (case_id > 0) {
    const auto c = std::find_if(cases.begin(), cases.end(),
                                [&](const deck::Case& k) { return k.id == case_id; });
    if (c == cases.end()) {
      std::string defined;
      for (const deck::Case& k : cases)
        defined += fmt::format("{}{} ({})", defined.empty() ? "" : ", ", k.id, k.job);
      d.diags.error(core::SourceLoc{}, "--case {}: the deck defines {}", case_id,
                    defined.empty() ? std::string("no *CASE") : "the cases " + defined);
    } else {
      deck::keep_case(d.deck, *c);
    }
  } else {
    deck::keep_main_model(d.deck);
  }
  const auto t1 = Clock::now();
  d.built = deck::build_model(d.deck, registry, d.diags);
  const auto t2 = Clock::now();
  model::check(d.built.model, d.diags);
  const auto t3 = Clock::now();
  d.unsupported_physics = print_migration_report(migration_report, d.deck, d.built.keywords);
  d.read_ms = ms(t0, t1);
  d.build_ms = ms(t1, t2);
  d.check_ms = ms(t2, t3);
  return d;
}

std::vector<deck::Case> deck_cases(const std::filesystem::path& path) {
  core::Diagnostics ignored;  // load_deck reports the deck's problems
  const deck::Deck d = deck::read_deck(path, ignored);
  return deck::read_cases(d, ignored);
}

}  // namespace mcdyna::cli
