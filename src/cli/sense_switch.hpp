#pragma once
/// LS-DYNA's sense switches: a user steers a running job by writing a file named d3kil in its
/// output directory (`echo sw1 > DIR/d3kil`). The run reads the file, deletes it and acts at the
/// same cycle on every process:
///   sw1  a restart dump (d3dumpNN), then stop (exit 5, as for a signal); an empty d3kil is sw1
///   sw2  print where the run stands (cycle, time, step, % done, ETA) and go on
///   sw3  a restart dump (d3dumpNN), and go on
///   sw4  a d3plot state, and go on
/// Anything else in the file is reported and ignored. Over several processes process 0 reads it.
#include <chrono>
#include <filesystem>
#include <ostream>
#include <string>

#include "solver/run/driver.hpp"

namespace mcdyna::cli {

class SenseSwitchFile {
 public:
  /// `reader`: this process reads the file (process 0); the others only take part in the
  /// agreement. `out` gets one line per switch read.
  SenseSwitchFile(std::filesystem::path dir, bool reader, std::ostream& out);
  /// The switches set since the last poll. Looks at the file at most every 0.2 s of wall time,
  /// so that a run of short cycles does not pay a file-system call per cycle.
  solver::SenseSwitches poll();
  /// Parses the file's text ("sw1", case and surrounding blanks ignored; empty = sw1). Returns
  /// false for text that names no switch.
  static bool parse(const std::string& text, solver::SenseSwitches& out);
  /// Was sw1 read: the run stops because the user asked (not a signal).
  [[nodiscard]] bool stop_requested() const { return stop_; }

 private:
  std::filesystem::path path_;
  bool reader_;
  std::ostream& out_;
  std::chrono::steady_clock::time_point last_look_{};
  bool stop_ = false;
};

}  // namespace mcdyna::cli
