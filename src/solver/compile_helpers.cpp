// What the compile passes share: node sets, curves and the controls several formulations read
// (compile.hpp).
#include <algorithm>

#include "solver/compile.hpp"

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

Index curve_index(const model::ModelDatabase& m, model::Id id) {
  const auto i = m.index.curves.find(id);
  return i == model::IdIndex::kNone ? -1 : static_cast<Index>(i);
}

}  // namespace detail

}  // namespace mcdyna::solver
