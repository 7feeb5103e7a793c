#include "cli/progress.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>

namespace mcdyna::cli {

namespace {
double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

Progress::Progress(std::ostream& out, std::ostream& log, bool terminal, bool quiet,
                   double start_fraction)
    : out_(out),
      log_(log),
      terminal_(terminal),
      quiet_(quiet),
      start_(Clock::now()),
      start_fraction_(start_fraction) {
  while (next_fraction_ <= start_fraction_)
    next_fraction_ += 0.05;
}

std::string Progress::refreshed(const std::string& line, std::size_t previous_length) {
  // "\r" returns to the line's start without clearing it: a shorter line left the end of the
  // longer one standing ("ETA 16.2 ss").
  return "\r" + line +
         std::string(previous_length > line.size() ? previous_length - line.size() : 0, ' ');
}

void Progress::update(const solver::State& s) {
  const double end = s.time_control.end_time;
  const double fraction = end > 0.0 ? std::min(1.0, s.time / end) : 0.0;
  const auto now = Clock::now();
  const bool milestone = fraction >= next_fraction_;
  const bool refresh = terminal_ && now - last_print_ > std::chrono::milliseconds(200);
  if (!milestone && !refresh) return;
  const std::string line = this->line(s, now);
  if (milestone) {
    fmt::print(log_, "{}\n", line);
    log_.flush();  // a user tailing d3hsp (or a batch log) sees the run advance
    while (next_fraction_ <= fraction)
      next_fraction_ += 0.05;
  }
  if (quiet_) return;
  if (terminal_) {
    out_ << refreshed(line, printed_length_);
    out_.flush();
    printed_length_ = line.size();
    last_print_ = now;
  } else if (milestone) {
    fmt::print(out_, "{}\n", line);
    out_.flush();
  }
}

std::string Progress::line(const solver::State& s, Clock::time_point now) const {
  const double end = s.time_control.end_time;
  const double fraction = end > 0.0 ? std::min(1.0, s.time / end) : 0.0;
  const double elapsed = seconds(start_, now);
  const double done = fraction - start_fraction_;
  const double eta = done > 0.0 ? elapsed * (1.0 - fraction) / done : 0.0;
  return fmt::format(
      "cycle {:>9}  t = {:.5e}  dt = {:.4e}  {:5.1f} %  elapsed {:.1f} s  ETA {:.1f} s", s.cycle,
      s.time, s.step, 100.0 * fraction, elapsed, eta);
}

void Progress::status(const solver::State& s) {
  const std::string text = "sw2: " + line(s, Clock::now());
  if (terminal_ && printed_length_ > 0) out_ << refreshed("", printed_length_) << '\r';
  fmt::print(out_, "{}\n", text);
  out_.flush();
  fmt::print(log_, "{}\n", text);
  log_.flush();
  printed_length_ = 0;
}

void Progress::finish() {
  if (terminal_ && !quiet_) fmt::print(out_, "\n");
}

}  // namespace mcdyna::cli
