// The velocity-level conditions (SPC and *NODE TC, prescribed nodal motion, rigid walls) and the
// body loads as blocks of the time loop (loads.hpp).
#include "solver/block.hpp"
#include "solver/loads/loads.hpp"

namespace mcdyna::solver {

namespace {

// A condition applied by one of loads.hpp's functions in the constraint phase.
class ConditionBlock final : public Block {
 public:
  using Apply = void (*)(State&, const StepTimes&);
  explicit ConditionBlock(Apply apply) : apply_(apply) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void constrain(State& s, const StepTimes& t) override { apply_(s, t); }

 private:
  Apply apply_;
};

class BodyLoadsBlock final : public Block {
 public:
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void forces(State& s, ForceReport& /*report*/) override { apply_body_loads(s); }
};

}  // namespace

void add_nodal_constraint_blocks(State& s, Blocks& blocks) {
  if (!s.constraints.nodes.empty())
    blocks.push_back(std::make_unique<ConditionBlock>(apply_nodal_constraints));
}

void add_nodal_motion_blocks(State& s, Blocks& blocks) {
  if (!s.nodal_motions.empty())
    blocks.push_back(std::make_unique<ConditionBlock>(apply_nodal_motions));
}

void add_rigid_wall_blocks(State& s, Blocks& blocks) {
  if (!s.rigid_walls.empty()) blocks.push_back(std::make_unique<ConditionBlock>(apply_rigid_walls));
}

void add_body_load_blocks(State& s, Blocks& blocks) {
  if (!s.body_loads.empty()) blocks.push_back(std::make_unique<BodyLoadsBlock>());
}

}  // namespace mcdyna::solver
