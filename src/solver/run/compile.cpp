// compile(): nodes and parts, then each formulation's compile pass (compile_*.cpp in its folder)
// in the registry's order (formulations.cpp); then the time controls.
#include "solver/run/compile.hpp"

#include <algorithm>
#include <cmath>

#include "solver/compile.hpp"
#include "solver/run/formulations.hpp"
#include "solver/shells/shell_elements.hpp"  // poisson_ratio, shells_of
#include "solver/solids/solids.hpp"

namespace mcdyna::solver {

namespace {

// The nodes (positions, zero velocities and masses) and one PartInfo per part, in deck order.
void compile_nodes_and_parts(const model::ModelDatabase& m, State& s) {
  Nodes& nd = s.nodes;
  const auto nn = static_cast<Index>(m.nodes.size());
  nd.initial.resize(3, nn);
  for (Index i = 0; i < nn; ++i) {
    const model::Node& node = m.nodes[static_cast<std::size_t>(i)];
    nd.ids.push_back(node.id);
    nd.initial.col(i) = Vec3(node.position[0], node.position[1], node.position[2]);
  }
  nd.position = nd.initial;
  nd.velocity.setZero(3, nn);
  nd.acceleration.setZero(3, nn);
  nd.mass.assign(static_cast<std::size_t>(nn), 0.0);
  nd.added_mass.assign(static_cast<std::size_t>(nn), 0.0);
  nd.rigid_body.assign(static_cast<std::size_t>(nn), -1);

  // Parts in deck order; each formulation's compile pass fills in its parts' material.
  for (const model::Part& part : m.parts)
    s.parts.push_back(PartInfo{part.id, part.heading, -1, -1, part.material});
}

// Elements whose every corner is free sideways breathe in a mode above their L / c step
// estimate (verification.md "Lone elements"): the one-point hexahedron at 2 c sqrt((1 + nu) /
// (1 - nu)) / L, unstable for TSSFAC above sqrt((1 - nu) / (1 + nu)) (0.734 at nu 0.3), as soon
// as every corner is on at most two hexahedra (a column one element across); the shell square
// at 2 c sqrt(1 + nu) / L, TSSFAC above 1 / sqrt(1 + nu) (0.877), when it is alone (a strip one
// element wide is held enough). Said per part when the deck's TSSFAC is above the bound.
void warn_free_corner_elements(const model::ModelDatabase& m, const State& s, const Solids& solids,
                               const Shells& shells, core::Diagnostics& d) {
  const double tssfac = s.time_control.scale_factor;
  const auto node_count = static_cast<std::size_t>(s.nodes.count());
  std::vector<int> uses(node_count, 0), shell_uses(node_count, 0);
  for (const auto& conn : solids.nodes)
    for (const Index n : conn)
      ++uses[static_cast<std::size_t>(n)];
  for (const auto& conn : shells.nodes)
    for (std::size_t c = 0; c < (conn[3] == conn[2] ? 3U : 4U); ++c)
      ++shell_uses[static_cast<std::size_t>(conn[c])];
  // Per part, the flagged elements' count said when TSSFAC is above bound(nu).
  auto warn = [&](const std::vector<long>& flagged, double (*bound_of)(double), const char* what) {
    for (std::size_t p = 0; p < flagged.size(); ++p) {
      const Index material = s.parts[p].material;
      if (flagged[p] == 0 || material < 0) continue;
      const double nu = poisson_ratio(s.materials[static_cast<std::size_t>(material)]);
      const double bound = bound_of(nu);
      if (tssfac <= bound) continue;
      d.warning(m.parts[p].loc,
                "part {}: {} {}: their breathing is above the step estimate for TSSFAC > {:.3f} "
                "(Poisson's ratio {:.2f}); at TSSFAC {} they can go unstable",
                m.parts[p].id, flagged[p], what, bound, nu, tssfac);
    }
  };
  std::vector<long> flagged(s.parts.size(), 0);
  for (std::size_t e = 0; e < solids.nodes.size(); ++e) {
    const auto& conn = solids.nodes[e];
    if (std::all_of(conn.begin(), conn.end(),
                    [&](Index n) { return uses[static_cast<std::size_t>(n)] <= 2; }))
      ++flagged[static_cast<std::size_t>(solids.part[e])];
  }
  warn(
      flagged, [](double nu) { return std::sqrt((1.0 - nu) / (1.0 + nu)); },
      "hexahedra are one element across (every corner on at most two; mesh two across or lower "
      "TSSFAC)");
  std::fill(flagged.begin(), flagged.end(), 0);
  for (std::size_t e = 0; e < shells.nodes.size(); ++e) {
    const auto& conn = shells.nodes[e];
    const std::size_t corners = conn[3] == conn[2] ? 3U : 4U;
    bool alone = true;
    for (std::size_t c = 0; c < corners; ++c) {
      const auto n = static_cast<std::size_t>(conn[c]);
      alone = alone && shell_uses[n] == 1 && uses[n] == 0 && s.nodes.rigid_body[n] < 0;
    }
    if (alone) ++flagged[static_cast<std::size_t>(shells.part[e])];
  }
  warn(
      flagged, [](double nu) { return 1.0 / std::sqrt(1.0 + nu); },
      "shell element(s) stand alone (no corner shared)");
}

}  // namespace

std::unique_ptr<State> compile(const model::ModelDatabase& m, core::Diagnostics& diags) {
  const std::size_t errors = diags.error_count();
  auto s = std::make_unique<State>();
  s->title = m.title;
  for (const model::Curve& c : m.curves)
    s->curves.emplace_back(c);
  detail::check_accuracy_control(m, diags);
  compile_nodes_and_parts(m, *s);
  const std::vector<Formulation>& lines = formulations();
  std::vector<Blocks> compiled(lines.size());
  const CompiledBlocks before(compiled);
  for (const std::size_t k : compile_order(lines)) {
    if (lines[k].compile != nullptr) lines[k].compile(m, *s, before, diags);
    if (lines[k].compile_blocks != nullptr)
      lines[k].compile_blocks(m, *s, before, compiled[k], diags);
    if (lines[k].stop_on_errors && diags.error_count() > errors) return nullptr;
  }

  TimeControl& tc = s->time_control;
  if (m.controls.termination) {
    tc.end_time = m.controls.termination->end_time;
    tc.end_cycle = m.controls.termination->end_cycle;
    tc.min_step_factor = m.controls.termination->min_step_factor;
  }
  if (m.controls.time_step) {
    const model::TimeStepControl& t = *m.controls.time_step;
    tc.scale_factor = t.scale_factor > 0.0 ? t.scale_factor : 0.9;
    if (t.scale_factor < 0.0) {
      diags.error(t.loc, "*CONTROL_TIMESTEP: TSSFAC < 0 (a curve) is not supported");
    }
    tc.initial_step = t.initial_step;
    tc.mass_scaling_step = t.mass_scaling_step;
    if (t.max_step_curve != 0) {
      tc.max_step_curve = detail::curve_index(m, t.max_step_curve);
      if (tc.max_step_curve < 0) {
        diags.error(t.loc, "*CONTROL_TIMESTEP: LCTM {} is not a defined curve", t.max_step_curve);
      }
    }
  }
  s->mass_scaling_dt =
      tc.mass_scaling_step != 0.0 ? tc.scale_factor * std::abs(tc.mass_scaling_step) : 0.0;
  warn_free_corner_elements(m, *s, solids_of(before), shells_of(before), diags);
  if (diags.error_count() > errors) return nullptr;
  s->blocks = make_blocks(std::move(compiled));
  for (const auto& b : s->blocks)
    b->link(*s, s->blocks, diags);
  if (diags.error_count() > errors) return nullptr;
  return s;
}

}  // namespace mcdyna::solver
