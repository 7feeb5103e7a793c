#pragma once
/// A block's part in *SENSOR_DEFINE_FORCE and *SENSOR_CONTROL (Block::sensed_force,
/// Block::switch_entity) for the entities of one kind it holds, each with an `id` and a
/// `switched_off` flag that its force pass reads.
#include "model/sensors.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::sensors {

/// The force `force_of(e)` of the entity `id` among `entities` when they are of the kind asked.
template <class Range, class ForceOf>
bool sensed_force_in(const Range& entities, model::SensedEntity held, model::SensedEntity kind,
                     model::Id id, ForceOf force_of, Vec3& force) {
  if (kind != held) return false;
  for (const auto& e : entities)
    if (e.id == id) {
      force = force_of(e);
      return true;
    }
  return false;
}

/// Switches every entity `id` among `entities` (when they are of the kind asked); false when
/// there is none.
template <class Range>
bool switch_in(Range&& entities, model::SensedEntity held, model::SensedEntity kind, model::Id id,
               bool on) {
  if (kind != held) return false;
  bool found = false;
  for (auto& e : entities)
    if (e.id == id) {
      e.switched_off = !on;
      found = true;
    }
  return found;
}

}  // namespace mcdyna::solver::sensors
