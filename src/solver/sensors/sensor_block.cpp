// *SENSOR_DEFINE_NODE / _FORCE, *SENSOR_SWITCH and *SENSOR_CONTROL as one block, last in the
// loop: at the end of each cycle (x^{n+1}, v^{n+1/2}, a^n and this cycle's forces, at t^{n+1})
// it reads its sensors, steps each control's watch of its current switch, and switches the
// control's entity in the block that holds it (Block::switch_entity), from the next cycle on.
// Over several processes every process reads the same values (the sensed nodes are moved by
// every process, the forces are sums over the processes), so all switch at the same cycle.
#include <fmt/format.h>

#include <algorithm>

#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/sensors/sensors.hpp"

namespace mcdyna::solver::sensors {

bool advance(Control& c, const Switch& w, bool condition, double t) {
  ControlStatus& st = c.status;
  if (st.changes_at < 0.0) {
    if (!condition) {
      st.held_since = -1.0;
      return false;
    }
    if (st.held_since < 0.0) st.held_since = t;
    if (t - st.held_since < w.window) return false;
    st.changes_at = t + w.delay;
  }
  if (t < st.changes_at) return false;
  st.on = !st.on;
  ++st.switched;
  st.held_since = -1.0;
  st.changes_at = -1.0;
  return true;
}

template <class Ar>
void fields(Ar& ar, ControlStatus& c) {
  ar(c.on, c.switched, c.held_since, c.changes_at);
}

template <class Ar>
void fields(Ar& ar, Change& c) {
  ar(c.control, c.on, c.time);
}

inline constexpr auto kSensorDumpedSizes = core::sizes_of<ControlStatus, Change>();
static_assert(!core::kSizesPinned || kSensorDumpedSizes == decltype(kSensorDumpedSizes){32, 24},
              "ControlStatus or Change changed: list the new member in fields() above");

namespace {

// The block holding entity `kind` `id`: its place in `all`, or all.size().
std::size_t holder(State& s, const Blocks& all, model::SensedEntity kind, model::Id id,
                   bool to_switch) {
  for (std::size_t b = 0; b < all.size(); ++b) {
    Vec3 unused;
    // Asking a block to switch an entity to the status it has is how a control finds it
    // without changing it: link() sets the initial status right after.
    if (to_switch ? all[b]->switch_entity(s, kind, id, true)
                  : all[b]->sensed_force(s, kind, id, unused))
      return b;
  }
  return all.size();
}

class SensorBlock final : public DumpedBlock<SensorBlock> {
 public:
  SensorBlock(std::vector<Sensor> sensors, std::vector<Switch> switches,
              std::vector<Control> controls)
      : sensors_(std::move(sensors)),
        switches_(std::move(switches)),
        controls_(std::move(controls)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }

  void link(State& s, const Blocks& all, core::Diagnostics& d) override {
    for (Sensor& x : sensors_) {
      if (x.on_node) continue;
      x.block = holder(s, all, x.kind, x.target, false);
      if (x.block == all.size())
        d.error(x.loc, "*SENSOR_DEFINE_FORCE {}: there is no {} {} to read the force of{}", x.id,
                model::sensed_entity_keyword(x.kind), x.target, absent_hint(x.kind));
    }
    for (Control& c : controls_) {
      c.block = holder(s, all, c.kind, c.target, true);
      if (c.block == all.size()) {
        d.error(c.loc, "*SENSOR_CONTROL {}: there is no {} {} to switch{}", c.id,
                model::sensed_entity_keyword(c.kind), c.target, absent_hint(c.kind));
        continue;
      }
      all[c.block]->switch_entity(s, c.kind, c.target, c.status.on);
    }
  }

  // The sensed nodes, and the nodes of a sensed prescribed motion, are moved by every process.
  void mark_replicated(const State& s, std::vector<std::uint8_t>& nodes) const override {
    for (const Sensor& x : sensors_) {
      if (x.on_node)
        nodes[static_cast<std::size_t>(x.node)] = 1;
      else
        s.blocks[x.block]->mark_entity_nodes(x.kind, x.target, nodes);
    }
  }

  void advance_positions(State& s, double dt) override {
    const double t = s.time + dt;
    for (Control& c : controls_) {
      if (!c.watching()) continue;
      const Switch& w = switches_[c.current()];
      const double value = w.sensor < 0 ? t : read(s, sensors_[static_cast<std::size_t>(w.sensor)]);
      if (!advance(c, w, holds(w, value), t)) continue;
      s.blocks[c.block]->switch_entity(s, c.kind, c.target, c.status.on);
      changes_.push_back({c.id, c.status.on, t});
    }
  }

