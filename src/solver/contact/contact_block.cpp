// A contact interface as a block of the time loop: its penalty, friction and damping forces at
// t^n, after every internal force (contact.hpp).
#include <algorithm>
#include <chrono>
#include <span>

#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/contact/contact.hpp"
#include "solver/contact/interface_dump.hpp"
#include "solver/parallel/exchange_plan.hpp"
#include "solver/parallel/owned_gather.hpp"
#include "solver/sensors/switchable.hpp"
#include "solver/spg/domain.hpp"

namespace mcdyna::solver {

namespace {

// A node's x and v, 6 doubles, as the contact exchanges send them.
void pack_motion(const State& s, Index n, double* out) {
  std::copy_n(s.nodes.position.col(n).data(), 3, out);
  std::copy_n(s.nodes.velocity.col(n).data(), 3, out + 3);
}
void unpack_motion(State& s, Index n, const double* in) {
  std::copy_n(in, 3, s.nodes.position.col(n).data());
  std::copy_n(in + 3, 3, s.nodes.velocity.col(n).data());
}

// An interface's block: it owns the interface (contact::Interface), its dump section, named by
// its place among the deck's contacts (`order_`, as rcforc lists them).
template <class Derived>
class InterfaceBlock : public DumpedBlock<Derived> {
 public:
  InterfaceBlock(contact::Interface interface, std::size_t order)
      : interface_(std::move(interface)), order_(order) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::contact; }
  [[nodiscard]] const contact::Interface& interface() const { return interface_; }
  [[nodiscard]] std::size_t order() const { return order_; }
  [[nodiscard]] std::string dump_name() const override {
    return fmt::format("contact interface {}", order_ + 1);
  }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(contact::kInterfaceDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(interface_);
  }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    e.sliding += interface_.energy;
  }
  // A contact's force is side A's (rcforc's slave line).
  bool sensed_force(const State& /*s*/, model::SensedEntity kind, model::Id id,
                    Vec3& force) const override {
    return sensors::sensed_force_in(
        std::span(&interface_, 1), model::SensedEntity::contact, kind, id,
        [](const contact::Interface& c) { return c.force_a; }, force);
  }
  bool switch_entity(State& /*s*/, model::SensedEntity kind, model::Id id, bool on) override {
    return sensors::switch_in(std::span(&interface_, 1), model::SensedEntity::contact, kind, id,
                              on);
  }
  // rcforc: side A is the slave line, side B the master line.
  void add_history_records(const State& /*s*/, HistoryRecords& out) const override {
    const contact::Interface& c = interface_;
    out.contacts.push_back(
        {c.id, c.heading, order_, c.force_a, c.moment_a, c.force_b, c.moment_b, c.mass_in_contact});
  }

 protected:
  contact::Interface interface_;
  std::size_t order_;
};

