// The time loop. One cycle, from t^n (forces known) to t^{n+1}:
//   choose dt^{n+1/2} -> free velocity update -> rigid bodies -> nodal constraints and motions ->
//   rigid walls -> output at t^n -> positions -> element pass at t^{n+1} -> checks.
#include "solver/driver.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "solver/fe/solid_elements.hpp"
#include "solver/loads/loads.hpp"
#include "solver/rigid/rigid_bodies.hpp"

namespace mcdyna::solver {

const char* PhaseTimes::name(int p) {
  static const char* kNames[kCount] = {"elements", "boundary conditions", "rigid bodies", "output",
                                       "other"};
  return kNames[p];
}

namespace {

using Clock = std::chrono::steady_clock;

class PhaseClock {
 public:
  explicit PhaseClock(PhaseTimes& t) : times_(t), last_(Clock::now()) {}
  void charge(PhaseTimes::Phase p) {
    const auto now = Clock::now();
    times_.seconds[p] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  PhaseTimes& times_;
  Clock::time_point last_;
};

std::string element_name(const State& s, Index e) {
  const auto i = static_cast<std::size_t>(e);
  return fmt::format("solid element {} (part {})", s.solids.ids[i],
                     s.parts[static_cast<std::size_t>(s.solids.part[i])].id);
}

// Nodal added mass from the elements' added mass (gather, fixed order).
void refresh_added_mass(State& s) {
  Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static)
  for (Index n = 0; n < nd.count(); ++n) {
    double sum = 0.0;
    for (Index k = nd.corner_offsets[static_cast<std::size_t>(n)];
         k < nd.corner_offsets[static_cast<std::size_t>(n) + 1]; ++k)
      sum += s.solids
                 .added_mass[static_cast<std::size_t>(nd.corners[static_cast<std::size_t>(k)] / 8)];
    nd.added_mass[static_cast<std::size_t>(n)] = sum / 8.0;
  }
}

// Element pass at the current positions: forces f^n and the critical step.
ElementPassResult compute_forces(State& s) {
  s.nodes.force.setZero();
  const ElementPassResult r = solid_element_pass(
      s, ElementPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
  gather_solid_forces(s);
  if (r.mass_changed) refresh_added_mass(s);
  return r;
}

// a = f / m and v += a dt for deformable nodes; returns the lowest node with a non-finite value.
Index free_velocity_update(State& s, double dt) {
  Nodes& nd = s.nodes;
  Index bad = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static) reduction(min : bad) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n) {
    const auto i = static_cast<std::size_t>(n);
    if (nd.rigid_body[i] >= 0) continue;
    const double m = nd.mass[i] + nd.added_mass[i];
    if (!(m > 0.0)) continue;
    for (int k = 0; k < 3; ++k) {
      const double a = nd.force(k, n) / m;
      nd.acceleration(k, n) = a;
      nd.velocity(k, n) += a * dt;
    }
    if (!std::isfinite(nd.velocity(0, n) + nd.velocity(1, n) + nd.velocity(2, n))) bad = n;
  }
  return bad == std::numeric_limits<Index>::max() ? -1 : bad;
}

void advance_positions(State& s, double dt) {
  Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n) {
    if (nd.rigid_body[static_cast<std::size_t>(n)] >= 0) continue;
    nd.position.col(n) += dt * nd.velocity.col(n);
  }
  place_rigid_nodes(s, dt);
}

double choose_step(const State& s, const ElementPassResult& r, bool first) {
  const TimeControl& tc = s.time_control;
  // Without deformable elements (rigid bodies only) DTINIT is the step.
  double dt = std::isfinite(r.critical_step) ? tc.scale_factor * r.critical_step
                                             : std::max(tc.initial_step, 0.0);
  if (first && tc.initial_step > 0.0) dt = std::min(dt, tc.initial_step);
  if (tc.max_step_curve >= 0)
    dt = std::min(dt, s.curves[static_cast<std::size_t>(tc.max_step_curve)](s.time));
  return dt;
}

}  // namespace

