#pragma once
/// Reading a deck as both `check` and `run` do: read, build, cross-check, migration report.
#include <filesystem>
#include <iosfwd>

#include "core/diagnostics.hpp"
#include "deck/build_model.hpp"
#include "deck/deck.hpp"

namespace mcdyna::cli {

struct LoadedDeck {
  core::Diagnostics diags;
  deck::Deck deck;
  deck::BuildResult built;
  std::size_t unsupported_physics = 0;  ///< unsupported keywords that change the physics
  double read_ms = 0.0, build_ms = 0.0, check_ms = 0.0;
};

LoadedDeck load_deck(const std::filesystem::path& path, std::ostream& migration_report);

}  // namespace mcdyna::cli