  void add_notes(const State& /*s*/, std::vector<std::string>& notes) const override {
    for (const Change& ch : changes_) {
      const Control& c = *std::find_if(controls_.begin(), controls_.end(),
                                       [&](const Control& k) { return k.id == ch.control; });
      notes.push_back(fmt::format("sensor control {}: {} {} switched {} at t = {:.6e}", c.id,
                                  model::sensed_entity_keyword(c.kind), c.target,
                                  ch.on ? "on" : "off", ch.time));
    }
  }

  [[nodiscard]] std::string dump_name() const override { return "sensor controls"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kSensorDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    for (Control& c : controls_)
      ar(c.status);
    ar(changes_);
  }

 private:
  static const char* absent_hint(model::SensedEntity kind) {
    if (kind == model::SensedEntity::prescribed_motion)
      return " (a *BOUNDARY_PRESCRIBED_MOTION_NODE or _SET with that ID on its _ID card; the "
             "motions of rigid bodies are not read or switched)";
    return "";
  }

  double read(const State& s, const Sensor& x) const {
    Vec3 v = Vec3::Zero();
    if (x.on_node) {
      const Nodes& nd = s.nodes;
      switch (x.quantity) {
        case model::NodeQuantity::coordinate:
          v = nd.position.col(x.node);
          break;
        case model::NodeQuantity::velocity:
          v = nd.velocity.col(x.node);
          break;
        case model::NodeQuantity::acceleration:
          v = nd.acceleration.col(x.node);
          break;
      }
    } else {
      s.blocks[x.block]->sensed_force(s, x.kind, x.target, v);
    }
    return x.magnitude ? v.norm() : v.dot(x.direction);
  }

  std::vector<Sensor> sensors_;
  std::vector<Switch> switches_;
  std::vector<Control> controls_;
  std::vector<Change> changes_;
};

Sensor make_sensor(const model::ModelDatabase& m, const model::SensorDirection& dir,
                   const core::SourceLoc& vector_loc, core::Diagnostics& d) {
  Sensor x;
  x.magnitude = dir.magnitude;
  if (dir.axis >= 0) x.direction = Vec3::Unit(dir.axis);
  if (dir.vector != 0) x.direction = detail::vector_direction(m, dir.vector, vector_loc, d);
  return x;
}

}  // namespace

}  // namespace mcdyna::solver::sensors

namespace mcdyna::solver::detail {

void compile_sensors(const model::ModelDatabase& m, State& /*s*/, const CompiledBlocks& /*before*/,
                     Blocks& own, core::Diagnostics& d) {
  using namespace sensors;
  const model::Sensors& in = m.sensors;
  if (in.empty()) return;
  std::vector<Sensor> list;
  for (const model::NodeSensor& n : in.nodes) {
    Sensor x = make_sensor(m, n.direction, n.vector_loc, d);
    x.id = n.id;
    x.node = static_cast<Index>(m.index.nodes.find(n.node));
    x.quantity = n.quantity;
    x.loc = n.loc;
    list.push_back(x);
  }
  for (const model::ForceSensor& f : in.forces) {
    Sensor x = make_sensor(m, f.direction, f.vector_loc, d);
    x.id = f.id;
    x.on_node = false;
    x.kind = f.kind;
    x.target = f.target;
    x.loc = f.loc;
    list.push_back(x);
  }
  auto sensor_index = [&](model::Id id) {
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const Sensor& x) { return x.id == id; });
    return static_cast<std::ptrdiff_t>(it - list.begin());
  };
  std::vector<Switch> switches;
  for (const model::SensorSwitch& w : in.switches)
    switches.push_back(
        {w.id, w.on_time ? -1 : sensor_index(w.sensor), w.greater, w.value, w.window, w.delay});
  std::vector<Control> controls;
  for (const model::SensorControl& c : in.controls) {
    Control k;
    k.id = c.id;
    k.kind = c.kind;
    k.target = c.target;
    k.repeats = c.repeats;
    k.loc = c.loc;
    k.status.on = c.initially_on;
    for (const model::Id w : c.switches) {
      const auto it = std::find_if(switches.begin(), switches.end(),
                                   [&](const Switch& x) { return x.id == w; });
      k.switches.push_back(static_cast<std::size_t>(it - switches.begin()));
    }
    controls.push_back(std::move(k));
  }
  own.push_back(
      std::make_unique<SensorBlock>(std::move(list), std::move(switches), std::move(controls)));
}

}  // namespace mcdyna::solver::detail
