#pragma once
/// Text reports of `mcdyna check`: the model summary and the migration report.
#include <iosfwd>
#include <vector>

#include "deck/build_model.hpp"
#include "deck/deck.hpp"
#include "model/model_database.hpp"

namespace mcdyna::cli {

/// Counts a summary needs that take a pass over the mesh.
struct ModelCounts {
  std::size_t spg_particles = 0;               ///< distinct nodes of elements in SPG parts
  std::vector<std::size_t> elements_per_part;  ///< parallel to model.parts
};

ModelCounts count_model(const model::ModelDatabase& m);

void print_summary(std::ostream& out, const deck::Deck& deck, const model::ModelDatabase& m,
                   const ModelCounts& counts);

/// Prints the migration report; returns the number of unsupported physics-changing keywords.
std::size_t print_migration_report(std::ostream& out, const deck::Deck& deck,
                                   const std::vector<deck::KeywordUse>& uses);

}  // namespace mcdyna::cli