class ContactBlock final : public InterfaceBlock<ContactBlock> {
 public:
  using InterfaceBlock::InterfaceBlock;
  void forces(State& s, NodalForces& f, ForceReport& /*report*/) override {
    contact::Interface& c = interface_;
    if (s.ownership.comm.size() == 1) {
      contact::interface_pass(s, c, contact::sort_due(s, c), f.force, exchange_seconds_);
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    if (generation_ != s.ownership.generation) follow_owners(s);
    const bool sort = contact::sort_due(s, c);
    if (sort)
      share_segment_nodes(s);
    else
      segment_ghosts_.exchange([&](Index n, double* out) { pack_motion(s, n, out); },
                               [&](Index n, const double* in) { unpack_motion(s, n, in); });
    exchange_seconds_ += spg::seconds_since(start);
    contact::interface_pass(s, c, sort, f.force, exchange_seconds_);
    if (sort) plan_segment_ghosts(s);
  }
  // The exchanges of the nodes' motion (and the wait for the slowest process) are exchange.
  void split_times(const State& /*s*/, PhaseTimes& phases) const override {
    phases.seconds[PhaseTimes::exchange] += exchange_seconds_;
    phases.seconds[PhaseTimes::contact] -= exchange_seconds_;
  }
  void add_contact_nodes(std::vector<Index>& nodes) const override {
    for (const contact::Pass& p : interface_.passes)
      nodes.insert(nodes.end(), p.nodes.begin(), p.nodes.end());
  }

 private:
  // Over several processes each process computes the hits of the slave nodes it owns, from
  // candidates it sorted for those nodes only, and the owner of every node adds the forces on
  // it in the order of one process (contact_forces.cpp). It reads the x and v of its own slave
  // nodes and of the segment nodes: rigid-body nodes are placed alike by every process; the
  // deformable segment nodes come from their owners, all of them to every process at a bucket
  // sort (the boxes of every segment), between sorts those its candidates hold
  // (`segment_ghosts_`, point to point). What a slave node carries from cycle to cycle
  // (friction, side, initial penetration, candidates, position at the last sort) goes with it
  // when a renewal gives it another owner.
  void share_segment_nodes(State& s) {
    parallel::gather_owned(
        s.ownership.comm, segment_nodes_.size(),
        [&](std::size_t k) {
          return s.ownership.owner[static_cast<std::size_t>(segment_nodes_[k])];
        },
        [&](std::size_t k, std::vector<double>& out) {
          out.resize(out.size() + 6);
          pack_motion(s, segment_nodes_[k], out.data() + out.size() - 6);
        },
        [&](std::size_t k, const double*& in) {
          unpack_motion(s, segment_nodes_[k], in);
          in += 6;
        });
  }

  // The deformable segment nodes the candidates of this process's slave nodes hold that
  // another process owns. Collective.
  void plan_segment_ghosts(const State& s) {
    const contact::Interface& c = interface_;
    std::vector<std::uint8_t> ghost(static_cast<std::size_t>(s.nodes.count()), 0);
    for (const contact::Pass& p : c.passes)
      for (const Index k : p.near) {
        const auto i = static_cast<std::size_t>(k);
        if (!s.ownership.owned_now(p.nodes[i])) continue;
        for (Index q = p.candidate_offsets[i]; q < p.candidate_offsets[i + 1]; ++q)
          for (const Index n : p.surface.segments[static_cast<std::size_t>(p.candidates[q])])
            if (!s.ownership.owned_now(n) && s.nodes.rigid_body[static_cast<std::size_t>(n)] < 0)
              ghost[static_cast<std::size_t>(n)] = 1;
      }
    segment_ghosts_ = parallel::ExchangePlan(s.ownership.comm, s.ownership.owner, ghost, 6);
  }

  // The interface's deformable segment nodes, ascending; the slave nodes' state handed to their
  // new owners when the owners changed; the ghosts planned again. Collective.
  void follow_owners(State& s) {
    contact::Interface& c = interface_;
    if (generation_ >= 0) hand_over(s, c);
    std::vector<std::uint8_t> in(static_cast<std::size_t>(s.nodes.count()), 0);
    for (const contact::Pass& p : c.passes)
      for (const auto& segment : p.surface.segments)
        for (const Index n : segment)
          in[static_cast<std::size_t>(n)] = 1;
    segment_nodes_.clear();
    for (Index n = 0; n < s.nodes.count(); ++n)
      if (in[static_cast<std::size_t>(n)] && s.nodes.rigid_body[static_cast<std::size_t>(n)] < 0)
        segment_nodes_.push_back(n);
    owner_ = s.ownership.owner;
    generation_ = s.ownership.generation;
    plan_segment_ghosts(s);
  }

  // Each slave node that leaves this process sends its new owner what it carries between
  // cycles: per pass node [0, pass, index, friction 3, side 3, initial, count, candidates...],
  // per tracked node [1, index, position at the last sort 3]. Collective.
  void hand_over(State& s, contact::Interface& c) {
    const int me = s.ownership.comm.rank();
    const std::vector<int>& now = s.ownership.owner;
    auto leaves = [&](Index n) {
      const auto k = static_cast<std::size_t>(n);
      return owner_[k] == me && now[k] != me;
    };
    std::vector<std::vector<double>> to(static_cast<std::size_t>(s.ownership.comm.size()));
    for (std::size_t pass = 0; pass < c.passes.size(); ++pass) {
      const contact::Pass& p = c.passes[pass];
      for (const Index k : p.near) {
        const auto i = static_cast<std::size_t>(k);
        const Index node = p.nodes[i];
        if (!leaves(node)) continue;
        std::vector<double>& out =
            to[static_cast<std::size_t>(now[static_cast<std::size_t>(node)])];
        out.insert(out.end(), {0.0, static_cast<double>(pass), static_cast<double>(i)});
        out.insert(out.end(), p.friction.col(k).data(), p.friction.col(k).data() + 3);
        out.insert(out.end(), p.side.col(k).data(), p.side.col(k).data() + 3);
        out.push_back(p.initial_penetration[i]);
        out.push_back(static_cast<double>(p.candidate_offsets[i + 1] - p.candidate_offsets[i]));
        for (Index q = p.candidate_offsets[i]; q < p.candidate_offsets[i + 1]; ++q)
          out.push_back(static_cast<double>(p.candidates[static_cast<std::size_t>(q)]));
      }
    }
    for (std::size_t t = 0; t < c.tracked.size(); ++t) {
      const Index node = c.tracked[t];
      if (!leaves(node) || s.nodes.rigid_body[static_cast<std::size_t>(node)] >= 0) continue;
      std::vector<double>& out = to[static_cast<std::size_t>(now[static_cast<std::size_t>(node)])];
      out.insert(out.end(), {1.0, static_cast<double>(t)});
      const auto col = static_cast<Eigen::Index>(t);
      out.insert(out.end(), c.sorted_positions.col(col).data(),
                 c.sorted_positions.col(col).data() + 3);
    }
    const std::vector<std::vector<double>> from = s.ownership.comm.all_to_all(to);
    // The candidates of each pass's nodes under the new owners: kept for the nodes this
    // process still owns, received for those it gained, none for the others.
    std::vector<std::vector<std::vector<Index>>> gained(c.passes.size());
    for (std::size_t pass = 0; pass < c.passes.size(); ++pass)
      gained[pass].resize(c.passes[pass].nodes.size());
    for (const std::vector<double>& in : from)
      for (std::size_t k = 0; k < in.size();) {
        if (in[k] == 1.0) {
          const auto col = static_cast<Eigen::Index>(in[k + 1]);
          std::copy_n(&in[k + 2], 3, c.sorted_positions.col(col).data());
          k += 5;
          continue;
        }
        const auto pass = static_cast<std::size_t>(in[k + 1]);
        const auto i = static_cast<std::size_t>(in[k + 2]);
        contact::Pass& p = c.passes[pass];
        const auto col = static_cast<Eigen::Index>(i);
        std::copy_n(&in[k + 3], 3, p.friction.col(col).data());
        std::copy_n(&in[k + 6], 3, p.side.col(col).data());
        p.initial_penetration[i] = in[k + 9];
        const auto count = static_cast<std::size_t>(in[k + 10]);
        for (std::size_t q = 0; q < count; ++q)
          gained[pass][i].push_back(static_cast<Index>(in[k + 11 + q]));
        k += 11 + count;
      }
    for (std::size_t pass = 0; pass < c.passes.size(); ++pass)
      regroup(s, c.passes[pass], gained[pass], me);
  }

  // A pass's candidate lists (CSR) and near nodes for the current owners.
  void regroup(const State& s, contact::Pass& p, const std::vector<std::vector<Index>>& gained,
               int me) const {
    std::vector<Index> offsets(p.nodes.size() + 1, 0), candidates;
    std::vector<Index> near;
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
      const auto node = static_cast<std::size_t>(p.nodes[i]);
      if (s.ownership.owner[node] == me) {
        if (owner_[node] == me) {
          for (Index q = p.candidate_offsets[i]; q < p.candidate_offsets[i + 1]; ++q)
            candidates.push_back(p.candidates[static_cast<std::size_t>(q)]);
        } else {
          candidates.insert(candidates.end(), gained[i].begin(), gained[i].end());
          if (gained[i].empty()) {  // it carried nothing: no contact before the next sort
            p.friction.col(static_cast<Eigen::Index>(i)).setZero();
            p.side.col(static_cast<Eigen::Index>(i)).setZero();
            p.initial_penetration[i] = 0.0;
          }
        }
      }
      offsets[i + 1] = static_cast<Index>(candidates.size());
      if (offsets[i + 1] > offsets[i]) near.push_back(static_cast<Index>(i));
    }
    p.candidate_offsets = std::move(offsets);
    p.candidates = std::move(candidates);
    p.near = std::move(near);
  }

