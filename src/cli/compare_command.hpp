#pragma once
/// `mcdyna compare A B`: compare two histories (our CSV, other CSV, LS-DYNA ASCII files) column
/// by column, or two d3plot families (ours or LS-DYNA's: a folder holding d3plot, or the d3plot
/// file) state by state (post/state_compare.hpp); B is the reference.
#include <filesystem>
#include <iosfwd>
#include <optional>

#include "post/history_compare.hpp"

namespace mcdyna::cli {

struct CompareCommandOptions {
  std::filesystem::path a, b;
  post::CompareOptions compare;
  std::optional<double> tolerance;          ///< max |A-B| / peak |B| allowed per column
  std::filesystem::path plot;               ///< PNG of both curves and their difference
  std::filesystem::path csv;                ///< the resampled curves
  std::filesystem::path difference_series;  ///< two d3plot families: A - B as a VTK series here
};

/// Exit code: 0 compared (and within --tol), 1 a column exceeds --tol, 2 the files cannot be
/// read or compared (message on `err`).
int run_compare(const CompareCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mcdyna::cli
