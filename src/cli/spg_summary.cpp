#include "cli/spg_summary.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "solver/spg/distribution.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::cli {

void print_angular_budgets(std::ostream& out, const solver::State& s,
                           const std::vector<solver::spg::AngularBudget>& budgets) {
  for (std::size_t k = 0; k < budgets.size(); ++k) {
    const solver::spg::AngularBudget& b = budgets[k];
    if (!b.started) continue;
    const solver::Vec3 dl = b.last - b.first, defect = b.defect();
    fmt::print(
        out,
        "  SPG part {}: angular momentum (about the origin) changed by ({:.4e}, {:.4e}, "
        "{:.4e}); the moment impulse of the forces on its particles was ({:.4e}, {:.4e}, "
        "{:.4e}); the scheme's own part A + B - C (theory.md, Angular momentum) "
        "({:.4e}, {:.4e}, {:.4e}): {:.3e} of the forces' moment impulse, {:.3e} of the initial "
        "sum m|x - x_c||u| {:.4e}{}\n",
        s.parts[static_cast<std::size_t>(solver::spg::domain_of(s, k).part)].id, dl.x(), dl.y(),
        dl.z(), b.sum_c.x(), b.sum_c.y(), b.sum_c.z(), defect.x(), defect.y(), defect.z(),
        b.sum_c.norm() > 0.0 ? defect.norm() / b.sum_c.norm() : 0.0,
        b.scale > 0.0 ? defect.norm() / b.scale : 0.0, b.scale,
        b.pinned ? " (pinned particles: constraint and coupling impulses are not in the "
                   "forces)"
                 : "");
  }
}

void print_spg_summary(std::ostream& out, const solver::State& s) {
  const std::vector<const solver::spg::Domain*> domains = solver::spg::domains_of(s);
  for (std::size_t k = 0; k < domains.size(); ++k) {
    const solver::spg::Domain& d = *domains[k];
    const solver::spg::NeighbourList gathered =
        s.ownership.split_part(k) ? solver::spg::rows_on_root(s, k) : solver::spg::NeighbourList{};
    const solver::spg::NeighbourList& rows = s.ownership.split_part(k) ? gathered : d.kernel.list;
    if (d.kernel.step_bound.initial_critical > 0.0) {
      fmt::print(out,
                 "  SPG part {}: critical step of the initial arrangement {:.4e} s (largest "
                 "eigenvalue by power iteration)",
                 s.parts[static_cast<std::size_t>(d.part)].id,
                 d.kernel.step_bound.initial_critical);
      const solver::Index at = d.kernel.step_bound.smallest_critical_particle;
      if (d.settings.step_estimate == solver::spg::StepEstimate::eigenvalue)
        fmt::print(out,
                   ", the smallest {:.4e} s at t = {:.6e} (mode largest at node {}); particle "
                   "steps scaled to it every second cycle",
                   d.kernel.step_bound.smallest_critical,
                   d.kernel.step_bound.smallest_critical_time,
                   at >= 0 ? s.nodes.ids[static_cast<std::size_t>(
                                 d.particles.nodes[static_cast<std::size_t>(at)])]
                           : 0);
      fmt::print(out, "\n");
    }
    const double pairs = static_cast<double>(rows.neighbours.size());
    fmt::print(out,
               "  SPG part {}: {} particles, {:.1f} neighbours per particle, {} kernel renewals "
               "({:.1f} % of the rows per renewal), {} bonds broken\n",
               s.parts[static_cast<std::size_t>(d.part)].id, d.count(),
               d.count() > 0 ? pairs / d.count() : 0.0, d.diagnostics.renewals,
               d.diagnostics.renewals > 0 && d.count() > 0
                   ? 100.0 * static_cast<double>(d.diagnostics.renewed_rows) /
                         (static_cast<double>(d.diagnostics.renewals) * d.count())
                   : 0.0,
               d.diagnostics.broken_bonds);
    if (d.diagnostics.broken_bonds > 0) {
      const solver::spg::Pieces p = solver::spg::count_pieces(rows);
      fmt::print(out,
                 "  SPG part {}: {} separate piece(s) with no neighbours across ({} of them "
                 "single particles; the largest has {} particles)\n",
                 s.parts[static_cast<std::size_t>(d.part)].id, p.pieces, p.single, p.largest);
    }
    if (d.diagnostics.released > 0)
      fmt::print(out,
                 "  SPG part {}: {} time(s) a particle with broken bonds had its neighbourhood "
                 "invert and was left without stress until its next kernel renewal (debris of "
                 "the failed material)\n",
                 s.parts[static_cast<std::size_t>(d.part)].id, d.diagnostics.released);
    if (d.diagnostics.largest_mobility_particle >= 0)
      fmt::print(out,
                 "  SPG part {}: steps shortened where smoothed masses (Eq. 20) fell below the "
                 "particle masses: largest factor {:.3g} on the frequency squared, at the row of "
                 "node {} at t = {:.6e}\n",
                 s.parts[static_cast<std::size_t>(d.part)].id, d.diagnostics.largest_mobility,
                 s.nodes.ids[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(
                     d.diagnostics.largest_mobility_particle)])],
                 d.diagnostics.largest_mobility_time);
    if (d.diagnostics.first_degenerate >= 0) {
      fmt::print(out,
                 "  warning: SPG part {}: degenerate neighbourhoods (moment matrix singular: "
                 "neighbours on a plane or line) at {} renewals, first at node {} at t = {:.6e}; "
                 "such particles carry no stress until their neighbourhood is 3-D again\n",
                 s.parts[static_cast<std::size_t>(d.part)].id, d.diagnostics.degenerate_events,
                 s.nodes.ids[static_cast<std::size_t>(
                     d.particles.nodes[static_cast<std::size_t>(d.diagnostics.first_degenerate)])],
                 d.diagnostics.first_degenerate_time);
    }
  }
}

}  // namespace mcdyna::cli
