// The compiled state as d3hsp describes it before the first cycle.
#include "cli/state_summary.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "solver/block.hpp"
#include "solver/energy.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::cli {

namespace {

// *CONTROL_ACCURACY OSU of a block or SPG part.
const char* stress_update_name(bool objective) {
  return objective ? "second-order objective stress update (OSU 1)"
                   : "first-order stress update (OSU 0)";
}

}  // namespace

void print_state_summary(std::ostream& log, const solver::State& s) {
  double mass = 0.0;
  for (const double m : s.nodes.mass)
    mass += m;
  const double added = solver::total_added_mass(s);
  for (const auto& b : s.rigid_bodies)
    mass += b.mass;
  fmt::print(log,
             "\nSolver state\n  nodes {}, deformable solids {} in {} blocks, rigid bodies {}\n",
             s.nodes.count(), solver::solids_of(s).count(), solver::solids_of(s).blocks.size(),
             s.rigid_bodies.size());
  for (const auto& b : solver::solids_of(s).blocks) {
    const auto& part = s.parts[static_cast<std::size_t>(b.part)];
    fmt::print(log, "  part {:>8}: {} elements, ELFORM {}, {} hourglass QM {}, Q1 {} Q2 {}, {}\n",
               part.id, b.end - b.begin, b.points_per_element == 1 ? 1 : 2,
               b.hourglass.stiffness() ? "stiffness" : "viscous", b.hourglass.coefficient,
               b.bulk_viscosity.quadratic, b.bulk_viscosity.linear,
               stress_update_name(b.objective));
  }
  for (const auto& b : s.rigid_bodies) {
    fmt::print(log, "  rigid part {:>8}: mass {:.6e}, centre ({:.6g}, {:.6g}, {:.6g}), {} nodes\n",
               b.part_id, b.mass, b.center[0], b.center[1], b.center[2], b.nodes.size());
  }
  // One spcforc line per constrained node, one record per wall.
  const solver::HistoryRecords records = solver::history_records(s);
  fmt::print(log, "  total mass {:.6e}; constrained nodes {}; rigid walls {}\n", mass,
             records.reactions.size(), records.walls.size());
  if (s.mass_scaling_dt > 0.0) {
    fmt::print(log, "  mass scaling: target step {:.4e}, added mass so far {:.6e} ({:.3f} %)\n",
               s.mass_scaling_dt, added, mass > 0.0 ? 100.0 * added / mass : 0.0);
  }
  static const char* kModes[] = {"none (plain nodal integration)", "direct smoothing (Eq. 7)",
                                 "MC-SPG (Eqs. 13-31)",
                                 "original SPG, strain-gradient stabilisation (ITB 1, Eqs. 8-12)"};
  static const char* kShapes[] = {"cubic spline, box", "quadratic spline, box",
                                  "cubic spline, sphere"};
  for (const solver::spg::Domain* dp : solver::spg::domains_of(s)) {
    const solver::spg::Domain& d = *dp;
    const auto& st = d.settings;
    long shared = 0, surface = 0;
    for (std::size_t i = 0; i < d.particles.nodes.size(); ++i) {
      shared += d.particles.shared[i];
      surface += d.particles.surface[i];
    }
    fmt::print(
        log,
        "  SPG part {:>8}: {} particles ({} shared with FE/constraints, {} on the surface); "
        "{}{}; kernel {}, {}, checked every {} steps{}; bond failure {}; {}\n",
        s.parts[static_cast<std::size_t>(d.part)].id, d.count(), shared, surface,
        kModes[static_cast<int>(st.stabilization)],
        st.mode_control > 0.0
            ? fmt::format(" with low-energy-mode control {:g} (MSC 1)", st.mode_control)
            : std::string(),
        kShapes[static_cast<int>(st.shape)],
        st.kernel_update == solver::spg::KernelUpdate::eulerian ? "Eulerian" : "updated Lagrangian",
        st.renewal_interval,
        st.kernel_update == solver::spg::KernelUpdate::eulerian || !(st.renewal_strain > 0.0)
            ? std::string(" and renewed at each check")
            : fmt::format(" and renewed per particle at Green strain {:g} ({:g} under "
                          "compression) or broken bonds",
                          st.renewal_strain,
                          solver::spg::kCompressionRenewalShare * st.renewal_strain),
        st.bond_failure
            ? fmt::format("FS {:g} and STRETCH {:g}", st.failure_strain, st.failure_stretch)
            : std::string("off"),
        stress_update_name(st.objective));
  }
}

}  // namespace mcdyna::cli
