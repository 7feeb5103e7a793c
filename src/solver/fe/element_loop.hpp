#pragma once
/// The loop every finite-element pass shares (solids, shells): elements of a block in
/// interleaved chunks over the threads, the smallest step (ties to the lower index, so the same
/// for any thread count), the first inverted or non-finite element, erosion, and DT2MS mass
/// scaling. Every element writes only its own data.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "solver/nodal_forces.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

struct ElementPassResult {
  double critical_step = 0.0;  ///< min over elements of the element step (before TSSFAC)
  Index controlling = -1;      ///< element giving it (lowest index on ties)
  Index inverted = -1;         ///< lowest element with non-positive volume or area, or -1
  Index non_finite = -1;       ///< lowest element with a NaN/Inf state (its step), or -1
  Index runaway = -1;          ///< lowest element grown past kRunawayGrowth, or -1
  Index newly_eroded = 0;
  bool mass_changed = false;  ///< mass scaling added mass this pass
};

namespace fe {

// Small blocks run serially: a parallel region costs more than a few elements.
constexpr Index kParallelMinimum = 512;
// Elements are handed to threads in interleaved chunks: plastic work concentrates in one region
// of a part (the impact end of a Taylor bar), and contiguous halves would leave one thread idle.
constexpr int kElementChunk = 128;

/// An element whose area (shell) or volume (solid) has grown this many times is taken as a
/// run gone unstable: no material stretches so, and an element blowing up without inverting
/// would otherwise end the run "normally" with a vast step (a lone unsupported shell square's
/// dilatation, omega = 2 c sqrt(1 + nu) / L, is above the L / c estimate: TSSFAC 0.9 > 0.877).
constexpr double kRunawayGrowth = 1.0e4;

/// Whether an element of area or volume `size` has run away from its `initial` one.
[[nodiscard]] inline bool runaway(double size, double initial) {
  return size > kRunawayGrowth * initial;
}

/// What one element's update found.
struct ElementOutcome {
  double step = 0.0;
  bool inverted = false;
  bool failed = false;   ///< its failure criterion was met: it erodes
  bool runaway = false;  ///< grown past kRunawayGrowth times its initial area or volume
};

/// Per-thread minimum of (step, element); ties go to the lower element index.
struct StepMin {
  double step = std::numeric_limits<double>::infinity();
  Index element = -1;
  void take(double s, Index e) {
    if (s < step || (s == step && (element < 0 || e < element))) {
      step = s;
      element = e;
    }
  }
};

/// What a pass gathers over blocks and threads.
struct PassTotals {
  StepMin step;
  Index inverted = std::numeric_limits<Index>::max();
  Index non_finite = std::numeric_limits<Index>::max();
  Index runaway = std::numeric_limits<Index>::max();
  Index eroded = 0;
  bool mass_changed = false;
  void add(const PassTotals& o) {
    step.take(o.step.step, o.step.element);
    inverted = std::min(inverted, o.inverted);
    non_finite = std::min(non_finite, o.non_finite);
    runaway = std::min(runaway, o.runaway);
    eroded += o.eroded;
    mass_changed = mass_changed || o.mass_changed;
  }
  [[nodiscard]] ElementPassResult result() const {
    constexpr Index kNone = std::numeric_limits<Index>::max();
    return {step.step,
            step.element,
            inverted == kNone ? -1 : inverted,
            non_finite == kNone ? -1 : non_finite,
            runaway == kNone ? -1 : runaway,
            eroded,
            mass_changed};
  }
};

/// The per-element arrays the loop updates.
struct ElementArrays {
  std::vector<std::uint8_t>& eroded;
  std::vector<double>& corner_force;
  int corner_values;  ///< values per element in corner_force (cleared when it erodes)
  const std::vector<double>& mass;
  std::vector<double>& added_mass;
  std::vector<double>& time_step;
};

/// Mass scaling (DT2MS): enough added mass that the element's step reaches the target
/// (TSSFAC * |DT2MS| / TSSFAC); added mass never decreases. Returns the step with it.
inline double scale_mass(double mass, double& added, double step, double scale_factor,
                         double target, bool& changed) {
  const double with_added = step * std::sqrt((mass + added) / mass);
  if (target <= 0.0 || scale_factor * with_added >= target) return with_added;
  const double ratio = target / (scale_factor * step);
  added = mass * (ratio * ratio - 1.0);
  changed = true;
  return target / scale_factor;
}

/// Runs `element(e) -> ElementOutcome` over [begin, end) but the eroded elements and those
/// `skip(e)` names, and gathers the outcomes into `totals`.
template <class Element, class Skip>
void element_loop(Index begin, Index end, ElementArrays a, double scale_factor, double target,
                  Skip skip, Element element, PassTotals& totals) {
#pragma omp parallel if (end - begin > kParallelMinimum)
  {
    PassTotals local;
#pragma omp for schedule(static, kElementChunk) nowait
    for (Index e = begin; e < end; ++e) {
      const auto i = static_cast<std::size_t>(e);
      if (a.eroded[i] || skip(e)) continue;
      const ElementOutcome o = element(e);
      if (o.inverted) {
        local.inverted = std::min(local.inverted, e);
        continue;
      }
      if (!std::isfinite(o.step)) {  // NaN or Inf stress, energy or wave speed
        local.non_finite = std::min(local.non_finite, e);
        continue;
      }
      if (o.runaway) local.runaway = std::min(local.runaway, e);
      if (o.failed) {
        a.eroded[i] = 1;
        const auto n = static_cast<std::size_t>(a.corner_values);
        std::fill(&a.corner_force[n * i], &a.corner_force[n * i] + n, 0.0);
        ++local.eroded;
        continue;
      }
      const double step =
          scale_mass(a.mass[i], a.added_mass[i], o.step, scale_factor, target, local.mass_changed);
      a.time_step[i] = step;
      local.step.take(step, e);
    }
#pragma omp critical
    totals.add(local);
  }
}

/// Sums per-corner forces and moments (6 values: force then moment, global axes) into the nodal
/// forces and moments over a node -> (element * N + corner) list (CSR `offsets`, `corners`), in
/// its fixed order: the shells' and the beams' gather.
inline void gather_forces_and_moments(const State& state, const std::vector<double>& values,
                                      const std::vector<Index>& offsets,
                                      const std::vector<Index>& corners, NodalForces& f) {
  const Nodes& nd = state.nodes;
  const double* cf = values.data();
  const std::size_t count = state.ownership.moved_count(nd.count());
#pragma omp parallel for schedule(static) if (count > 4 * kParallelMinimum)
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = state.ownership.moved_node(k);
    const auto nn = static_cast<std::size_t>(n);
    const Index begin = offsets[nn], end = offsets[nn + 1];
    if (begin == end) continue;
    double sum[6] = {};
    for (Index j = begin; j < end; ++j) {
      const double* c = cf + 6 * static_cast<std::size_t>(corners[static_cast<std::size_t>(j)]);
      for (int d = 0; d < 6; ++d)
        sum[d] += c[d];
    }
    for (int d = 0; d < 3; ++d) {
      f.force(d, n) += sum[d];
      f.moment(d, n) += sum[3 + d];
    }
  }
}

}  // namespace fe

}  // namespace mcdyna::solver
