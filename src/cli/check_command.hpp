#pragma once
/// `mcdyna check DECK`: read, build and cross-check a deck; print the summary and migration report.
#include <filesystem>
#include <iosfwd>

namespace mcdyna::cli {

struct CheckOptions {
  std::filesystem::path deck;
  bool allow_unsupported = false;
  bool quiet = false;             ///< no summary, only diagnostics and the verdict
  std::size_t max_messages = 50;  ///< 0: all
  long case_id = 0;               ///< --case; 0: each *CASE of the deck in turn (if any)
};

/// Exit code: 0 fine, 1 deck errors (or unsupported physics without --allow-unsupported).
int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mcdyna::cli
