// The time loop over the model's blocks (block.hpp). One cycle, from t^n (forces known) to
// t^{n+1}, is two halves around the output of t^n:
//   choose dt^{n+1/2} -> velocities (free nodes, then the blocks: SPG parts, rigid bodies) ->
//   conditions (constraints, motions, walls) -> what the blocks take up from them ->
//   output at t^n -> positions -> forces of every block at t^{n+1} -> checks.
// run() wraps the two halves with the stop decisions, restart dumps, outputs and the phase
// clock.
#include "solver/run/driver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "core/communicator.hpp"
#include "solver/block.hpp"
#include "solver/run/halo.hpp"

namespace mcdyna::solver {

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

// Forces at t^n from every block into `f`, and the critical step of them all.
// Over several processes only the nodes this process moves: the forces of the others are never
// read here (their owners integrate them).
ForceReport compute_forces(State& s, NodalForces& f, Phases& phases) {
  ForceReport r;
  if (s.ownership.moves.empty()) {
    f.force.setZero();
    if (f.rotations()) f.moment.setZero();
  } else {
    for (const Index n : s.ownership.moved_nodes) {
      f.force.col(n).setZero();
      if (f.rotations()) f.moment.col(n).setZero();
    }
  }
  phases.each([&](Block& b) { b.forces(s, f, r); });
  return r;
}

std::string controlling_name(const State& s, const ForceReport& r) {
  if (r.controlling_element >= 0) return element_name(s, r.controlling_element);
  if (r.controlling_particle >= 0)
    return particle_name(s, r.controlling_domain, r.controlling_particle);
  return "none";
}

// w += M / I dt for a node with rotations (a shell node). Its rotary inertia grows with any
// DT2MS mass in proportion, so the rotations stay off the step as the translations slow down.
bool rotation_update(Nodes& nd, const Eigen::Matrix3Xd& moment, Index n, double dt) {
  const auto i = static_cast<std::size_t>(n);
  const double inertia = nd.rotary_inertia[i] * (1.0 + nd.added_mass[i] / nd.mass[i]);
  nd.previous_angular_velocity.col(n) = nd.angular_velocity.col(n);
  nd.angular_velocity.col(n) += (dt / inertia) * moment.col(n);
  return std::isfinite(nd.angular_velocity.col(n).sum());
}

// a = f / m and v += a dt for deformable nodes (and w += M / I dt where they rotate); returns
// the lowest node with a non-finite value.
Index free_velocity_update(State& s, const NodalForces& f, double dt) {
  Nodes& nd = s.nodes;
  const bool rotations = nd.rotates();
  Index bad = std::numeric_limits<Index>::max();
  const std::size_t count = s.ownership.moved_count(nd.count());  // another process moves the rest
#pragma omp parallel for schedule(static) reduction(min : bad) if (count > 2048)
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = s.ownership.moved_node(k);
    const auto i = static_cast<std::size_t>(n);
    if (nd.rigid_body[i] >= 0 || nd.smoothed[i]) continue;  // smoothed: spg::advance_velocities
    const double m = nd.mass[i] + nd.added_mass[i];
    if (!(m > 0.0)) continue;
    for (int k = 0; k < 3; ++k) {
      const double a = f.force(k, n) / m;
      nd.acceleration(k, n) = a;
      nd.velocity(k, n) += a * dt;
    }
    if (!std::isfinite(nd.velocity(0, n) + nd.velocity(1, n) + nd.velocity(2, n))) bad = n;
    if (rotations && nd.rotary_inertia[i] > 0.0 && !rotation_update(nd, f.moment, n, dt)) bad = n;
  }
  return bad == std::numeric_limits<Index>::max() ? -1 : bad;
}

// x^n -> x^{n+1} for the nodes that are not rigid.
void advance_free_positions(State& s, double dt) {
  Nodes& nd = s.nodes;
  const std::size_t count = s.ownership.moved_count(nd.count());
#pragma omp parallel for schedule(static) if (count > 2048)
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = s.ownership.moved_node(k);
    if (nd.rigid_body[static_cast<std::size_t>(n)] >= 0) continue;
    nd.position.col(n) += dt * nd.velocity.col(n);
  }
}

