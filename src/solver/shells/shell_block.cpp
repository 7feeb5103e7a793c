// The deformable shells as one block of the time loop: the element pass and the gather of the
// corner forces and moments into the nodes.
#include "solver/block.hpp"
#include "solver/fe/added_mass.hpp"
#include "solver/shells/shell_elements.hpp"

namespace mcdyna::solver {

namespace {

class ShellsBlock final : public Block {
 public:
  explicit ShellsBlock(long count) : count_(count) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return count_; }

  // Every process computes the shells whole (and so moves their nodes itself): the same bits
  // for any process count, without a share of the work.
  void mark_replicated(const State& s, std::vector<std::uint8_t>& nodes) const override {
    for (const auto& conn : s.shells.nodes)
      for (const Index n : conn)
        nodes[static_cast<std::size_t>(n)] = 1;
  }

  void forces(State& s, ForceReport& r) override {
    const ElementPassResult e = shell_element_pass(
        s, ShellPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
    gather_shell_forces(s);
    if (e.mass_changed) refresh_added_mass(s);
    // Elements are numbered solids first, then shells (block.hpp).
    const Index offset = s.solids.count();
    if (e.critical_step < r.critical_step) {
      r.critical_step = e.critical_step;
      r.controlling_element = offset + e.controlling;
      r.controlling_particle = -1;
    }
    if (e.inverted >= 0)
      r.fail("zero or negative area in " + element_name(s, offset + e.inverted), true);
    else if (e.non_finite >= 0)
      r.fail("non-finite stress or step in " + element_name(s, offset + e.non_finite), false);
    else if (e.runaway >= 0)
      r.fail(runaway_message(s, offset + e.runaway, "area"), false);
  }

 private:
  long count_;
};

}  // namespace

void add_shell_blocks(State& s, Blocks& blocks) {
  if (s.shells.count() > 0) blocks.push_back(std::make_unique<ShellsBlock>(s.shells.count()));
}

}  // namespace mcdyna::solver
