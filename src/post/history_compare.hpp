// Comparing two histories column by column (`mcdyna compare`): both tables are aligned on a
// monotonic column (time, or e.g. plunge distance), resampled linearly onto one uniform grid over
// the range they share, and each chosen column is reported as max and RMS difference, difference
// relative to the reference peak, the peaks and where they occur, and the correlation.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "io/history_table.hpp"

namespace mcdyna::post {

struct CompareOptions {
  std::string x_a = "time";          ///< alignment column in A (name or 1-based index)
  std::string x_b;                   ///< in B; empty: same as x_a
  std::vector<std::string> columns;  ///< NAME, A_NAME:B_NAME, or indices; empty: all shared
  std::size_t points = 0;            ///< resampling points; 0: the denser file's count in range
  double from = -1e300, to = 1e300;  ///< optional window on x
};

struct ColumnComparison {
  std::string name_a, name_b;
  double max_difference = 0.0;  ///< max |A - B|
  double x_at_max = 0.0;
  double rms_difference = 0.0;
  double relative_to_peak = 0.0;        ///< max |A - B| / max |B| (B is the reference)
  double peak_a = 0.0, x_peak_a = 0.0;  ///< value of largest magnitude, signed, and where
  double peak_b = 0.0, x_peak_b = 0.0;
  double correlation = 0.0;  ///< Pearson; NaN when either curve is constant
  std::vector<double> a, b;  ///< resampled values on the grid
};

struct Comparison {
  std::string x_name_a, x_name_b;
  std::vector<double> x;  ///< the common grid
  std::vector<ColumnComparison> columns;
};

/// A request that cannot be met (unknown column, no overlap, non-monotonic x …), said plainly.
class CompareError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Comparison compare_histories(const io::HistoryTable& a, const io::HistoryTable& b,
                             const CompareOptions& options);

/// Linear interpolation of (x, y) at `at`; x ascending with NaN-free samples.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at);

}  // namespace mcdyna::post