// The first half of a cycle: v^{n-1/2} -> v^{n+1/2} (the nodes by a = f / m, then the blocks
// that move their nodes themselves), then the conditions and what the blocks take up from them.
// Returns the lowest node with a non-finite velocity, or -1.
Index advance_velocities(State& s, const NodalForces& f, Phases& phases, const StepTimes& t) {
  Index bad = free_velocity_update(s, f, t.mean);
  phases.charge(PhaseTimes::elements);
  phases.each([&](Block& b) {
    const Index n = b.advance_velocities(s, f, t);
    if (bad < 0) bad = n;
  });
  phases.each([&](Block& b) { b.constrain(s, t); });
  phases.each([&](Block& b) { b.after_constraints(s); });
  return bad;
}

// The second half: x^n -> x^{n+1}, t^{n+1}, and the forces there. Over several processes the
// ghost nodes' new positions and velocities arrive before the forces.
ForceReport advance_positions(State& s, NodalForces& f, Phases& phases, const StepTimes& t,
                              parallel::Halo* halo) {
  advance_free_positions(s, t.step);
  phases.charge(PhaseTimes::other);
  phases.each([&](Block& b) { b.advance_positions(s, t.step); });
  s.time += t.step;
  s.step = t.step;
  ++s.cycle;
  if (halo) {
    halo->exchange_motion(s);
    phases.charge(PhaseTimes::exchange);
  }
  return compute_forces(s, f, phases);
}

