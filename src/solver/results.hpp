#pragma once
/// Element results as users see them: the Cauchy stress averaged over the integration points,
/// von Mises stress, mean effective plastic strain, and damage (the largest of the points).
#include <algorithm>
#include <array>
#include <cmath>

#include "solver/shells/shell_elements.hpp"
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

/// Result of particle `i` of an SPG domain (its one integration point).
inline ElementResult particle_result(const spg::Domain& d, Index i) {
  ElementResult r;
  const auto ii = static_cast<std::size_t>(i);
  std::array<double, 6> dev{};
  for (int k = 0; k < 6; ++k)
    dev[static_cast<std::size_t>(k)] = d.fields.points.deviator(k, i);
  set_stress(r, dev, d.fields.pressure[ii]);
  r.plastic_strain = d.fields.points.plastic_strain[ii];
  r.damage = d.fields.points.damage[ii];
  return r;
}

/// Result of element `e` of `block`.
inline ElementResult element_result(const State& s, const SolidBlock& block, Index e) {
  ElementResult r;
  const int np = block.points_per_element;
  const Index first = block.point_begin + np * (e - block.begin);
  const auto& pts = s.solids.points;
  std::array<double, 6> dev{};
  for (Index p = first; p < first + np; ++p) {
    for (int k = 0; k < 6; ++k)
      dev[static_cast<std::size_t>(k)] += pts.deviator(k, p) / np;
    r.plastic_strain += pts.plastic_strain[static_cast<std::size_t>(p)] / np;
    r.damage = std::max(r.damage, pts.damage[static_cast<std::size_t>(p)]);
  }
  set_stress(r, dev, s.solids.pressure[static_cast<std::size_t>(e)]);
  return r;
}

/// Which layers of a shell a result averages: all of them (the mid-surface value LS-DYNA's
/// d3plot shows by default), the top (outermost, +z) or the bottom one.
enum class ShellSurface { all, top, bottom };

/// Result of shell `e` of `block`: the stress turned from the element's frame to the global axes,
/// the plastic strain (mean of the layers taken, over the in-plane points) and the damage
/// (largest of them).
inline ElementResult shell_result(const State& s, const ShellBlock& block, Index e,
                                  ShellSurface surface) {
  ElementResult r;
  const int layers = block.layers, in_plane = block.in_plane_points;
  const Index first = block.point_begin + in_plane * layers * (e - block.begin);
  int from = 0, to = layers;
  if (surface == ShellSurface::top) from = layers - 1;
  if (surface == ShellSurface::bottom) to = 1;
  const auto& pts = s.shells.points;
  Mat3 local = Mat3::Zero();
  for (int k = 0; k < in_plane * layers; ++k) {  // the in-plane points' layers, averaged
    const int l = k % layers;
    if (l < from || l >= to) continue;
    const Index p = first + k;
    const auto pp = static_cast<std::size_t>(p);
    const double w = 1.0 / ((to - from) * in_plane);
    local(0, 0) += w * pts.stress(0, p);
    local(1, 1) += w * pts.stress(1, p);
    local(2, 2) += w * pts.stress(2, p);
    local(0, 1) += w * pts.stress(3, p);
    local(1, 2) += w * pts.stress(4, p);
    local(0, 2) += w * pts.stress(5, p);
    r.plastic_strain += w * pts.plastic_strain[pp];
    r.damage = std::max(r.damage, pts.damage[pp]);
  }
  local(1, 0) = local(0, 1);
  local(2, 1) = local(1, 2);
  local(2, 0) = local(0, 2);
  set_local_stress(r, local, shell_axes(s, e));
  return r;
}

}  // namespace mcdyna::solver
