#pragma once
/// Sensors, switches and controls as the solver runs them (model/sensors.hpp has the deck's
/// words): at the end of every cycle each control watches its current switch, and a switch that
/// trips changes the control's entity from the next cycle on (sensor_block.cpp).
#include <cstddef>
#include <vector>

#include "model/sensors.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::sensors {

/// One sensor: a node's coordinate, velocity or acceleration, or an entity's force; the
/// component along `direction` (unit), or the magnitude.
struct Sensor {
  model::Id id = 0;
  bool on_node = true;
  Index node = -1;
  model::NodeQuantity quantity = model::NodeQuantity::acceleration;
  model::SensedEntity kind = model::SensedEntity::contact;
  model::Id target = 0;
  std::size_t block = 0;  ///< the block holding the entity (Block::link)
  bool magnitude = true;
  Vec3 direction = Vec3::UnitX();
  core::SourceLoc loc;
};

/// One switch: its sensor (or the time), its test and its timing.
struct Switch {
  model::Id id = 0;
  std::ptrdiff_t sensor = -1;  ///< into the block's sensors; -1: the time
  bool greater = false;
  double value = 0.0, window = 0.0, delay = 0.0;
};

/// What a control is at, dumped: its status, how far along its switches it is, and the times of
/// the current switch's test (-1 when not started).
struct ControlStatus {
  bool on = true;
  long switched = 0;         ///< switches tripped so far (over the repeats)
  double held_since = -1.0;  ///< the current switch's condition has held since then
  double changes_at = -1.0;  ///< tripped: the status changes at this time (TDELAY after)
};

/// One control: its entity, its switch sequence, and where it is.
struct Control {
  model::Id id = 0;
  model::SensedEntity kind = model::SensedEntity::contact;
  model::Id target = 0;
  std::size_t block = 0;  ///< the block holding the entity (Block::link)
  std::vector<std::size_t> switches;
  int repeats = 0;  ///< NREP; -1 without end
  core::SourceLoc loc;
  ControlStatus status;
  /// Whether another switch is still to come.
  [[nodiscard]] bool watching() const {
    if (switches.empty()) return false;
    if (repeats < 0) return true;
    return status.switched < static_cast<long>(switches.size()) * (repeats + 1L);
  }
  [[nodiscard]] std::size_t current() const {
    return switches[static_cast<std::size_t>(status.switched) % switches.size()];
  }
};

/// A status change, for the run's summary.
struct Change {
  model::Id control = 0;
  bool on = true;
  double time = 0.0;
};

/// Whether a switch's condition holds for `value`.
[[nodiscard]] inline bool holds(const Switch& w, double value) {
  return w.greater ? value > w.value : value < w.value;
}

/// Steps a control's watch of its current switch at time `t` with the switch's condition
/// `condition`: true when its status changes now (then `c.status` holds the new status and
/// the next switch).
bool advance(Control& c, const Switch& w, bool condition, double t);

}  // namespace mcdyna::solver::sensors