RunResult run(State& s, const RunHooks& hooks) {
  RunResult result;
  const auto start = Clock::now();
  PhaseClock clock(result.phases);
  const long elements = s.solids.count();
  ElementPassResult pass = compute_forces(s);
  clock.charge(PhaseTimes::elements);
  const double first_step = choose_step(s, pass, true);
  // DTMIN: stop when the step falls below DTMIN x the first step; without it, a step below
  // 1e-6 x the first one is treated as a collapse.
  const double min_step =
      first_step * (s.time_control.min_step_factor > 0.0 ? s.time_control.min_step_factor : 1e-6);
  Eigen::Matrix3Xd velocity_before;
  for (;;) {
    const double dt = s.cycle == 0 ? first_step : choose_step(s, pass, false);
    const bool at_end = s.time >= s.time_control.end_time * (1.0 - 1e-12) ||
                        (s.time_control.end_cycle > 0 && s.cycle >= s.time_control.end_cycle);
    const bool interrupted = hooks.stop_requested && hooks.stop_requested();
    if (!at_end && !interrupted && !(dt > min_step)) {
      result.reason = StopReason::step_collapse;
      result.message = fmt::format(
          "time step {:.4e} fell below the minimum {:.4e} at t = {:.6e} (cycle {}); controlling "
          "element: {}",
          dt, min_step, s.time, s.cycle,
          pass.controlling >= 0 ? element_name(s, pass.controlling) : "none");
    }
    const bool stop = at_end || interrupted || result.reason == StopReason::step_collapse;
    const double step = dt > 0.0 ? dt : min_step;  // a collapsed step still closes the cycle
    const StepTimes t{s.time, step, 0.5 * (s.step + step)};
    const bool write = stop || (hooks.output_due && hooks.output_due(s));
    if (write) velocity_before = s.nodes.velocity;
    const Index bad = free_velocity_update(s, t.mean);
    clock.charge(PhaseTimes::elements);
    advance_rigid_bodies(s, t);
    clock.charge(PhaseTimes::rigid);
    apply_nodal_constraints(s, t);
    apply_nodal_motions(s, t);
    apply_rigid_walls(s, t);
    clock.charge(PhaseTimes::boundary);
    if (bad >= 0 && result.reason == StopReason::end_time) {
      result.reason = StopReason::non_finite;
      result.message = fmt::format("non-finite velocity at node {} at t = {:.6e} (cycle {})",
                                   s.nodes.ids[static_cast<std::size_t>(bad)], s.time, s.cycle);
    }
    if (write || bad >= 0) {
      if (hooks.write) hooks.write(s, velocity_before, stop || bad >= 0);
      clock.charge(PhaseTimes::output);
    }
    if (bad >= 0 || stop) {
      if (interrupted && !at_end)
        result.reason = StopReason::interrupted;
      else if (at_end && result.reason == StopReason::end_time && s.time_control.end_cycle > 0 &&
               s.cycle >= s.time_control.end_cycle)
        result.reason = StopReason::end_cycle;
      break;
    }
    advance_positions(s, t.step);
    s.time += t.step;
    s.step = t.step;
    ++s.cycle;
    clock.charge(PhaseTimes::other);
    pass = compute_forces(s);
    result.element_cycles += elements;
    clock.charge(PhaseTimes::elements);
    if (pass.inverted >= 0 || pass.non_finite >= 0) {
      result.reason = pass.inverted >= 0 ? StopReason::inverted_element : StopReason::non_finite;
      result.message =
          pass.inverted >= 0
              ? fmt::format("negative volume in {} at t = {:.6e} (cycle {})",
                            element_name(s, pass.inverted), s.time, s.cycle)
              : fmt::format("non-finite stress or wave speed in {} at t = {:.6e} (cycle {})",
                            element_name(s, pass.non_finite), s.time, s.cycle);
      if (hooks.write) hooks.write(s, s.nodes.velocity, true);
      break;
    }
    s.controlling_element = pass.controlling;
    if (hooks.progress) hooks.progress(s);
  }
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace mcdyna::solver
