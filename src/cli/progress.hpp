#pragma once
/// The progress of a run: a refreshed line on a terminal, otherwise a plain line every 5 % of the
/// end time, flushed (a batch run's redirected output is block-buffered and showed nothing until
/// the end). The same lines (every 5 %) go to d3hsp as the time-step history.
#include <chrono>
#include <ostream>
#include <string>

#include "solver/state.hpp"

namespace mcdyna::cli {

class Progress {
 public:
  /// `start_fraction`: the share of ENDTIM done before this run started (a restart).
  Progress(std::ostream& out, std::ostream& log, bool terminal, bool quiet, double start_fraction);
  void update(const solver::State& s);
  /// Sense switch sw2: the progress line now, on a line of its own (also when quiet).
  void status(const solver::State& s);
  /// Ends the refreshed line on a terminal.
  void finish();
  /// A refreshed line shorter than the one before it, padded to cover all of that one.
  static std::string refreshed(const std::string& line, std::size_t previous_length);

 private:
  using Clock = std::chrono::steady_clock;
  [[nodiscard]] std::string line(const solver::State& s, Clock::time_point now) const;
  std::ostream& out_;
  std::ostream& log_;
  bool terminal_, quiet_;
  Clock::time_point start_, last_print_{};
  double start_fraction_ = 0.0;
  double next_fraction_ = 0.05;
  std::size_t printed_length_ = 0;  ///< of the refreshed line now on the terminal
};

}  // namespace mcdyna::cli
