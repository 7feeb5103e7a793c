// The sensors' cross-checks: their IDs (sensors, switches and controls each have their own), the
// nodes, vectors, sensors and switches they name. The contacts, walls, motions and joints that
// force sensors read and controls switch are found by the solver, which numbers them
// (solver/sensors/, Block::link).
#include <fmt/format.h>

#include "model/checks.hpp"

namespace mcdyna::model::detail {

namespace {

void need(bool found, const core::SourceLoc& loc, const char* user, model::Id user_id,
          const char* what, model::Id id, core::Diagnostics& diags) {
  if (!found)
    diags.error(loc, "{} {} refers to {} {}, which is not defined", user, user_id, what, id);
}

}  // namespace

void check_sensors(const ModelDatabase& m, core::Diagnostics& diags) {
  const Sensors& s = m.sensors;
  // Node and force sensors share one ID space (a switch names a sensor by SENSID alone).
  IdIndex node_sensors, force_sensors, switches, controls;
  index_one(node_sensors, s.nodes, "sensor", diags);
  index_one(force_sensors, s.forces, "sensor", diags);
  index_one(switches, s.switches, "*SENSOR_SWITCH", diags);
  index_one(controls, s.controls, "*SENSOR_CONTROL", diags);
  for (const ForceSensor& f : s.forces)
    if (node_sensors.contains(f.id))
      diags.error(f.loc, "sensor {} is defined twice (also a *SENSOR_DEFINE_NODE)", f.id);

  for (const NodeSensor& n : s.nodes) {
    need(m.index.nodes.contains(n.node), n.node_loc, "*SENSOR_DEFINE_NODE", n.id, "node", n.node,
         diags);
    if (n.direction.vector != 0)
      need(m.index.vectors.contains(n.direction.vector), n.vector_loc, "*SENSOR_DEFINE_NODE", n.id,
           "vector", n.direction.vector, diags);
  }
  for (const ForceSensor& f : s.forces)
    if (f.direction.vector != 0)
      need(m.index.vectors.contains(f.direction.vector), f.vector_loc, "*SENSOR_DEFINE_FORCE", f.id,
           "vector", f.direction.vector, diags);
  for (const SensorSwitch& w : s.switches)
    if (!w.on_time)
      need(node_sensors.contains(w.sensor) || force_sensors.contains(w.sensor), w.sensor_loc,
           "*SENSOR_SWITCH", w.id, "sensor", w.sensor, diags);
  for (const SensorControl& c : s.controls)
    for (const Id w : c.switches)
      need(switches.contains(w), c.switches_loc, "*SENSOR_CONTROL", c.id, "switch", w, diags);
  if (s.controls.empty() && (!s.nodes.empty() || !s.forces.empty()))
    diags.note(!s.nodes.empty() ? s.nodes.front().loc : s.forces.front().loc,
               "the sensors act only through *SENSOR_SWITCH and *SENSOR_CONTROL, and this deck "
               "has no *SENSOR_CONTROL: they change nothing");
}

}  // namespace mcdyna::model::detail
