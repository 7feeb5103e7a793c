// A contact interface as a block of the time loop: its penalty, friction and damping forces at
// t^n, after every internal force (contact.hpp).
#include <algorithm>
#include <chrono>

#include "solver/block.hpp"
#include "solver/contact/contact.hpp"
#include "solver/parallel/owned_gather.hpp"

namespace mcdyna::solver {

namespace {

class ContactBlock final : public Block {
 public:
  explicit ContactBlock(std::size_t interface) : interface_(interface) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::contact; }
  void forces(State& s, ForceReport& /*report*/) override {
    if (s.ownership.comm.size() > 1) {
      const auto start = std::chrono::steady_clock::now();
      share_motion(s);
      exchange_seconds_ += spg::seconds_since(start);
    }
    contact::interface_pass(s, s.contacts[interface_]);
  }
  // The all-gather of the nodes' motion (and the wait for the slowest process) is exchange.
  void split_times(const State& /*s*/, PhaseTimes& phases) const override {
    phases.seconds[PhaseTimes::exchange] += exchange_seconds_;
    phases.seconds[PhaseTimes::contact] -= exchange_seconds_;
  }

 private:
  // Over several processes every process computes the whole interface, from the x and v of
  // every node in it, which their owners send to all (one all-gather per cycle). Rigid-body
  // nodes are placed alike by every process and are not sent. What each contact force does to
  // a node counts on the node's owner only (the others' copies of it are not used).
  void share_motion(State& s) {
    if (generation_ != s.ownership.generation) list_nodes(s);
    Eigen::Matrix3Xd& x = s.nodes.position;
    Eigen::Matrix3Xd& v = s.nodes.velocity;
    parallel::gather_owned(
        s.ownership.comm, nodes_.size(),
        [&](std::size_t k) { return s.ownership.owner[static_cast<std::size_t>(nodes_[k])]; },
        [&](std::size_t k, std::vector<double>& out) {
          out.insert(out.end(), x.col(nodes_[k]).data(), x.col(nodes_[k]).data() + 3);
          out.insert(out.end(), v.col(nodes_[k]).data(), v.col(nodes_[k]).data() + 3);
        },
        [&](std::size_t k, const double*& in) {
          std::copy(in, in + 3, x.col(nodes_[k]).data());
          std::copy(in + 3, in + 6, v.col(nodes_[k]).data());
          in += 6;
        });
  }

  // The interface's deformable nodes, ascending.
  void list_nodes(const State& s) {
    const contact::Interface& c = s.contacts[interface_];
    std::vector<std::uint8_t> in(static_cast<std::size_t>(s.nodes.count()), 0);
    auto mark = [&](Index n) { in[static_cast<std::size_t>(n)] = 1; };
    for (const Index n : c.tracked)
      mark(n);
    for (const contact::Pass& p : c.passes) {
      for (const Index n : p.nodes)
        mark(n);
      for (const auto& segment : p.surface.segments)
        for (const Index n : segment)
          mark(n);
    }
    nodes_.clear();
    for (Index n = 0; n < s.nodes.count(); ++n)
      if (in[static_cast<std::size_t>(n)] && s.nodes.rigid_body[static_cast<std::size_t>(n)] < 0)
        nodes_.push_back(n);
    generation_ = s.ownership.generation;
  }

  std::size_t interface_;
  std::vector<Index> nodes_;
  long generation_ = -1;
  double exchange_seconds_ = 0.0;
};

}  // namespace

void add_contact_blocks(State& s, Blocks& blocks) {
  for (std::size_t k = 0; k < s.contacts.size(); ++k)
    blocks.push_back(std::make_unique<ContactBlock>(k));
}

}  // namespace mcdyna::solver
