#pragma once
/// A shell's result as users see it (results.hpp): its layers' stress turned to global axes.
#include "solver/results.hpp"
#include "solver/shells/shell_elements.hpp"

namespace mcdyna::solver {

/// Which layers of a shell a result averages: all of them, the top (outermost, +z) or the bottom
/// one, or the middle one (the two nearest the mid-surface for an even count: LS-DYNA's
/// mid-surface value of MAXINT 3).
enum class ShellSurface { all, top, bottom, middle };

/// Result of shell `e` of `block`: the stress turned from the element's frame to the global axes,
/// the plastic strain (mean of the layers taken, over the in-plane points) and the damage
/// (largest of them).
inline ElementResult shell_result(const Nodes& nodes, const Shells& sh, const ShellBlock& block,
                                  Index e, ShellSurface surface) {
  ElementResult r;
  const int layers = block.layers, in_plane = block.in_plane_points;
  const Index first = block.point_begin + in_plane * layers * (e - block.begin);
  int from = 0, to = layers;
  if (surface == ShellSurface::top) from = layers - 1;
  if (surface == ShellSurface::bottom) to = 1;
  if (surface == ShellSurface::middle) {
    from = (layers - 1) / 2;
    to = layers / 2 + 1;
  }
  const auto& pts = sh.points;
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
  set_local_stress(r, local, shell_axes(nodes, sh, e));
  return r;
}

}  // namespace mcdyna::solver
