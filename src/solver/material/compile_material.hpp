#pragma once
/// A part's deck material (with its *EOS and *MAT_ADD_EROSION) as the solver's Material, for
/// the compile passes of the formulations whose parts carry a material.
#include "core/diagnostics.hpp"
#include "model/model_database.hpp"
#include "solver/material/material.hpp"

namespace mcdyna::solver::detail {

Material compile_material(const model::ModelDatabase& m, const model::Part& part,
                          core::Diagnostics& d);

}  // namespace mcdyna::solver::detail
