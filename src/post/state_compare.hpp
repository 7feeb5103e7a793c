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
  double largest_offset = 0.0;                     ///< max |time A - time B| over them
  std::size_t nodes = 0, elements = 0;             ///< matched by user ID
  std::size_t only_a = 0, only_b = 0;              ///< nodes and elements in one family only
  std::vector<StateFieldDifference> rows;          ///< by part, then field
};

/// Receives each matched state's differences A - B in B's numbering (the difference series,
/// post/difference_series.hpp): nodes by their index in B, elements by class ("solid", "shell",
/// "beam", "particle") and index in B's class.
class DifferenceSink {
 public:
  virtual ~DifferenceSink() = default;
  virtual void begin_state(double time_b, const std::vector<double>& x_b) = 0;
  virtual void node(std::size_t b, const char* field, const double* a_minus_b) = 0;  ///< 3
  virtual void element(const char* element_class, std::size_t b, const char* field,
                       const double* a_minus_b, int components) = 0;
  virtual void end_state() = 0;
};

/// Each state of A is matched to B's state nearest in time when it is within `time_tolerance`
/// (default, negative: half of B's shortest interval between states: both codes write a state
/// at the first cycle at or after its time, so the same output time differs by up to a step).
StateComparison compare_states(const io::d3plot::Reader& a, const io::d3plot::Reader& b,
                               double time_tolerance = -1.0, DifferenceSink* sink = nullptr);

}  // namespace mcdyna::post
