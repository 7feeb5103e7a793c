// The time loop. One cycle, from t^n (forces known) to t^{n+1}:
//   choose dt^{n+1/2} -> free velocity update -> rigid bodies -> nodal constraints and motions ->
//   rigid walls -> output at t^n -> positions -> element pass at t^{n+1} -> checks.
#include "solver/driver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "solver/contact/contact.hpp"
#include "solver/fe/solid_elements.hpp"
#include "solver/loads/loads.hpp"
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/spg/spg_solver.hpp"

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

std::string particle_name(const State& s, std::size_t domain, Index particle) {
  const spg::Domain& d = s.spg[domain];
  return fmt::format(
      "SPG particle at node {} (part {})",
      s.nodes.ids[static_cast<std::size_t>(d.nodes[static_cast<std::size_t>(particle)])],
      s.parts[static_cast<std::size_t>(d.part)].id);
}

// Forces at t^n from the element and particle passes, and the critical step of both.
struct ForcePass {
  ElementPassResult elements;
  double critical_step = std::numeric_limits<double>::infinity();
  Index controlling_element = -1;
  std::size_t controlling_domain = 0;
  Index controlling_particle = -1;
  std::string failure;  ///< inverted or non-finite element/particle, named
  bool inverted = false;
};

ForcePass compute_forces(State& s) {
  ForcePass r;
  s.nodes.force.setZero();
  r.elements = solid_element_pass(
      s, ElementPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
  gather_solid_forces(s);
  if (r.elements.mass_changed) refresh_added_mass(s);
  r.critical_step = r.elements.critical_step;
  r.controlling_element = r.elements.controlling;
  if (r.elements.inverted >= 0) {
    r.inverted = true;
    r.failure = "negative volume in " + element_name(s, r.elements.inverted);
  } else if (r.elements.non_finite >= 0) {
    r.failure = "non-finite stress or wave speed in " + element_name(s, r.elements.non_finite);
  }
  for (std::size_t k = 0; k < s.spg.size(); ++k) {
    const spg::ParticlePassResult p = spg::particle_pass(s, s.spg[k], s.step);
    if (p.critical_step < r.critical_step) {
      r.critical_step = p.critical_step;
      r.controlling_element = -1;
      r.controlling_domain = k;
      r.controlling_particle = p.controlling;
    }
    if (r.failure.empty() && p.inverted >= 0) {
      r.inverted = true;
      r.failure = "non-positive Jacobian or volume at " + particle_name(s, k, p.inverted);
    } else if (r.failure.empty() && p.non_finite >= 0) {
      r.failure = "non-finite stress or wave speed at " + particle_name(s, k, p.non_finite);
    }
  }
  apply_body_loads(s);
  contact::contact_pass(s);  // after the internal forces: SPG particles and rigid nodes included
  return r;
}

std::string controlling_name(const State& s, const ForcePass& r) {
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

void advance_positions(State& s, double dt) {
  Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n) {
    if (nd.rigid_body[static_cast<std::size_t>(n)] >= 0) continue;
    nd.position.col(n) += dt * nd.velocity.col(n);
  }
  place_rigid_nodes(s, dt);
}

double choose_step(const State& s, const ForcePass& r, bool first) {
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
  PhaseClock clock(result.phases);
  const long elements = s.solids.count();
  long particles = 0;
  for (spg::Domain& d : s.spg) {
    if (d.renewals == 0 && !resume) spg::initialise(s, d);
    particles += d.count();
  }
  ForcePass pass;
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
    pass = compute_forces(s);
    clock.charge(PhaseTimes::elements);
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
      clock.charge(PhaseTimes::other);
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
      clock.charge(PhaseTimes::output);
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
    Index bad = free_velocity_update(s, t.mean);
    for (spg::Domain& d : s.spg) {
      const Index b = spg::advance_velocities(s, d, t.mean);
      if (bad < 0) bad = b;
    }
    clock.charge(PhaseTimes::elements);
    advance_rigid_bodies(s, t);
    clock.charge(PhaseTimes::rigid);
    apply_nodal_constraints(s, t);
    apply_nodal_motions(s, t);
    apply_rigid_walls(s, t);
    for (spg::Domain& d : s.spg)
      spg::absorb_constraints(s, d);
    clock.charge(PhaseTimes::boundary);
    if (bad >= 0 && result.reason == StopReason::end_time) {
      result.reason = StopReason::non_finite;
      result.message = fmt::format("non-finite velocity at node {} at t = {:.6e} (cycle {})",
                                   s.nodes.ids[static_cast<std::size_t>(bad)], s.time, s.cycle);
    }
    if (hooks.velocities_advanced && bad < 0) hooks.velocities_advanced(s, t);
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
    result.particle_cycles += particles;
    clock.charge(PhaseTimes::elements);
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
  // The SPG work ran inside the element phase; show it split (neighbour search, shape
  // functions, smoothing, stress, stabilisation, forces, bond failure, step estimate).
  for (const spg::Domain& d : s.spg) {
    constexpr int kSplit = PhaseTimes::spg_step_estimate - PhaseTimes::spg_neighbours + 1;
    const double split[kSplit] = {d.times.neighbours, d.times.shape_functions, d.times.smoothing,
                                  d.times.stress,     d.times.stabilization,   d.times.force,
                                  d.times.bonds,      d.times.step_estimate};
    for (int k = 0; k < kSplit; ++k) {
      result.phases.seconds[PhaseTimes::spg_neighbours + k] += split[k];
      result.phases.seconds[PhaseTimes::elements] -= split[k];
    }
  }
  for (const contact::Interface& c : s.contacts) {
    result.phases.seconds[PhaseTimes::contact] += c.seconds;
    result.phases.seconds[PhaseTimes::elements] -= c.seconds;
  }
  const double seconds = elapsed();
  result.wall_seconds = earlier_wall + seconds;
  result.core_seconds = earlier_core + threads * seconds;
  return result;
}

}  // namespace mcdyna::solver
