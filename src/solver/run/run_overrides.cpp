#include "solver/run/run_overrides.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::solver {

void apply_spg_overrides(State& s, const SpgOverrides& o) {
  for (spg::Domain* d : spg::domains_of(s)) {
    if (o.stabilization) {
      d->settings.stabilization = *o.stabilization;
      d->settings.step_estimate = spg::default_step_estimate(*o.stabilization);
    }
    if (o.renewal_strain) d->settings.renewal_strain = *o.renewal_strain;
    if (o.mode_control) d->settings.mode_control = *o.mode_control;
    if (o.step_estimate) d->settings.step_estimate = *o.step_estimate;
  }
}

void apply_run_limits(State& s, const RunLimits& l) {
  if (l.fixed_step > 0.0) {
    s.time_control.fixed_step = l.fixed_step;
    s.mass_scaling_dt = 0.0;  // a probe of the true critical step adds no mass
  }
  if (l.cycles > 0) s.time_control.end_cycle = s.cycle + l.cycles;
  if (l.end_time > 0.0) s.time_control.end_time = l.end_time;
}

}  // namespace mcdyna::solver