// Over several processes each computed the step estimate and failures of its own share: all
// take the smallest step (an element before a particle, then the lowest index, as one process
// picks) and the failure the lowest process met.
void agree_on_forces(ForceReport& r, const core::Communicator& comm) {
  const std::vector<double> mine = {r.critical_step,
                                    static_cast<double>(r.controlling_element),
                                    static_cast<double>(r.controlling_domain),
                                    static_cast<double>(r.controlling_particle),
                                    r.failure.empty() ? 0.0 : 1.0,
                                    r.inverted ? 1.0 : 0.0};
  const std::vector<double> all = comm.all_gather(mine);
  auto key = [&](int p) {
    const double* v = &all[static_cast<std::size_t>(p) * mine.size()];
    const double element = v[1] >= 0.0 ? v[1] : std::numeric_limits<double>::infinity();
    return std::array<double, 4>{v[0], element, v[2], v[3]};
  };
  int best = 0, failed = -1;
  for (int p = 0; p < comm.size(); ++p) {
    if (key(p) < key(best)) best = p;
    if (failed < 0 && all[static_cast<std::size_t>(p) * mine.size() + 4] != 0.0) failed = p;
  }
  const double* b = &all[static_cast<std::size_t>(best) * mine.size()];
  r.critical_step = b[0];
  r.controlling_element = static_cast<Index>(b[1]);
  r.controlling_domain = static_cast<std::size_t>(b[2]);
  r.controlling_particle = static_cast<Index>(b[3]);
  if (failed >= 0) {
    comm.broadcast(r.failure, failed);
    r.inverted = all[static_cast<std::size_t>(failed) * mine.size() + 5] != 0.0;
  }
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

namespace {

// The wrapper around the cycle: where the run started, the stop decisions, restart dumps and
// outputs, the phase clock and the timing. cycle() is the time loop's body.
class Loop {
 public:
  Loop(State& s, const RunHooks& hooks, const ResumePoint* resume, RunResult& result)
      : s_(s),
        hooks_(hooks),
        result_(result),
        start_(Clock::now()),
        blocks_(s.blocks),
        phases_(blocks_, result.phases),
        threads_(omp_get_max_threads()),
        comm_(core::Communicator::world()) {
    for (const std::unique_ptr<Block>& b : blocks_) {
      elements_ += b->elements();
      particles_ += b->particles();
    }
    if (comm_.size() > 1) decompose(resume != nullptr);
    if (resume) {
      // The dump was taken at the top of a cycle: its forces and step estimate are in the
      // resume point; computing them again would advance the stresses again.
      forces_ = resume->forces;
      pass_.critical_step = resume->critical_step;
      pass_.controlling_element = resume->controlling_element;
      pass_.controlling_domain = resume->controlling_domain;
      pass_.controlling_particle = resume->controlling_particle;
      result_.phases = resume->phases;
      result_.element_cycles = resume->element_cycles;
      result_.particle_cycles = resume->particle_cycles;
      earlier_wall_ = resume->wall_seconds;
      earlier_core_ = resume->core_seconds;
    } else {
      forces_ = NodalForces(s_.nodes.count(), s_.nodes.rotates());
      phases_.each([&](Block& b) { b.initialise(s_); });
    }
    if (halo_) {
      for (const std::unique_ptr<Block>& b : blocks_)
        b->distribute(s_);
      follow_ownership(true);
      const std::string summary = halo_->summary();
      if (hooks_.decomposed && comm_.rank() == 0) hooks_.decomposed(summary);
    }
    if (!resume) {
      pass_ = compute_forces(s_, forces_, phases_);
      if (halo_) {
        follow_ownership(false);
        agree_on_forces(pass_, comm_);
      }
    }
    s_.critical_step = pass_.critical_step;
    first_cycle_ = s_.cycle;
    first_step_ = resume ? resume->first_step : choose_step(s_, pass_, true);
    // DTMIN: stop when the step falls below DTMIN x the first step; without it, a step below
    // 1e-6 x the first one is treated as a collapse.
    const double factor = s_.time_control.min_step_factor;
    min_step_ = first_step_ * (factor > 0.0 ? factor : 1e-6);
  }

  // One cycle, t^n -> t^{n+1}; false once the run has stopped.
  bool cycle() {
    const bool at_end = reached_end();
    bool interrupted = hooks_.stop_requested && hooks_.stop_requested();
    SenseSwitches sw = hooks_.sense_switches ? hooks_.sense_switches() : SenseSwitches{};
    bool output_due = hooks_.output_due && hooks_.output_due(s_);
    state_due_ = output_due && hooks_.state_due && hooks_.state_due(s_);
    if (halo_) agree(interrupted, output_due, state_due_, sw);
    act_on(sw, interrupted, output_due);
    dump_if_due(at_end, interrupted, sw.stop || sw.dump);
    const StepTimes t = next_step(at_end || interrupted);
    const bool stop = at_end || interrupted || result_.reason == StopReason::step_collapse;
    const bool write = stop || output_due;
    if (write) velocity_before_ = s_.nodes.velocity;
    Index bad = advance_velocities(s_, forces_, phases_, t);
    if (halo_) bad = agree(bad);
    if (bad >= 0) stop_on_non_finite_velocity(bad);
    if (hooks_.velocities_advanced && bad < 0) hooks_.velocities_advanced(s_, forces_, t);
    if (write || bad >= 0) write_state(velocity_before_, stop || bad >= 0);
    if (bad >= 0 || stop) return close(at_end, interrupted);
    pass_ = advance_positions(s_, forces_, phases_, t, halo_ ? &*halo_ : nullptr);
    if (halo_) {
      follow_ownership(false);
      agree_on_forces(pass_, comm_);
      phases_.charge(PhaseTimes::exchange);
    }
    result_.element_cycles += elements_;
    result_.particle_cycles += particles_;
    if (!pass_.failure.empty()) return stop_on_failure();
    s_.controlling_element = pass_.controlling_element;
    s_.controlling_domain = pass_.controlling_domain;
    s_.controlling_particle = pass_.controlling_particle;
    s_.critical_step = pass_.critical_step;
    if (hooks_.progress) hooks_.progress(s_);
    return true;
  }

  // Finer phases (the SPG parts' neighbour search, shape functions, ...) out of the ones their
  // blocks were charged to, and the run's wall and core time.
  void finish() {
    for (const std::unique_ptr<Block>& b : blocks_)
      b->split_times(s_, result_.phases);
    const double seconds = elapsed();
    result_.wall_seconds = earlier_wall_ + seconds;
    result_.core_seconds = earlier_core_ + threads_ * seconds;
  }

 private:
  // Over several processes: the decomposition and this process's halo (halo.hpp).
  // A restart takes the owners its dumps were written with: the particles were owned again at
  // kernel renewals, and each dump holds the kernel rows its process read (spg/distribution.hpp).
  void decompose(bool resume) {
    std::vector<std::uint8_t> replicated(static_cast<std::size_t>(s_.nodes.count()), 0);
    for (const std::unique_ptr<Block>& b : blocks_)
      b->mark_replicated(s_, replicated);
    parallel::Decomposition d = parallel::decompose(s_, comm_.size());
    if (resume && s_.ownership.owner.size() == d.owner.size()) d.owner = s_.ownership.owner;
    halo_.emplace(s_, d, std::move(replicated), comm_);
  }

  // The halo again when the owners or the SPG rows changed (a renewal re-owns particles,
  // spg/distribution.hpp), or `always`.
  void follow_ownership(bool always) {
    if (!always && halo_generation_ == s_.ownership.generation) return;
    halo_->rebuild(s_);
    halo_generation_ = s_.ownership.generation;
  }

  // The owned values of the blocks that split their entities: to process 0, which writes the
  // outputs, or to every process before a dump (each dump holds the whole state).
  void synchronise_blocks(Block::Gather what) {
    for (const std::unique_ptr<Block>& b : blocks_)
      b->synchronise(s_, what);
  }

  // Every process stops and writes when any one is asked to (a signal reaches the processes
  // of an mpirun at different cycles); process 0 alone knows when an output is due and reads
  // the d3kil file. One collective per cycle carries all of it.
  void agree(bool& interrupted, bool& output_due, bool& state_due, SenseSwitches& sw) {
    const unsigned flags =
        comm_.bitwise_or((interrupted ? 1U : 0U) | (output_due ? 2U : 0U) | (state_due ? 4U : 0U) |
                         (sw.stop ? 8U : 0U) | (sw.status ? 16U : 0U) | (sw.dump ? 32U : 0U) |
                         (sw.state ? 64U : 0U));
    interrupted = (flags & 1U) != 0;
    output_due = (flags & 2U) != 0;
    state_due = (flags & 4U) != 0;
    sw = SenseSwitches{(flags & 8U) != 0, (flags & 16U) != 0, (flags & 32U) != 0,
                       (flags & 64U) != 0};
  }

  // sw1 stops the run (its restart dump follows), sw2 reports where it stands, sw4 makes this
  // cycle's output a d3plot state.
  void act_on(const SenseSwitches& sw, bool& interrupted, bool& output_due) {
    if (sw.stop) interrupted = true;
    if (sw.status && hooks_.status) hooks_.status(s_);
    if (sw.state && hooks_.request_state) {
      hooks_.request_state();
      output_due = state_due_ = true;
    }
  }

  // The lowest node with a non-finite velocity on any process.
  Index agree(Index bad) {
    const std::int64_t lowest =
        comm_.min(bad >= 0 ? std::int64_t{bad} : std::numeric_limits<std::int64_t>::max());
    return lowest == std::numeric_limits<std::int64_t>::max() ? -1 : static_cast<Index>(lowest);
  }

  [[nodiscard]] double elapsed() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

  [[nodiscard]] bool reached_end() const {
    const TimeControl& tc = s_.time_control;
    return s_.time >= tc.end_time * (1.0 - 1e-12) || (tc.end_cycle > 0 && s_.cycle >= tc.end_cycle);
  }

  // A restart dump at the top of the cycle: everything the cycle starts from is in the state
  // and in pass_, so a run continued from here repeats this cycle bit for bit.
  void dump_if_due(bool at_end, bool interrupted, bool requested) {
    if (!hooks_.dump || !hooks_.dump_due || at_end ||
        (s_.cycle == first_cycle_ && !interrupted && !requested) ||
        !hooks_.dump_due(s_, interrupted, requested))
      return;
    phases_.charge(PhaseTimes::other);
    if (halo_) synchronise_blocks(Block::Gather::dump);
    const double seconds = elapsed();
    const ResumePoint point{forces_,
                            pass_.critical_step,
                            pass_.controlling_element,
                            pass_.controlling_domain,
                            pass_.controlling_particle,
                            first_step_,
                            result_.phases,
                            earlier_wall_ + seconds,
                            earlier_core_ + threads_ * seconds,
                            result_.element_cycles,
                            result_.particle_cycles};
    hooks_.dump(s_, point);
    phases_.charge(PhaseTimes::output);
  }

  // The cycle's times; a step below the minimum stops the run (unless it stops anyway) and
  // still closes the cycle with the minimum.
  StepTimes next_step(bool stopping) {
    const double dt = s_.cycle == 0 ? first_step_ : choose_step(s_, pass_, false);
    if (!stopping && !(dt > min_step_)) {
      result_.reason = StopReason::step_collapse;
      result_.message = fmt::format(
          "time step {:.4e} fell below the minimum {:.4e} at t = {:.6e} (cycle {}); controlling "
          "element: {}",
          dt, min_step_, s_.time, s_.cycle, controlling_name(s_, pass_));
    }
    const double step = dt > 0.0 ? dt : min_step_;
    return StepTimes{s_.time, step, 0.5 * (s_.step + step)};
  }

  void stop_on_non_finite_velocity(Index node) {
    if (result_.reason != StopReason::end_time) return;
    result_.reason = StopReason::non_finite;
    result_.message = fmt::format("non-finite velocity at node {} at t = {:.6e} (cycle {})",
                                  s_.nodes.ids[static_cast<std::size_t>(node)], s_.time, s_.cycle);
  }

  void write_state(Eigen::Matrix3Xd& previous, bool final) {
    // The last write of a run completes every output, d3plot included.
    if (halo_) {
      synchronise_blocks(final || state_due_ ? Block::Gather::state : Block::Gather::histories);
      halo_->gather_for_output(s_, previous, final || state_due_);
    }
    if (hooks_.write) hooks_.write(s_, previous, final);
    phases_.charge(PhaseTimes::output);
  }

  bool close(bool at_end, bool interrupted) {
    if (interrupted && !at_end)
      result_.reason = StopReason::interrupted;
    else if (at_end && result_.reason == StopReason::end_time && s_.time_control.end_cycle > 0 &&
             s_.cycle >= s_.time_control.end_cycle)
      result_.reason = StopReason::end_cycle;
    return false;
  }

  // An inverted or non-finite element or particle at t^{n+1}: the state is written as it is.
  bool stop_on_failure() {
    result_.reason = pass_.inverted ? StopReason::inverted_element : StopReason::non_finite;
    result_.message = fmt::format("{} at t = {:.6e} (cycle {})", pass_.failure, s_.time, s_.cycle);
    write_state(s_.nodes.velocity, true);
    return false;
  }

  State& s_;
  const RunHooks& hooks_;
  RunResult& result_;
  Clock::time_point start_;
  Blocks& blocks_;
  Phases phases_;
  int threads_;
  core::Communicator comm_;
  std::optional<parallel::Halo> halo_;  ///< over several processes only
  long halo_generation_ = -1;           ///< s.ownership.generation the halo was built for
  long elements_ = 0, particles_ = 0;
  ForceReport pass_;
  NodalForces forces_;      ///< at t^n: the step context the blocks' phases share
  bool state_due_ = false;  ///< the output of this cycle includes a d3plot state
  double earlier_wall_ = 0.0, earlier_core_ = 0.0;
  long first_cycle_ = 0;
  double first_step_ = 0.0, min_step_ = 0.0;
  Eigen::Matrix3Xd velocity_before_;
};

}  // namespace

RunResult run(State& s, const RunHooks& hooks, const ResumePoint* resume) {
  RunResult result;
  Loop loop(s, hooks, resume, result);
  while (loop.cycle()) {
  }
  loop.finish();
  return result;
}

}  // namespace mcdyna::solver
