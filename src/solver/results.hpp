#pragma once
/// Element results as users see them: the Cauchy stress averaged over the integration points,
/// von Mises stress, mean effective plastic strain, and damage (the largest of the points).
#include <algorithm>
#include <array>
#include <cmath>

#include "solver/state.hpp"

namespace mcdyna::solver {

struct ElementResult {
  std::array<double, 6> stress{};  ///< xx yy zz xy yz zx
  double von_mises = 0.0;
  double plastic_strain = 0.0;
  double damage = 0.0;
};

/// The pressure of a result's stress (compression positive): minus the mean normal stress.
inline double pressure_of(const ElementResult& r) {
  return -(r.stress[0] + r.stress[1] + r.stress[2]) / 3.0;
}

/// Stress of a deviator and pressure as a result (Cauchy stress, von Mises).
inline void set_stress(ElementResult& r, const std::array<double, 6>& dev, double pressure) {
  r.stress = dev;
  for (int k = 0; k < 3; ++k)
    r.stress[static_cast<std::size_t>(k)] -= pressure;
  const double j2 = 0.5 * (dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]) + dev[3] * dev[3] +
                    dev[4] * dev[4] + dev[5] * dev[5];
  r.von_mises = std::sqrt(3.0 * j2);
}

/// Stress given in an element's local axes (columns of `axes`) as a result in global axes.
inline void set_local_stress(ElementResult& r, const Mat3& local, const Mat3& axes) {
  const Mat3 g = axes * local * axes.transpose();
  const double mean = g.trace() / 3.0;
  set_stress(r, {g(0, 0) - mean, g(1, 1) - mean, g(2, 2) - mean, g(0, 1), g(1, 2), g(0, 2)}, -mean);
}

}  // namespace mcdyna::solver
