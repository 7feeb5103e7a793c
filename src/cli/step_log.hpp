#pragma once
/// `mcdyna run --step-log FILE`: one CSV row per cycle saying what set the step: the step taken,
/// the stable-step estimate, the element or particle giving it, and for the particle with the
/// smallest step at its physical mass (what the step would be without DT2MS) its nearest
/// neighbour now against its initial spacing, its row's mass factor, its MC-SPG mobility and
/// whether contact pushed it this cycle. For measuring what holds the step (issue 23).
#include <filesystem>

#include "io/checked_file.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

class StepLog {
 public:
  /// Creates FILE with its header row (a restart continues a fresh file: the log is a probe).
  explicit StepLog(const std::filesystem::path& path);
  /// Appends the row of the cycle just computed; rows go to disk in blocks.
  void add(const solver::State& s);
  void flush();

 private:
  io::RecordFile file_;
  long rows_ = 0;
};

}  // namespace mcdyna::cli
