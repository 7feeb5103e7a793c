#include "cli/load.hpp"

#include <chrono>

#include "cli/report.hpp"
#include "deck/registry.hpp"
#include "model/checks.hpp"

namespace mcdyna::cli {

LoadedDeck load_deck(const std::filesystem::path& path, std::ostream& migration_report) {
  using Clock = std::chrono::steady_clock;
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  LoadedDeck d;
  const auto t0 = Clock::now();
  const deck::Registry registry;
  d.deck = deck::read_deck(path, d.diags);
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

}  // namespace mcdyna::cli