  std::vector<Index> segment_nodes_;  ///< deformable, ascending
  std::vector<int> owner_;            ///< the node owners the lists were made for
  parallel::ExchangePlan segment_ghosts_;
  long generation_ = -1;
  double exchange_seconds_ = 0.0;
};

// A force transducer: applies nothing, reads the hits the contact blocks before it computed.
class TransducerBlock final : public InterfaceBlock<TransducerBlock> {
 public:
  using InterfaceBlock::InterfaceBlock;
  // The interfaces it reads: every contact block's, in the deck's order.
  void link(State& /*s*/, const Blocks& all, core::Diagnostics& /*d*/) override {
    contacts_.clear();
    for (const std::unique_ptr<Block>& b : all)
      if (const auto* c = dynamic_cast<const ContactBlock*>(b.get()))
        contacts_.push_back(&c->interface());
  }
  void forces(State& s, NodalForces& /*f*/, ForceReport& /*report*/) override {
    contact::transducer_pass(s, interface_, contacts_, exchange_seconds_);
  }
  void split_times(const State& /*s*/, PhaseTimes& phases) const override {
    phases.seconds[PhaseTimes::exchange] += exchange_seconds_;
    phases.seconds[PhaseTimes::contact] -= exchange_seconds_;
  }

 private:
  std::vector<const contact::Interface*> contacts_;
  double exchange_seconds_ = 0.0;
};

}  // namespace

namespace contact {

void add_interface_blocks(std::vector<Interface> interfaces, Blocks& blocks) {
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    if (!interfaces[k].sensor.active)
      blocks.push_back(std::make_unique<ContactBlock>(std::move(interfaces[k]), k));
  // After every contact, whatever the deck order.
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    if (interfaces[k].sensor.active)
      blocks.push_back(std::make_unique<TransducerBlock>(std::move(interfaces[k]), k));
}

std::vector<const Interface*> interfaces_of(const State& s) {
  std::vector<std::pair<std::size_t, const Interface*>> found;
  for (const std::unique_ptr<Block>& b : s.blocks) {
    if (const auto* c = dynamic_cast<const ContactBlock*>(b.get()))
      found.emplace_back(c->order(), &c->interface());
    else if (const auto* t = dynamic_cast<const TransducerBlock*>(b.get()))
      found.emplace_back(t->order(), &t->interface());
  }
  std::sort(found.begin(), found.end());
  std::vector<const Interface*> out;
  for (const auto& [order, in] : found)
    out.push_back(in);
  return out;
}

}  // namespace contact

}  // namespace mcdyna::solver
