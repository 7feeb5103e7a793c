#include "solver/fe/hourglass.hpp"

#include "solver/compile.hpp"  // control_bulk_viscosity

namespace mcdyna::solver::detail {

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

}  // namespace mcdyna::solver::detail
