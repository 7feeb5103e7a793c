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
    contact::Interface& c = s.contacts[interface_];
    if (s.ownership.comm.size() == 1) {
      contact::interface_pass(s, c, contact::sort_due(s, c));
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    if (generation_ != s.ownership.generation) list_nodes(s);
    if (near_sort_ != c.last_sort) list_near_nodes(s);
    const bool sort = contact::sort_due(s, c);
    share_motion(s, sort ? nodes_ : near_nodes_);
    exchange_seconds_ += spg::seconds_since(start);
    contact::interface_pass(s, c, sort);
  }
  // The all-gather of the nodes' motion (and the wait for the slowest process) is exchange.
  void split_times(const State& /*s*/, PhaseTimes& phases) const override {
    phases.seconds[PhaseTimes::exchange] += exchange_seconds_;
    phases.seconds[PhaseTimes::contact] -= exchange_seconds_;
  }

 private:
  // Over several processes every process applies every hit, as one process does, and the
  // owners of the slave nodes compute them. At a bucket sort every process sorts the whole
  // interface, from the x and v of every node in it; between sorts it needs those of the nodes
  // that can be hit (the sort's `near` nodes) and of the deformable segment nodes. Their owners
  // send them to all (one all-gather per cycle). Rigid-body nodes are placed alike by every
  // process and are not sent. What each contact force does to a node counts on the node's
  // owner only (the others' copies of it are not used).
  void share_motion(State& s, const std::vector<Index>& nodes) {
    Eigen::Matrix3Xd& x = s.nodes.position;
    Eigen::Matrix3Xd& v = s.nodes.velocity;
    parallel::gather_owned(
        s.ownership.comm, nodes.size(),
        [&](std::size_t k) { return s.ownership.owner[static_cast<std::size_t>(nodes[k])]; },
        [&](std::size_t k, std::vector<double>& out) {
          out.insert(out.end(), x.col(nodes[k]).data(), x.col(nodes[k]).data() + 3);
          out.insert(out.end(), v.col(nodes[k]).data(), v.col(nodes[k]).data() + 3);
        },
        [&](std::size_t k, const double*& in) {
          std::copy(in, in + 3, x.col(nodes[k]).data());
          std::copy(in + 3, in + 6, v.col(nodes[k]).data());
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

  // The deformable nodes a cycle between sorts reads: the passes' near nodes and the segments'
  // nodes, ascending.
  void list_near_nodes(const State& s) {
    const contact::Interface& c = s.contacts[interface_];
    std::vector<std::uint8_t> in(static_cast<std::size_t>(s.nodes.count()), 0);
    for (const contact::Pass& p : c.passes) {
      for (const Index k : p.near)
        in[static_cast<std::size_t>(p.nodes[static_cast<std::size_t>(k)])] = 1;
      for (const auto& segment : p.surface.segments)
        for (const Index n : segment)
          in[static_cast<std::size_t>(n)] = 1;
    }
    near_nodes_.clear();
    for (const Index n : nodes_)
      if (in[static_cast<std::size_t>(n)]) near_nodes_.push_back(n);
    near_sort_ = c.last_sort;
  }

  std::size_t interface_;
  std::vector<Index> nodes_, near_nodes_;
  long near_sort_ = -2;  ///< the interface's last sort when near_nodes_ was listed
  long generation_ = -1;
  double exchange_seconds_ = 0.0;
};

// A force transducer: applies nothing, reads what the contact blocks before it applied.
class TransducerBlock final : public Block {
 public:
  explicit TransducerBlock(std::size_t interface) : interface_(interface) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::contact; }
  void forces(State& s, ForceReport& /*report*/) override {
    contact::transducer_pass(s, s.contacts[interface_]);
  }

 private:
  std::size_t interface_;
};

}  // namespace

void add_contact_blocks(State& s, Blocks& blocks) {
  for (std::size_t k = 0; k < s.contacts.size(); ++k)
    if (!s.contacts[k].sensor.active) blocks.push_back(std::make_unique<ContactBlock>(k));
  // After every contact, whatever the deck order.
  for (std::size_t k = 0; k < s.contacts.size(); ++k)
    if (s.contacts[k].sensor.active) blocks.push_back(std::make_unique<TransducerBlock>(k));
}

}  // namespace mcdyna::solver
