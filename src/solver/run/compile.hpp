#pragma once
/// Model database -> solver State. Runs once after the deck checks. Everything the solver cannot
/// run is reported as an error at the deck location that asks for it; nothing is dropped silently.
/// The formulations' compile passes and what they share: solver/compile.hpp.
#include <memory>

#include "core/diagnostics.hpp"
#include "model/model_database.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// Returns the state, or nullptr when errors were reported (the model must have passed
/// model::check, which builds the ID indices this uses).
std::unique_ptr<State> compile(const model::ModelDatabase& model, core::Diagnostics& diags);

}  // namespace mcdyna::solver
