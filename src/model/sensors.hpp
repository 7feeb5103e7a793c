#pragma once
/// Sensors (*SENSOR_DEFINE_NODE / _FORCE), the switches that watch them or the clock
/// (*SENSOR_SWITCH) and the controls that turn entities on and off when switches trip
/// (*SENSOR_CONTROL), as the deck gives them. solver/sensors/ runs them.
#include <array>
#include <string>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::model {

/// The entities a force sensor reads and a control switches (FTYPE, TYPE).
enum class SensedEntity { contact, rigid_wall, prescribed_motion, joint };

/// LS-DYNA's name of an entity kind (FTYPE / TYPE).
constexpr const char* sensed_entity_keyword(SensedEntity kind) {
  switch (kind) {
    case SensedEntity::contact:
      return "CONTACT";
    case SensedEntity::rigid_wall:
      return "RWALL";
    case SensedEntity::prescribed_motion:
      return "PRESC-MOT";
    case SensedEntity::joint:
      return "JOINT";
  }
  return "?";
}

/// What a sensor measures of its node or force: a component along a direction, or the length.
struct SensorDirection {
  bool magnitude = true;
  Id vector = 0;  ///< *DEFINE_VECTOR (0: an axis or the magnitude)
  int axis = -1;  ///< 0 x, 1 y, 2 z (global); -1 with a vector or the magnitude
};

enum class NodeQuantity { acceleration, velocity, coordinate };

/// *SENSOR_DEFINE_NODE: NODE1's coordinate, velocity or acceleration.
struct NodeSensor {
  Id id = 0;
  Id node = 0;
  NodeQuantity quantity = NodeQuantity::acceleration;
  SensorDirection direction;
  core::SourceLoc loc, node_loc, vector_loc;
};

/// *SENSOR_DEFINE_FORCE: the force an entity takes or applies this cycle.
struct ForceSensor {
  Id id = 0;
  SensedEntity kind = SensedEntity::contact;
  Id target = 0;  ///< TYPEID
  SensorDirection direction;
  core::SourceLoc loc, target_loc, vector_loc;
};

/// *SENSOR_SWITCH: trips when its sensor's value (or the time) has been below (LT) or above (GT)
/// VALUE for TIMWIN; the control it drives changes TDELAY later.
struct SensorSwitch {
  Id id = 0;
  bool on_time = false;  ///< TYPE TIME: the value is the time
  Id sensor = 0;
  bool greater = false;  ///< LOGIC GT (LT otherwise)
  double value = 0.0;
  double window = 0.0;  ///< TIMWIN
  double delay = 0.0;   ///< TDELAY
  core::SourceLoc loc, sensor_loc;
};

/// *SENSOR_CONTROL: an entity's status, INITSTT first, changed by SWIT1, then SWIT2, ...; the
/// sequence repeats NREP more times (-1: without end).
struct SensorControl {
  Id id = 0;
  SensedEntity kind = SensedEntity::contact;
  Id target = 0;  ///< TYPEID
  bool initially_on = true;
  std::vector<Id> switches;
  int repeats = 0;
  core::SourceLoc loc, target_loc, switches_loc;
};

struct Sensors {
  std::vector<NodeSensor> nodes;
  std::vector<ForceSensor> forces;
  std::vector<SensorSwitch> switches;
  std::vector<SensorControl> controls;
  [[nodiscard]] bool empty() const { return controls.empty(); }
};

}  // namespace mcdyna::model
