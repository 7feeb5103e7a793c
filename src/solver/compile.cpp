// compile(): nodes and parts, then each formulation's compile pass (compile_*.cpp in its folder)
// in the registry's order (formulations.cpp); then the time controls.
#include "solver/compile.hpp"

#include <algorithm>
#include <cmath>

#include "solver/formulations.hpp"
#include "solver/shells/shell_elements.hpp"  // poisson_ratio, shells_of
#include "solver/solids/solids.hpp"

namespace mcdyna::solver {

std::vector<Index> node_set_nodes(const model::ModelDatabase& m, model::Id set) {
  std::vector<Index> out;
  const model::NodeSet* ns = m.node_set(set);
  if (ns == nullptr) return out;
  for (const model::Id id : ns->nodes) {
    const auto i = m.index.nodes.find(id);
    if (i != model::IdIndex::kNone) out.push_back(static_cast<Index>(i));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace detail {

BulkViscosityParams control_bulk_viscosity(const model::ModelDatabase& m) {
  BulkViscosityParams q;
  if (m.controls.bulk_viscosity) {
    q.quadratic = m.controls.bulk_viscosity->quadratic;
    q.linear = m.controls.bulk_viscosity->linear;
  }
  return q;
}

bool objective_update(const model::ModelDatabase& m, const model::Part& part) {
  if (!m.controls.accuracy) return false;
  const model::AccuracyControl& a = *m.controls.accuracy;
  if (a.objective_parts == 0) return a.objective == 1;
  const model::PartSet* ps = m.part_set(a.objective_parts);
  return ps != nullptr && std::find(ps->parts.begin(), ps->parts.end(), part.id) != ps->parts.end();
}

void check_accuracy_control(const model::ModelDatabase& m, core::Diagnostics& d) {
  if (!m.controls.accuracy) return;
  const model::AccuracyControl& a = *m.controls.accuracy;
  if (a.objective_parts != 0 && m.part_set(a.objective_parts) == nullptr)
    d.error(a.loc, "*CONTROL_ACCURACY: PIDOSU part set {} is not defined", a.objective_parts);
  if (a.objective_parts != 0 && a.objective != 0)
    d.note(a.loc,
           "*CONTROL_ACCURACY: OSU {} is ignored, PIDOSU {} names the parts that take the "
           "objective stress update",
           a.objective, a.objective_parts);
  if (a.invariant != 1 && a.invariant != 0)
    d.note(a.loc,
           "*CONTROL_ACCURACY: INN {} (invariant node numbering) has no effect: mcdyna's "
           "solids and particles do not depend on the node order, and its shells take their "
           "frame from the first side (LS-DYNA's INN 1)",
           a.invariant);
  if (a.implicit != 0)
    d.note(a.loc, "*CONTROL_ACCURACY: IACC {} (implicit accuracy) has no effect: explicit solver",
           a.implicit);
  if (a.explicit_accuracy != 0.0)
    d.note(a.loc,
           "*CONTROL_ACCURACY: EXACC {:g} (explicit accuracy of the shells) has no effect: "
           "mcdyna's shells run their standard update",
           a.explicit_accuracy);
}

const model::Hourglass* part_hourglass(const model::ModelDatabase& m, const model::Part& part) {
  if (part.hourglass == 0) return nullptr;
  for (const model::Hourglass& h : m.hourglasses)
    if (h.id == part.hourglass) return &h;
  return nullptr;
}

namespace {
// IHQ 4 and 5 resist the modes with stiffness; 0 (the default, 1) to 3 with viscous forces.
// Other types are refused by the model checks (6-10) or noted by the shells' pass (8).
HourglassForm hourglass_form(int ihq) {
  return ihq == 4 || ihq == 5 ? HourglassForm::stiffness : HourglassForm::viscous;
}
}  // namespace

HourglassParams hourglass_of(const model::ModelDatabase& m, const model::Part& part,
                             BulkViscosityParams& q) {
  HourglassParams hg;
  if (m.controls.hourglass) {
    hg.form = hourglass_form(m.controls.hourglass->type);
    hg.coefficient = m.controls.hourglass->coefficient;
  }
  q = control_bulk_viscosity(m);
  if (const model::Hourglass* h = part_hourglass(m, part)) {
    hg.form = hourglass_form(h->type);
    hg.coefficient = h->coefficient;
    q.quadratic = h->quadratic_bulk_viscosity;
    q.linear = h->linear_bulk_viscosity;
  }
  return hg;
}

Index curve_index(const model::ModelDatabase& m, model::Id id) {
  const auto i = m.index.curves.find(id);
  return i == model::IdIndex::kNone ? -1 : static_cast<Index>(i);
}

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

}  // namespace detail

std::unique_ptr<State> compile(const model::ModelDatabase& m, core::Diagnostics& diags) {
  const std::size_t errors = diags.error_count();
  auto s = std::make_unique<State>();
  s->title = m.title;
  for (const model::Curve& c : m.curves)
    s->curves.emplace_back(c);
  detail::check_accuracy_control(m, diags);
  detail::compile_nodes_and_parts(m, *s);
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
  detail::warn_free_corner_elements(m, *s, solids_of(before), shells_of(before), diags);
  if (diags.error_count() > errors) return nullptr;
  s->blocks = make_blocks(std::move(compiled));
  for (const auto& b : s->blocks)
    b->link(*s, s->blocks, diags);
  if (diags.error_count() > errors) return nullptr;
  return s;
}

}  // namespace mcdyna::solver
