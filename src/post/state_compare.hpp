#pragma once
/// Two d3plot families compared state by state (issue 49): an engineer's LS-DYNA d3plot beside
/// mcdyna's run of the same deck, or two mcdyna runs. States are matched by time, nodes and
/// elements by user ID; per part and field the largest and the RMS difference over the matched
/// states, and B's peak for a relative tolerance. B is the reference.
///
/// Fields: displacement and velocity (per node, the length of the difference vector; a node
/// belongs to the part of the first element or particle on it), stress (the largest of the six
/// components' differences; solids, shells' first written layer, SPG/SPH particles), plastic
/// strain (solids, shells' first layer, particles), beam resultants (the largest of the six).
/// Where an element writes several integration points, the first point's values are compared.
#include <string>
#include <vector>

#include "io/d3plot/d3plot_reader.hpp"

namespace mcdyna::post {

struct StateFieldDifference {
  std::int64_t part = 0;  ///< part ID (0: nodes of no element)
  std::string field;
  double max = 0.0;  ///< largest |A - B|
  double time_at_max = 0.0;
  double rms = 0.0;        ///< over the matched states and entities
  double peak_b = 0.0;     ///< largest |B|
  std::size_t values = 0;  ///< entity-states compared
  [[nodiscard]] double relative() const {
    return peak_b > 0.0 ? max / peak_b : max > 0.0 ? 1e300 : 0.0;
  }
};

struct StateComparison {
  std::size_t states_a = 0, states_b = 0;
  std::vector<std::pair<double, double>> matched;  ///< (time A, time B) of each matched pair
  std::size_t nodes = 0, elements = 0;             ///< matched by user ID
  std::size_t only_a = 0, only_b = 0;              ///< nodes and elements in one family only
  std::vector<StateFieldDifference> rows;          ///< by part, then field
};

/// `time_tolerance`: relative to B's last time, how far a state's time may be from its match.
StateComparison compare_states(const io::d3plot::Reader& a, const io::d3plot::Reader& b,
                               double time_tolerance = 1e-5);

}  // namespace mcdyna::post
