#pragma once
/// What the outputs show of a beam (results.hpp's ElementResult) and its resultants.
#include <array>

#include "solver/beams/beam_elements.hpp"
#include "solver/results.hpp"

namespace mcdyna::solver {

/// Result of beam `e` of `block`: the fibres' stress (sigma_rr, tau_rs, tau_rt) weighted by area
/// (the resultant beam: N / A), turned to the global axes; the plastic strain as the fibres'
/// area-weighted mean, the damage their largest.
inline ElementResult beam_result(const State& s, const Beams& bm, const BeamBlock& block, Index e) {
  ElementResult r;
  const auto i = static_cast<std::size_t>(e);
  Mat3 local = Mat3::Zero();
  if (block.formulation == BeamFormulation::belytschko_schwer) {
    local(0, 0) = bm.resultants[6 * i] / bm.area[i];
  } else {
    const auto& pts = bm.points;
    const Index first = block.point_begin + block.points * (e - block.begin);
    for (int k = 0; k < block.points; ++k) {
      const Index p = first + k;
      const auto pp = static_cast<std::size_t>(p);
      const double w = block.point_weight[static_cast<std::size_t>(k)];
      local(0, 0) += w * pts.stress(0, p);
      local(0, 1) += w * pts.stress(3, p);
      local(0, 2) += w * pts.stress(5, p);
      r.plastic_strain += w * pts.plastic_strain[pp];
      r.damage = std::max(r.damage, pts.damage[pp]);
    }
    local(1, 0) = local(0, 1);
    local(2, 0) = local(0, 2);
  }
  set_local_stress(r, local, beam_axes(s, bm, e));
  return r;
}

/// The resultants of beam `e` in its local axes: N, V_s, V_t, T, M_s, M_t (the resultant beam's
/// shears from its end moments, its moments the mean of the two ends').
inline std::array<double, 6> beam_resultants(const State& s, const Beams& bm,
                                             const BeamBlock& block, Index e) {
  const auto i = static_cast<std::size_t>(e);
  const double* r = &bm.resultants[6 * i];
  if (block.formulation == BeamFormulation::hughes_liu) return {r[0], r[1], r[2], r[3], r[4], r[5]};
  const auto& conn = bm.nodes[i];
  const double l = (s.nodes.position.col(conn[1]) - s.nodes.position.col(conn[0])).norm();
  return {r[0], -(r[4] + r[5]) / l,  (r[2] + r[3]) / l,
          r[1], 0.5 * (r[3] - r[2]), 0.5 * (r[5] - r[4])};
}

}  // namespace mcdyna::solver
