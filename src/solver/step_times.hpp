#pragma once
/// The times of one cycle, which every block's step reads (StepTimes), and the wall-clock
/// seconds per phase of the cycle, which blocks report their work under (PhaseTimes). Here,
/// with the block interface, because both the formulations and the time loop
/// (run/driver.hpp) use them.
#include <array>

namespace mcdyna::solver {

struct StepTimes {
  double time = 0.0;  ///< t^n
  double step = 0.0;  ///< dt^{n+1/2}: positions advance over it
  double mean = 0.0;  ///< dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2: velocities advance over it
};

/// Wall-clock seconds per phase of the cycle.
struct PhaseTimes {
  static constexpr int kCount = 15;
  enum Phase {
    elements,
    boundary,
    rigid,
    output,
    other,
    spg_neighbours,
    spg_shape_functions,
    spg_smoothing,
    spg_stress,
    spg_stabilization,
    spg_forces,
    spg_bonds,
    spg_step_estimate,
    contact,
    exchange  ///< over several processes: halo messages and the per-cycle agreements
  };
  std::array<double, kCount> seconds{};
  static const char* name(int p);
};

}  // namespace mcdyna::solver
