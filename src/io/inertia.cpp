#include "io/inertia.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>

#include "solver/energy.hpp"

namespace mcdyna::io {

void InertiaRecord::add(const solver::State& s, const Eigen::Matrix3Xd& previous) {
  const std::vector<solver::PartSummary> parts = solver::part_summaries(s, previous);
  Sample sample{.time = s.time};
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (s.parts[p].rigid_body >= 0) continue;
    deformable_ = true;
    sample.kinetic += parts[p].kinetic;
    sample.internal += parts[p].internal;
    sample.added_mass += parts[p].added_mass;
  }
  samples_.push_back(sample);
}

void InertiaRecord::print(std::ostream& out) const {
  if (samples_.empty() || !deformable_) return;
  const Sample& end = samples_.back();
  double top = 0.0;
  for (const Sample& x : samples_)
    top = std::max(top, x.internal);
  const Sample* largest = nullptr;
  for (const Sample& x : samples_)
    if (top > 0.0 && x.internal >= kInternalFloor * top &&
        (largest == nullptr || x.kinetic / x.internal > largest->kinetic / largest->internal))
      largest = &x;
  fmt::print(out,
             "  deformable parts (rigid bodies left out), at the end: kinetic energy {:.4e}, "
             "internal energy {:.4e}",
             end.kinetic, end.internal);
  if (end.internal > 0.0) fmt::print(out, ", KE/IE {:.4f}", end.kinetic / end.internal);
  fmt::print(out, "; added mass (DT2MS) {:.4e}\n", end.added_mass);
  if (largest != nullptr)
    fmt::print(out,
               "  deformable parts: largest KE/IE {:.4f} at t = {:.6e} (over {} outputs, once "
               "their internal energy had reached {:g} % of its largest)\n",
               largest->kinetic / largest->internal, largest->time, samples_.size(),
               100.0 * kInternalFloor);
}

}  // namespace mcdyna::io
