#pragma once
/// Deck -> model database: classify every keyword block, run the builder of each supported one.
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "deck/deck.hpp"
#include "deck/registry.hpp"
#include "model/model_database.hpp"

namespace mcdyna::deck {

/// One keyword occurrence as classified, for the migration report.
struct KeywordUse {
  std::string name;  ///< as written (upper case, options included)
  Support support = Support::unsupported;
  std::string reason;
  core::SourceLoc loc;
};

struct BuildResult {
  model::ModelDatabase model;
  std::vector<KeywordUse> keywords;  ///< in deck order
};

BuildResult build_model(const Deck& deck, const Registry& registry, core::Diagnostics& diags);

}  // namespace mcdyna::deck
