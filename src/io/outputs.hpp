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

#include "io/history_file.hpp"
#include "io/vtk_series.hpp"
#include "model/model_database.hpp"
#include "solver/state.hpp"

namespace mcdyna::io {

class Outputs {
 public:
  /// `notes` receives one line per request that cannot be honoured (e.g. rcforc without contact).
  Outputs(const model::ModelDatabase& model, const solver::State& state,
          const std::filesystem::path& dir, std::vector<std::string>& notes);

  [[nodiscard]] bool due(const solver::State& state) const;
  /// `previous`: v^{n-1/2}; the state holds v^{n+1/2}.
  void write(const solver::State& state, const Eigen::Matrix3Xd& previous, bool final,
             double nanoseconds_per_zone_cycle);
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
  };
  static Schedule schedule(const model::ModelDatabase& model, const solver::State& state,
                           double interval, model::Id curve);
  std::unique_ptr<VtkSeries> d3plot_;
  Schedule d3plot_schedule_;
  std::vector<std::unique_ptr<HistoryFile>> histories_;
  std::vector<Schedule> history_schedules_;
};

}  // namespace mcdyna::io
