#pragma once
/// Reading a deck as both `check` and `run` do: read, build, cross-check, migration report.
#include <filesystem>
#include <iosfwd>

#include "core/diagnostics.hpp"
#include "deck/build_model.hpp"
#include "deck/cases.hpp"
#include "deck/deck.hpp"

namespace mcdyna::cli {

struct LoadedDeck {
  core::Diagnostics diags;
  deck::Deck deck;
  deck::BuildResult built;
  std::size_t unsupported_physics = 0;  ///< unsupported keywords that change the physics
  double read_ms = 0.0, build_ms = 0.0, check_ms = 0.0;
};

/// `case_id` > 0 reads that *CASE's model (an error if the deck has no such case); 0 reads the
/// main model (what a deck without *CASE is).
LoadedDeck load_deck(const std::filesystem::path& path, std::ostream& migration_report,
                     long case_id = 0);

/// The *CASE definitions of a deck (empty when it has none or cannot be read): `run` and
/// `check` go through them one by one when no --case is given.
std::vector<deck::Case> deck_cases(const std::filesystem::path& path);

}  // namespace mcdyna::cli
