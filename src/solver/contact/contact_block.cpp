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

 private:
  std::size_t interface_;
};

}  // namespace

void add_contact_blocks(State& s, Blocks& blocks) {
  for (std::size_t k = 0; k < s.contacts.size(); ++k)
    blocks.push_back(std::make_unique<ContactBlock>(k));
}

}  // namespace mcdyna::solver
