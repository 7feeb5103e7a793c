#include "io/inertia.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/block.hpp"
#include "solver/energy.hpp"
#include "solver/material/constitutive.hpp"

namespace mcdyna::io {

namespace {

/// The fastest node driven by a prescribed motion: the nodes of rigid bodies that carry one and
/// the nodes of *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET.
double driven_speed(const solver::State& s) {
  double fastest = 0.0;
  auto take = [&](solver::Index n) { fastest = std::max(fastest, s.nodes.velocity.col(n).norm()); };
  for (const solver::RigidBody& body : s.rigid_bodies)
    if (!body.motions.empty())
      for (solver::Index n : body.nodes)
        take(n);
  std::vector<std::uint8_t> held(static_cast<std::size_t>(s.nodes.count()), 0);
  for (const std::unique_ptr<solver::Block>& b : s.blocks)
    b->mark_held(held);
  for (solver::Index n = 0; n < s.nodes.count(); ++n)
    if (held[static_cast<std::size_t>(n)] & 8U) take(n);  // a prescribed motion's direction
  return fastest;
}

}  // namespace

InertiaVerdict judge_inertia(const InertiaFigures& f) {
  InertiaVerdict v;
  v.quasi_static_speeds = f.tool_speed > 0.0 && f.wave_speed > 0.0 && !f.moving_at_start &&
                          f.tool_speed < kQuasiStaticMach * f.wave_speed;
  if (!v.quasi_static_speeds) return v;
  if (f.largest_kinetic_over_internal > kKineticShare)
    v.reasons.push_back(fmt::format("their largest KE/IE is {:.3f} (above {:g})",
                                    f.largest_kinetic_over_internal, kKineticShare));
  if (f.inertia_number > kInertiaNumber)
    v.reasons.push_back(
        fmt::format("rho v^2 / yield of part {} at the tool's speed is {:.3f} (above {:g})",
                    f.inertia_part, f.inertia_number, kInertiaNumber));
  return v;
}

void InertiaRecord::add(const solver::State& s, const Eigen::Matrix3Xd& previous) {
  const std::vector<solver::PartSummary> parts = solver::part_summaries(s, previous);
  Sample sample{.time = s.time, .tool_speed = driven_speed(s)};
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (s.parts[p].rigid_body >= 0) continue;
    deformable_ = true;
    sample.kinetic += parts[p].kinetic;
    sample.internal += parts[p].internal;
    sample.added_mass += parts[p].added_mass;
  }
  if (samples_.empty()) {
    // A restart's first sample is not the start: only cycle 0 tells an initial velocity.
    moving_at_start_ = s.cycle == 0 && sample.kinetic > 0.0;
    restarted_ = s.cycle != 0;
    first_time_ = s.time;
    deformable_mass_ = 0.0;
    for (solver::Index n = 0; n < s.nodes.count(); ++n)
      if (s.nodes.rigid_body[static_cast<std::size_t>(n)] < 0)
        deformable_mass_ += s.nodes.mass[static_cast<std::size_t>(n)];
  }
  samples_.push_back(sample);
}

InertiaFigures InertiaRecord::figures(const solver::State& s) const {
  InertiaFigures f;
  f.moving_at_start = moving_at_start_;
  double top = 0.0;
  for (const Sample& x : samples_) {
    top = std::max(top, x.internal);
    f.tool_speed = std::max(f.tool_speed, x.tool_speed);
  }
  for (const Sample& x : samples_)
    if (top > 0.0 && x.internal >= kInternalFloor * top)
      f.largest_kinetic_over_internal =
          std::max(f.largest_kinetic_over_internal, x.kinetic / x.internal);
  f.wave_speed = std::numeric_limits<double>::infinity();
  for (const solver::PartInfo& part : s.parts) {
    if (part.rigid_body >= 0 || part.material < 0) continue;
    const solver::Material& m = s.materials[static_cast<std::size_t>(part.material)];
    f.wave_speed = std::min(f.wave_speed, std::sqrt(solver::wave_speed_squared(m, 1.0)));
    if (m.initial_yield() > 0.0) {
      const double number = m.density * f.tool_speed * f.tool_speed / m.initial_yield();
      if (number > f.inertia_number) {
        f.inertia_number = number;
        f.inertia_part = part.id;
      }
    }
  }
  if (f.wave_speed == std::numeric_limits<double>::infinity()) f.wave_speed = 0.0;
  return f;
}

namespace {

/// The warning line for a verdict with reasons, empty without.
std::string warning_text(const InertiaVerdict& verdict) {
  if (verdict.reasons.empty()) return {};
  std::string text =
      "  warning: the run looks quasi-static by its speeds but the deformable parts' inertia is "
      "not small:";
  for (std::size_t k = 0; k < verdict.reasons.size(); ++k)
    text += fmt::format("{} {}", k == 0 ? "" : ";", verdict.reasons[k]);
  return text +
         ". A time- or mass-scaled process answers to its speeds here (manual/migration.md, "
         "\"Time and mass scaling\"); an impact or a dynamic event may ignore this.\n";
}

}  // namespace

std::string InertiaRecord::warning(const solver::State& s) const {
  if (samples_.empty() || !deformable_) return {};
  return warning_text(judge_inertia(figures(s)));
}

void InertiaRecord::print(std::ostream& out, const solver::State& s) const {
  if (samples_.empty() || !deformable_) return;
  const Sample& end = samples_.back();
  if (restarted_)
    fmt::print(out,
               "  a restarted run: the figures below are over its outputs from t = {:.4e} on "
               "(matsum and glstat hold the whole run)\n",
               first_time_);
  fmt::print(out,
             "  deformable parts (rigid bodies left out), at the end: kinetic energy {:.4e}, "
             "internal energy {:.4e}",
             end.kinetic, end.internal);
  if (end.internal > 0.0) fmt::print(out, ", KE/IE {:.4f}", end.kinetic / end.internal);
  fmt::print(out, "; added mass (DT2MS) {:.4e}", end.added_mass);
  if (deformable_mass_ > 0.0)
    fmt::print(out, " ({:.3g} % of their mass)", 100.0 * end.added_mass / deformable_mass_);
  fmt::print(out, "\n");
  const InertiaFigures f = figures(s);
  if (f.largest_kinetic_over_internal >= 0.0)
    fmt::print(out,
               "  deformable parts: largest KE/IE {:.4f} (over {} outputs, once their internal "
               "energy had reached {:g} % of its largest)\n",
               f.largest_kinetic_over_internal, samples_.size(), 100.0 * kInternalFloor);
  if (f.tool_speed <= 0.0 || f.wave_speed <= 0.0) return;
  const InertiaVerdict verdict = judge_inertia(f);
  fmt::print(out, "  driven nodes: fastest {:.4e}, {:.4f} of the slowest wave speed ({:.4e})",
             f.tool_speed, f.tool_speed / f.wave_speed, f.wave_speed);
  if (f.inertia_part != 0)
    fmt::print(out, "; rho v^2 / yield {:.4f} (part {})", f.inertia_number, f.inertia_part);
  fmt::print(out, "{}\n",
             f.moving_at_start ? "; the deformable parts moved at t = 0 (an impact)"
             : verdict.quasi_static_speeds
                 ? fmt::format("; quasi-static by its speeds (below {:g})", kQuasiStaticMach)
                 : "");
  fmt::print(out, "{}", warning_text(verdict));
}

}  // namespace mcdyna::io
