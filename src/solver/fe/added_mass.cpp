#include "solver/fe/added_mass.hpp"

namespace mcdyna::solver {

void refresh_added_mass(State& s) {
  Nodes& nd = s.nodes;
  const bool shells = !nd.shell_corner_offsets.empty();
  const bool beams = !nd.beam_end_offsets.empty();
#pragma omp parallel for schedule(static)
  for (Index n = 0; n < nd.count(); ++n) {
    const auto nn = static_cast<std::size_t>(n);
    double sum = 0.0;
    for (Index k = nd.corner_offsets[nn]; k < nd.corner_offsets[nn + 1]; ++k)
      sum += s.solids
                 .added_mass[static_cast<std::size_t>(nd.corners[static_cast<std::size_t>(k)] / 8)];
    sum /= 8.0;
    if (shells) {
      for (Index k = nd.shell_corner_offsets[nn]; k < nd.shell_corner_offsets[nn + 1]; ++k) {
        const auto e = static_cast<std::size_t>(nd.shell_corners[static_cast<std::size_t>(k)] / 4);
        const bool triangle = s.shells.nodes[e][3] == s.shells.nodes[e][2];
        sum += s.shells.added_mass[e] / (triangle ? 3.0 : 4.0);
      }
    }
    if (beams) {
      for (Index k = nd.beam_end_offsets[nn]; k < nd.beam_end_offsets[nn + 1]; ++k)
        sum += 0.5 * s.beams.added_mass[static_cast<std::size_t>(
                         nd.beam_ends[static_cast<std::size_t>(k)] / 2)];
    }
    nd.added_mass[nn] = sum;
  }
}

}  // namespace mcdyna::solver
