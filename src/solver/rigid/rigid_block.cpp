// The rigid bodies as one block of the time loop: each body sums its nodes' forces, advances its
// velocities under constraints and prescribed motion and sets its nodes' velocities; after the
// other nodes have moved it advances its centre and orientation and places its nodes. Over
// several processes every process advances every body (a few numbers each) from the exact sum
// of its owned nodes' forces over the processes, and places all of the body's nodes.
#include "solver/block.hpp"
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/rigid/welds.hpp"

namespace mcdyna::solver {

namespace {

class RigidBodiesBlock final : public Block {
 public:
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::rigid; }
  Index advance_velocities(State& s, const StepTimes& t) override {
    const Index bad = advance_rigid_bodies(s, t);
    if (!s.welds.empty()) check_welds(s, t);
    return bad;
  }
  void advance_positions(State& s, double dt) override { place_rigid_nodes(s, dt); }
};

}  // namespace

void add_rigid_body_blocks(State& s, Blocks& blocks) {
  if (!s.rigid_bodies.empty()) blocks.push_back(std::make_unique<RigidBodiesBlock>());
}

}  // namespace mcdyna::solver
