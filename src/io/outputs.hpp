#pragma once
/// Everything a run writes besides d3hsp: the VTK series at *DATABASE_BINARY_D3PLOT DT and the
/// ASCII/CSV histories at each *DATABASE_<name> DT. Only requested outputs are created. States
/// are written at the first cycle whose time reaches the next output time, as LS-DYNA does, and
/// always at the last state of the run. A curve LCDT (d3plot) or LCUR (ASCII) overrides DT: the
/// interval after an output at time t is the curve's value at t, so a deck can write sparsely and
/// then every cycle near an event; an interval <= 0 writes every cycle.
#include <Eigen/Core>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/d3plot/d3plot_database.hpp"
#include "io/history_file.hpp"
#include "io/vtk_series.hpp"
#include "model/model_database.hpp"
#include "solver/state.hpp"

namespace mcdyna::io {

/// Where the outputs stood at a restart dump: the schedules (next output times), the VTK states
/// written and the history files' sizes.
struct OutputsResume {
  struct Times {
    double interval = 0.0, next = 0.0, last_written = -1.0;
  };
  Times d3plot;
  std::vector<std::pair<double, std::string>> states;  ///< (time, file) of the VTK states
  d3plot::FamilyPosition family;                       ///< where the binary d3plot stands
  std::vector<Times> history_times;                    ///< in the order of `histories`
  std::vector<HistoryResume> histories;
};

template <class Ar>
void fields(Ar& ar, OutputsResume::Times& t) {
  ar(t.interval, t.next, t.last_written);
}
template <class Ar>
void fields(Ar& ar, HistoryResume& h) {
  ar(h.name, h.ascii_bytes, h.csv_bytes, h.values);
}
template <class Ar>
void fields(Ar& ar, OutputsResume& o) {
  ar(o.d3plot, o.states, o.family, o.history_times, o.histories);
}

class Outputs {
 public:
  /// `notes` receives one line per request that cannot be honoured (e.g. rcforc without contact).
  /// `resume`: continue the outputs of a run restarted from a dump (files are appended to).
  Outputs(const model::ModelDatabase& model, const solver::State& state,
          const std::filesystem::path& dir, std::vector<std::string>& notes,
          const OutputsResume* resume = nullptr);
  /// Where the outputs stand now, for a restart dump (flushes the history files).
  [[nodiscard]] OutputsResume resume_point() const;

  [[nodiscard]] bool due(const solver::State& state) const;
  /// Is a d3plot state among what is due (the element fields; histories need only energies)?
  [[nodiscard]] bool state_due(const solver::State& state) const;
  /// `previous`: v^{n-1/2}; the state holds v^{n+1/2}.
  void write(const solver::State& state, const Eigen::Matrix3Xd& previous, bool final,
             double nanoseconds_per_zone_cycle);
  /// Sense switch sw4: the next write() writes a d3plot state whatever the schedule says (and
  /// leaves the schedule as it was). False when the deck asks for no d3plot states.
  bool request_state() {
    state_requested_ = d3plot_ != nullptr;
    return state_requested_;
  }
  /// Files created so far (for the end-of-run report).
  [[nodiscard]] std::vector<std::string> files() const;
  [[nodiscard]] std::size_t states_written() const { return d3plot_ ? d3plot_->states() : 0; }

 private:
  struct Schedule {
    double interval = 0.0;
    const solver::LoadCurve* interval_curve = nullptr;  ///< LCDT / LCUR: overrides `interval`
    double next = 0.0;
    double last_written = -1.0;
    [[nodiscard]] bool due(double t) const { return t >= next - 1.0e-9 * interval; }
    void advance(double t);
    [[nodiscard]] OutputsResume::Times times() const { return {interval, next, last_written}; }
    void restore(const OutputsResume::Times& t) {
      interval = t.interval;
      next = t.next;
      last_written = t.last_written;
    }
  };
  static Schedule schedule(const model::ModelDatabase& model, const solver::State& state,
                           double interval, model::Id curve);
  std::unique_ptr<VtkSeries> d3plot_;
  std::unique_ptr<d3plot::Database> binary_;  ///< LS-DYNA's d3plot, at the VTK series' times
  Schedule d3plot_schedule_;
  bool state_requested_ = false;
  std::vector<std::unique_ptr<HistoryFile>> histories_;
  std::vector<Schedule> history_schedules_;
};

}  // namespace mcdyna::io
