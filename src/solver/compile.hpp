#pragma once
/// Model database -> solver State. Runs once after the deck checks. Everything the solver cannot
/// run is reported as an error at the deck location that asks for it; nothing is dropped silently.
#include <memory>

#include "core/diagnostics.hpp"
#include "model/model_database.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// Returns the state, or nullptr when errors were reported (the model must have passed
/// model::check, which builds the ID indices this uses).
std::unique_ptr<State> compile(const model::ModelDatabase& model, core::Diagnostics& diags);

/// Solver indices of the nodes of a node set (sorted, unique); empty if the set is unknown.
std::vector<Index> node_set_nodes(const model::ModelDatabase& m, model::Id set);

namespace detail {
// The pieces of compile(), in the order it runs them (compile_*.cpp).
void compile_nodes_and_solids(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_rigid_bodies(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_constraints(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_motions(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_initial_velocities(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_rigid_walls(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_spg_parts(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
void compile_contacts(const model::ModelDatabase& m, State& s, core::Diagnostics& d);
Material compile_material(const model::ModelDatabase& m, const model::Part& part,
                          core::Diagnostics& d);
Index curve_index(const model::ModelDatabase& m, model::Id id);
/// Q1, Q2 of *CONTROL_BULK_VISCOSITY (defaults without it).
BulkViscosityParams control_bulk_viscosity(const model::ModelDatabase& m);
/// Whether the part takes the second-order objective stress update of *CONTROL_ACCURACY:
/// OSU 1, or membership of the PIDOSU part set when one is given (OSU then ignored).
bool objective_update(const model::ModelDatabase& m, const model::Part& part);
/// *CONTROL_ACCURACY's fields that do nothing here, as notes; a PIDOSU set that is not defined
/// is an error.
void check_accuracy_control(const model::ModelDatabase& m, core::Diagnostics& d);
}  // namespace detail

}  // namespace mcdyna::solver
