#include "io/outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/compile.hpp"
#include "solver/history_records.hpp"

namespace mcdyna::io {

void Outputs::Schedule::advance(double t) {
  last_written = t;
  if (interval_curve) {
    // The curve's interval at the output just written; a non-positive one writes every cycle.
    interval = std::max(0.0, (*interval_curve)(t));
    next = interval > 0.0 ? t + interval : std::nextafter(t, std::numeric_limits<double>::max());
    return;
  }
  // Usually one interval. A step longer than many intervals jumps in one go: stepping would
  // loop for ever once next + interval == next (an interval below the resolution of t).
  for (int k = 0; k < 8 && due(t); ++k)
    next += interval;
  if (due(t)) next = std::max(interval * (std::floor(t / interval) + 1.0), next);
  // An interval too short for t to tell apart: written at every cycle from here.
  if (due(t)) next = std::nextafter(t, std::numeric_limits<double>::max());
}

Outputs::Schedule Outputs::schedule(const model::ModelDatabase& m, const solver::State& s,
                                    double interval, model::Id curve) {
  Schedule sc{interval, nullptr, 0.0, -1.0};
  const solver::Index c = solver::detail::curve_index(m, curve);  // s.curves is in model order
  if (c >= 0) sc.interval_curve = &s.curves[static_cast<std::size_t>(c)];
  return sc;
}

namespace {
std::vector<solver::Index> history_nodes(const model::ModelDatabase& m) {
  std::vector<solver::Index> out;
  for (const model::HistoryNodes& h : m.outputs.history_nodes) {
    for (const model::Id id : h.ids) {
      if (h.is_set) {
        const auto set = solver::node_set_nodes(m, id);
        out.insert(out.end(), set.begin(), set.end());
      } else {
        const auto i = m.index.nodes.find(id);
        if (i != model::IdIndex::kNone) out.push_back(static_cast<solver::Index>(i));
      }
    }
  }
  return out;
}
}  // namespace

Outputs::Outputs(const model::ModelDatabase& m, const solver::State& s,
                 const std::filesystem::path& dir, std::vector<std::string>& notes,
                 const OutputsResume* resume) {
  if (m.outputs.d3plot) {
    const model::D3plotRequest& r = *m.outputs.d3plot;
    double dt = r.interval;
    if (dt <= 0.0 && r.plots > 0) dt = s.time_control.end_time / r.plots;
    if (dt > 0.0 || r.interval_curve != 0) {
      d3plot_ = std::make_unique<VtkSeries>(dir);
      binary_ = std::make_unique<d3plot::Database>(dir, resume ? &resume->family : nullptr);
      d3plot_schedule_ = schedule(m, s, dt, r.interval_curve);
      if (resume) {
        d3plot_->restore(resume->states);
        d3plot_schedule_.restore(resume->d3plot);
      }
    }
  }
  const HistoryPlace place{dir, resume ? &resume->histories : nullptr};
  const std::vector<solver::Index> nodes = history_nodes(m);
  for (const model::AsciiRequest& r : m.outputs.ascii) {
    if (r.interval <= 0.0 && r.interval_curve == 0) continue;
    const std::string name = model::ascii_database_name(r.database);
    if (name == "nodout" && nodes.empty()) {
      notes.push_back("nodout requested but no *DATABASE_HISTORY_NODE nodes: not written");
      continue;
    }
    if (name == "rcforc" && solver::history_records(s).contacts.empty()) {
      notes.push_back("rcforc requested but the deck has no contact: not written");
      continue;
    }
    auto h = make_history(name, place, s, nodes);
    if (!h) {
      notes.push_back(fmt::format("{} is not written by mcdyna", name));
      continue;
    }
    history_schedules_.push_back(schedule(m, s, r.interval, r.interval_curve));
    if (resume) {
      const std::size_t k = histories_.size();
      if (k >= resume->histories.size() || k >= resume->history_times.size() ||
          resume->histories[k].name != name)
        throw std::runtime_error("the restart dump's histories are not this deck's");
      h->continue_records(resume->histories[k]);
      history_schedules_.back().restore(resume->history_times[k]);
    }
    histories_.push_back(std::move(h));
  }
  if (resume && histories_.size() != resume->histories.size())
    throw std::runtime_error("the restart dump's histories are not this deck's");
}

OutputsResume Outputs::resume_point() const {
  OutputsResume r;
  if (d3plot_) {
    r.d3plot = d3plot_schedule_.times();
    r.states = d3plot_->entries();
    r.family = binary_->position();
  }
  for (std::size_t k = 0; k < histories_.size(); ++k) {
    r.history_times.push_back(history_schedules_[k].times());
    r.histories.push_back(histories_[k]->resume_point());
  }
  return r;
}

bool Outputs::due(const solver::State& s) const {
  if (d3plot_ && (d3plot_schedule_.due(s.time) || state_requested_)) return true;
  return std::any_of(history_schedules_.begin(), history_schedules_.end(),
                     [&](const Schedule& h) { return h.due(s.time); });
}

bool Outputs::state_due(const solver::State& s) const {
  return d3plot_ && (d3plot_schedule_.due(s.time) || state_requested_);
}

void Outputs::write(const solver::State& s, const Eigen::Matrix3Xd& previous, bool final,
                    double ns_per_cycle) {
  const Eigen::Matrix3Xd velocity = 0.5 * (previous + s.nodes.velocity);
  const solver::HistoryRecords records =
      histories_.empty() ? solver::HistoryRecords{} : solver::history_records(s);
  const OutputContext c{s, previous, velocity, records, ns_per_cycle};
  auto wanted = [&](const Schedule& sc) {
    return sc.due(s.time) || (final && sc.last_written != s.time);
  };
  if (d3plot_ && wanted(d3plot_schedule_)) {
    d3plot_->write(s, velocity);
    binary_->write(s, previous, velocity);
    d3plot_schedule_.advance(s.time);
  } else if (d3plot_ && state_requested_) {
    d3plot_->write(s, velocity);  // sw4: a state between the scheduled ones
    binary_->write(s, previous, velocity);
    d3plot_schedule_.last_written = s.time;
  }
  state_requested_ = false;
  for (std::size_t k = 0; k < histories_.size(); ++k) {
    if (!wanted(history_schedules_[k])) continue;
    histories_[k]->write(c);
    history_schedules_[k].advance(s.time);
  }
}

std::vector<std::string> Outputs::files() const {
  std::vector<std::string> out;
  if (d3plot_) out.push_back(fmt::format("d3plot.pvd ({} states)", d3plot_->states()));
  if (binary_)
    out.push_back(fmt::format("d3plot, d3plot01.. (LS-DYNA binary, {} states, {} file{})",
                              binary_->states(), binary_->position().member + 1,
                              binary_->position().member == 0 ? "" : "s"));
  for (const auto& h : histories_)
    out.push_back(h->name() + " (+ .csv)");
  return out;
}

}  // namespace mcdyna::io
