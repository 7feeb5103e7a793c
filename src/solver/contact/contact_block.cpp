// A contact interface as a block of the time loop: its penalty, friction and damping forces at
// t^n, after every internal force (contact.hpp).
#include "solver/block.hpp"
#include "solver/contact/contact.hpp"

namespace mcdyna::solver {

namespace {

class ContactBlock final : public Block {
 public:
  explicit ContactBlock(std::size_t interface) : interface_(interface) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::contact; }
  void forces(State& s, ForceReport& /*report*/) override {
    contact::interface_pass(s, s.contacts[interface_]);
  }
  void mark_replicated(const State& s, std::vector<std::uint8_t>& nodes) const override {
    const contact::Interface& c = s.contacts[interface_];
    auto mark = [&](Index n) { nodes[static_cast<std::size_t>(n)] = 1; };
    for (const Index n : c.tracked)
      mark(n);
    for (const contact::Pass& p : c.passes) {
      for (const Index n : p.nodes)
        mark(n);
      for (const auto& segment : p.surface.segments)
        for (const Index n : segment)
          mark(n);
    }
  }

 private:
  std::size_t interface_;
};

}  // namespace

void add_contact_blocks(State& s, Blocks& blocks) {
  for (std::size_t k = 0; k < s.contacts.size(); ++k)
    blocks.push_back(std::make_unique<ContactBlock>(k));
}

}  // namespace mcdyna::solver
