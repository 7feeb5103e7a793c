#pragma once
/// What a run's summary says of its SPG parts at the end (run_command.cpp): the kernels
/// (neighbours, renewals, bonds, pieces, degeneracy) and, with --spg-angular-budget, each
/// part's angular-momentum budget.
#include <ostream>
#include <vector>

#include "solver/spg/angular_budget.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

/// --spg-angular-budget: the scheme's own contribution to each part's angular momentum.
void print_angular_budgets(std::ostream& out, const solver::State& s,
                           const std::vector<solver::spg::AngularBudget>& budgets);

/// What the particle kernels did. Collective over several processes: process 0 receives the
/// rows it does not keep itself.
void print_spg_summary(std::ostream& out, const solver::State& s);

}  // namespace mcdyna::cli
