#pragma once
/// What the planar and the geometric walls' blocks share (planar_walls.cpp, geometric_walls.cpp):
/// the walls they own, the work the walls took (glstat's stonewall energy), and their part in the
/// sensors (a wall's force, its switch). Derived adds the constraint, the wall lines and the dump.
#include <utility>
#include <vector>

#include "solver/block.hpp"
#include "solver/sensors/switchable.hpp"

namespace mcdyna::solver::walls {

template <class Wall, class Derived>
class WallsBlock : public DumpedBlock<Derived> {
 public:
  explicit WallsBlock(std::vector<Wall> walls) : walls_(std::move(walls)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    for (const Wall& w : walls_)
      e.stonewall += w.energy;
  }
  bool sensed_force(const State& /*s*/, model::SensedEntity kind, model::Id id,
                    Vec3& force) const override {
    return sensors::sensed_force_in(
        walls_, model::SensedEntity::rigid_wall, kind, id, [](const Wall& w) { return w.force; },
        force);
  }
  bool switch_entity(State& /*s*/, model::SensedEntity kind, model::Id id, bool on) override {
    return sensors::switch_in(walls_, model::SensedEntity::rigid_wall, kind, id, on);
  }
  [[nodiscard]] const std::vector<Wall>& walls() const { return walls_; }

 protected:
  std::vector<Wall> walls_;
};

}  // namespace mcdyna::solver::walls
