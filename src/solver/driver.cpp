// The time loop over the model's blocks (block.hpp). One cycle, from t^n (forces known) to
// t^{n+1}, is two halves around the output of t^n:
//   choose dt^{n+1/2} -> velocities (free nodes, then the blocks: SPG parts, rigid bodies) ->
//   conditions (constraints, motions, walls) -> what the blocks take up from them ->
//   output at t^n -> positions -> forces of every block at t^{n+1} -> checks.
// run() wraps the two halves with the stop decisions, restart dumps, outputs and the phase
// clock.
#include "solver/driver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "solver/block.hpp"

namespace mcdyna::solver {

const char* PhaseTimes::name(int p) {
  static const char* kNames[kCount] = {"elements",
                                       "boundary conditions",
                                       "rigid bodies",
                                       "output",
                                       "other",
                                       "SPG neighbour search",
                                       "SPG shape functions",
                                       "SPG smoothing",
                                       "SPG stress",
                                       "SPG stabilisation",
                                       "SPG forces",
                                       "SPG bond failure",
                                       "SPG step estimate",
                                       "contact"};
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

// The phase clock over the blocks: each block's call charged to its phase.
class Phases {
 public:
  Phases(Blocks& blocks, PhaseTimes& times) : blocks_(blocks), clock_(times) {}
  template <class Call>
  void each(Call&& call) {
    for (const std::unique_ptr<Block>& b : blocks_) {
      call(*b);
      clock_.charge(b->phase());
    }
  }
  void charge(PhaseTimes::Phase p) { clock_.charge(p); }

 private:
  Blocks& blocks_;
  PhaseClock clock_;
};

// Forces at t^n from every block, and the critical step of them all.
ForceReport compute_forces(State& s, Phases& phases) {
  ForceReport r;
  s.nodes.force.setZero();
  phases.each([&](Block& b) { b.forces(s, r); });
  return r;
}

std::string controlling_name(const State& s, const ForceReport& r) {
  if (r.controlling_element >= 0) return element_name(s, r.controlling_element);
  if (r.controlling_particle >= 0)
    return particle_name(s, r.controlling_domain, r.controlling_particle);
  return "none";
}

// a = f / m and v += a dt for deformable nodes; returns the lowest node with a non-finite value.
Index free_velocity_update(State& s, double dt) {
  Nodes& nd = s.nodes;
  Index bad = std::numeric_limits<Index>::max();
#pragma omp parallel for schedule(static) reduction(min : bad) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n) {
    const auto i = static_cast<std::size_t>(n);
    if (nd.rigid_body[i] >= 0 || nd.smoothed[i]) continue;  // smoothed: spg::advance_velocities
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

// x^n -> x^{n+1} for the nodes that are not rigid.
void advance_free_positions(State& s, double dt) {
  Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n) {
    if (nd.rigid_body[static_cast<std::size_t>(n)] >= 0) continue;
    nd.position.col(n) += dt * nd.velocity.col(n);
  }
}

// The first half of a cycle: v^{n-1/2} -> v^{n+1/2} (the nodes by a = f / m, then the blocks
// that move their nodes themselves), then the conditions and what the blocks take up from them.
// Returns the lowest node with a non-finite velocity, or -1.
Index advance_velocities(State& s, Phases& phases, const StepTimes& t) {
  Index bad = free_velocity_update(s, t.mean);
  phases.charge(PhaseTimes::elements);
  phases.each([&](Block& b) {
    const Index n = b.advance_velocities(s, t);
    if (bad < 0) bad = n;
  });
  phases.each([&](Block& b) { b.constrain(s, t); });
  phases.each([&](Block& b) { b.after_constraints(s); });
  return bad;
}

// The second half: x^n -> x^{n+1}, t^{n+1}, and the forces there.
ForceReport advance_positions(State& s, Phases& phases, const StepTimes& t) {
  advance_free_positions(s, t.step);
  phases.charge(PhaseTimes::other);
  phases.each([&](Block& b) { b.advance_positions(s, t.step); });
  s.time += t.step;
  s.step = t.step;
  ++s.cycle;
  return compute_forces(s, phases);
}

double choose_step(const State& s, const ForceReport& r, bool first) {
  const TimeControl& tc = s.time_control;
  if (tc.fixed_step > 0.0) return tc.fixed_step;
  // Without deformable elements (rigid bodies only) DTINIT is the step.
  double dt = std::isfinite(r.critical_step) ? tc.scale_factor * r.critical_step
                                             : std::max(tc.initial_step, 0.0);
  if (first && tc.initial_step > 0.0) dt = std::min(dt, tc.initial_step);
  if (tc.max_step_curve >= 0)
    dt = std::min(dt, s.curves[static_cast<std::size_t>(tc.max_step_curve)](s.time));
  return dt;
}

}  // namespace

RunResult run(State& s, const RunHooks& hooks, const ResumePoint* resume) {
  RunResult result;
  const auto start = Clock::now();
  Blocks blocks = make_blocks(s);
  Phases phases(blocks, result.phases);
  long elements = 0, particles = 0;
  for (const std::unique_ptr<Block>& b : blocks) {
    elements += b->elements();
    particles += b->particles();
  }
  if (!resume) phases.each([&](Block& b) { b.initialise(s); });
  ForceReport pass;
  if (resume) {
    // The dump was taken at the top of a cycle: its forces and step estimate are in the state
    // and the resume point; computing them again would advance the stresses a second time.
    pass.critical_step = resume->critical_step;
    pass.controlling_element = resume->controlling_element;
    pass.controlling_domain = resume->controlling_domain;
    pass.controlling_particle = resume->controlling_particle;
    result.phases = resume->phases;
    result.element_cycles = resume->element_cycles;
    result.particle_cycles = resume->particle_cycles;
  } else {
    pass = compute_forces(s, phases);
  }
  s.critical_step = pass.critical_step;
  const double earlier_wall = resume ? resume->wall_seconds : 0.0;
  const double earlier_core = resume ? resume->core_seconds : 0.0;
  const int threads = omp_get_max_threads();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const long first_cycle = s.cycle;
  const double first_step = resume ? resume->first_step : choose_step(s, pass, true);
  // DTMIN: stop when the step falls below DTMIN x the first step; without it, a step below
  // 1e-6 x the first one is treated as a collapse.
  const double min_step =
      first_step * (s.time_control.min_step_factor > 0.0 ? s.time_control.min_step_factor : 1e-6);
  Eigen::Matrix3Xd velocity_before;
  for (;;) {
    const bool at_end = s.time >= s.time_control.end_time * (1.0 - 1e-12) ||
                        (s.time_control.end_cycle > 0 && s.cycle >= s.time_control.end_cycle);
    const bool interrupted = hooks.stop_requested && hooks.stop_requested();
    // A restart dump at the top of the cycle: everything the cycle starts from is in the state
    // and in `pass`, so a run continued from here repeats this cycle bit for bit.
    if (hooks.dump && hooks.dump_due && !at_end && (s.cycle != first_cycle || interrupted) &&
        hooks.dump_due(s, interrupted)) {
      phases.charge(PhaseTimes::other);
      const double seconds = elapsed();
      ResumePoint point{pass.critical_step,
                        pass.controlling_element,
                        pass.controlling_domain,
                        pass.controlling_particle,
                        first_step,
                        result.phases,
                        earlier_wall + seconds,
                        earlier_core + threads * seconds,
                        result.element_cycles,
                        result.particle_cycles};
      hooks.dump(s, point);
      phases.charge(PhaseTimes::output);
    }
    const double dt = s.cycle == 0 ? first_step : choose_step(s, pass, false);
    if (!at_end && !interrupted && !(dt > min_step)) {
      result.reason = StopReason::step_collapse;
      result.message = fmt::format(
          "time step {:.4e} fell below the minimum {:.4e} at t = {:.6e} (cycle {}); controlling "
          "element: {}",
          dt, min_step, s.time, s.cycle, controlling_name(s, pass));
    }
    const bool stop = at_end || interrupted || result.reason == StopReason::step_collapse;
    const double step = dt > 0.0 ? dt : min_step;  // a collapsed step still closes the cycle
    const StepTimes t{s.time, step, 0.5 * (s.step + step)};
    const bool write = stop || (hooks.output_due && hooks.output_due(s));
    if (write) velocity_before = s.nodes.velocity;
    const Index bad = advance_velocities(s, phases, t);
    if (bad >= 0 && result.reason == StopReason::end_time) {
      result.reason = StopReason::non_finite;
      result.message = fmt::format("non-finite velocity at node {} at t = {:.6e} (cycle {})",
                                   s.nodes.ids[static_cast<std::size_t>(bad)], s.time, s.cycle);
    }
    if (hooks.velocities_advanced && bad < 0) hooks.velocities_advanced(s, t);
    if (write || bad >= 0) {
      if (hooks.write) hooks.write(s, velocity_before, stop || bad >= 0);
      phases.charge(PhaseTimes::output);
    }
    if (bad >= 0 || stop) {
      if (interrupted && !at_end)
        result.reason = StopReason::interrupted;
      else if (at_end && result.reason == StopReason::end_time && s.time_control.end_cycle > 0 &&
               s.cycle >= s.time_control.end_cycle)
        result.reason = StopReason::end_cycle;
      break;
    }
    pass = advance_positions(s, phases, t);
    result.element_cycles += elements;
    result.particle_cycles += particles;
    if (!pass.failure.empty()) {
      result.reason = pass.inverted ? StopReason::inverted_element : StopReason::non_finite;
      result.message = fmt::format("{} at t = {:.6e} (cycle {})", pass.failure, s.time, s.cycle);
      if (hooks.write) hooks.write(s, s.nodes.velocity, true);
      break;
    }
    s.controlling_element = pass.controlling_element;
    s.controlling_domain = pass.controlling_domain;
    s.controlling_particle = pass.controlling_particle;
    s.critical_step = pass.critical_step;
    if (hooks.progress) hooks.progress(s);
  }
  // Finer phases (the SPG parts' neighbour search, shape functions, ...) out of the ones their
  // blocks were charged to.
  for (const std::unique_ptr<Block>& b : blocks)
    b->split_times(s, result.phases);
  const double seconds = elapsed();
  result.wall_seconds = earlier_wall + seconds;
  result.core_seconds = earlier_core + threads * seconds;
  return result;
}

}  // namespace mcdyna::solver
