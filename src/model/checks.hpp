#pragma once
/// Cross-checks of a built model: ID indices and duplicates, every reference resolved, physical
/// and geometric sanity, and whether mcdyna can run what the deck asks for. Reports every problem
/// at its deck location; builds ModelDatabase::index as a side effect.
#include "core/diagnostics.hpp"
#include "model/model_database.hpp"

namespace mcdyna::model {

/// Runs all checks. Returns the number of errors it added.
std::size_t check(ModelDatabase& model, core::Diagnostics& diags);

namespace detail {
/// Builds `index` from `v`'s IDs, reporting each repeated ID at the repeat's location.
template <typename Entity>
void index_one(IdIndex& index, const std::vector<Entity>& v, const char* what,
               core::Diagnostics& diags) {
  for (const auto& [first, again] : index.build(v)) {
    diags.error(v[again].loc, "{} {} is defined twice (first at line {})", what, v[again].id,
                v[first].loc.line);
  }
}

void build_indices(ModelDatabase& m, core::Diagnostics& diags);
void check_references(const ModelDatabase& m, core::Diagnostics& diags);
void check_sanity(const ModelDatabase& m, core::Diagnostics& diags);
void check_sensors(const ModelDatabase& m, core::Diagnostics& diags);  // checks_sensors.cpp
}  // namespace detail

}  // namespace mcdyna::model
