// The velocity-level conditions (SPC and *NODE TC, prescribed nodal motion) and the
// body loads as blocks of the time loop (loads.hpp).
#include <algorithm>
#include <utility>

#include "solver/block.hpp"
#include "solver/loads/loads.hpp"
#include "solver/loads/loads_dump.hpp"
#include "solver/parallel/owned_gather.hpp"
#include "solver/sensors/switchable.hpp"

namespace mcdyna::solver {

namespace {

// What the conditions give *SENSOR_DEFINE_FORCE and *SENSOR_CONTROL: a prescribed motion's force
// on its nodes; the nodal constraints (merged per node) take no part.
bool held_force(const NodalConstraints& /*c*/, model::SensedEntity /*kind*/, model::Id /*id*/,
                Vec3& /*force*/) {
  return false;
}
bool held_force(const std::vector<NodalMotion>& v, model::SensedEntity kind, model::Id id,
                Vec3& force) {
  return sensors::sensed_force_in(
      v, model::SensedEntity::prescribed_motion, kind, id,
      [](const NodalMotion& m) { return m.force(); }, force);
}
bool switch_held(NodalConstraints& /*c*/, model::SensedEntity /*kind*/, model::Id /*id*/,
                 bool /*on*/) {
  return false;
}
bool switch_held(std::vector<NodalMotion>& v, model::SensedEntity kind, model::Id id, bool on) {
  return sensors::switch_in(v, model::SensedEntity::prescribed_motion, kind, id, on);
}

// The translations they hold (Block::mark_held): the constraints' masks, a motion's own
// direction.
void mark_held_nodes(const NodalConstraints& c, std::vector<std::uint8_t>& held) {
  for (std::size_t k = 0; k < c.nodes.size(); ++k)
    held[static_cast<std::size_t>(c.nodes[k])] |= static_cast<std::uint8_t>(c.masks[k] & 7U);
}
void mark_held_nodes(const std::vector<NodalMotion>& v, std::vector<std::uint8_t>& held) {
  for (const NodalMotion& m : v)
    for (const Index n : m.nodes)
      held[static_cast<std::size_t>(n)] |= 8U;
}

void mark_motion_nodes(const NodalConstraints& /*c*/, model::SensedEntity /*kind*/,
                       model::Id /*id*/, std::vector<std::uint8_t>& /*nodes*/) {}
void mark_motion_nodes(const std::vector<NodalMotion>& v, model::SensedEntity kind, model::Id id,
                       std::vector<std::uint8_t>& nodes) {
  if (kind != model::SensedEntity::prescribed_motion) return;
  for (const NodalMotion& m : v)
    if (m.id == id)
      for (const Index n : m.nodes)
        nodes[static_cast<std::size_t>(n)] = 1;
}

void add_work(const NodalConstraints& /*c*/, EnergySummary& /*e*/) {}
void add_work(const std::vector<NodalMotion>& v, EnergySummary& e) {
  for (const NodalMotion& m : v)
    e.external_work += m.work();
}

// Their history lines: spcforc's reaction per constrained node, bndout's force and work per
// prescribed node (one line per node, as LS-DYNA prints them).
void held_records(const State& s, const NodalConstraints& c, HistoryRecords& out) {
  for (std::size_t k = 0; k < c.nodes.size(); ++k)
    out.reactions.push_back(
        {s.nodes.ids[static_cast<std::size_t>(c.nodes[k])], c.reaction.col(static_cast<Index>(k))});
}
void held_records(const State& s, const std::vector<NodalMotion>& v, HistoryRecords& out) {
  for (const NodalMotion& m : v)
    for (std::size_t k = 0; k < m.nodes.size(); ++k)
      out.boundaries.push_back(
          {BoundaryRecord::Kind::node, s.nodes.ids[static_cast<std::size_t>(m.nodes[k])],
           m.node_force.col(static_cast<Index>(k)), Vec3::Zero(), m.node_work[k]});
}

// Over several processes a node's owner applies its condition: what the histories print of it
// goes to process 0.
void gather_records(const parallel::Ownership& own, NodalConstraints& c) {
  parallel::gather_owned(
      own.comm, c.nodes.size(), [&](std::size_t k) { return own.output_owner(c.nodes[k]); },
      [&](std::size_t k, std::vector<double>& out) {
        const auto r = c.reaction.col(static_cast<Index>(k));
        out.insert(out.end(), r.data(), r.data() + 3);
      },
      [&](std::size_t k, const double*& in) {
        std::copy(in, in + 3, c.reaction.col(static_cast<Index>(k)).data());
        in += 3;
      },
      true);
}
// Every motion's nodes in one collective: entry k is node at[k].second of motion at[k].first.
void gather_records(const parallel::Ownership& own, std::vector<NodalMotion>& v) {
  std::vector<std::pair<std::size_t, std::size_t>> at;
  for (std::size_t m = 0; m < v.size(); ++m)
    for (std::size_t k = 0; k < v[m].nodes.size(); ++k)
      at.emplace_back(m, k);
  parallel::gather_owned(
      own.comm, at.size(),
      [&](std::size_t e) { return own.output_owner(v[at[e].first].nodes[at[e].second]); },
      [&](std::size_t e, std::vector<double>& out) {
        const NodalMotion& m = v[at[e].first];
        const auto f = m.node_force.col(static_cast<Index>(at[e].second));
        out.insert(out.end(), f.data(), f.data() + 3);
        out.push_back(m.node_work[at[e].second]);
      },
      [&](std::size_t e, const double*& in) {
        NodalMotion& m = v[at[e].first];
        std::copy(in, in + 3, m.node_force.col(static_cast<Index>(at[e].second)).data());
        m.node_work[at[e].second] = in[3];
        in += 4;
      },
      true);
}

// A condition applied in the constraint phase by one of loads.hpp's functions to the data the
// block owns, `Held` (its nodes, its reactions or forces, its work).
template <class Held, void (*Apply)(State&, Held&, const StepTimes&)>
class ConditionBlock final : public DumpedBlock<ConditionBlock<Held, Apply>> {
 public:
  ConditionBlock(std::string name, Held held) : name_(std::move(name)), held_(std::move(held)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void constrain(State& s, const StepTimes& t) override { Apply(s, held_, t); }
  void mark_held(std::vector<std::uint8_t>& held) const override { mark_held_nodes(held_, held); }
  void mark_entity_nodes(model::SensedEntity kind, model::Id id,
                         std::vector<std::uint8_t>& nodes) const override {
    mark_motion_nodes(held_, kind, id, nodes);
  }
  void synchronise(State& s, Block::Gather what) override {
    if (what != Block::Gather::dump) gather_records(s.ownership, held_);
  }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    add_work(held_, e);
  }
  bool sensed_force(const State& /*s*/, model::SensedEntity kind, model::Id id,
                    Vec3& force) const override {
    return held_force(held_, kind, id, force);
  }
  bool switch_entity(State& /*s*/, model::SensedEntity kind, model::Id id, bool on) override {
    return switch_held(held_, kind, id, on);
  }
  void add_history_records(const State& s, HistoryRecords& out) const override {
    held_records(s, held_, out);
  }
  [[nodiscard]] std::string dump_name() const override { return name_; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kConditionDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(held_);
  }

 private:
  std::string name_;
  Held held_;
};

// Owns its loads (deck data: nothing to dump).
class BodyLoadsBlock final : public Block {
 public:
  explicit BodyLoadsBlock(std::vector<BodyLoadState> loads) : loads_(std::move(loads)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void forces(State& s, NodalForces& f, ForceReport& /*report*/) override {
    apply_body_loads(s, loads_, f.force);
  }

 private:
  std::vector<BodyLoadState> loads_;
};

}  // namespace

std::unique_ptr<Block> make_nodal_constraints_block(NodalConstraints c) {
  return std::make_unique<ConditionBlock<NodalConstraints, apply_nodal_constraints>>(
      "nodal constraints", std::move(c));
}

std::unique_ptr<Block> make_nodal_motions_block(std::vector<NodalMotion> motions) {
  return std::make_unique<ConditionBlock<std::vector<NodalMotion>, apply_nodal_motions>>(
      "prescribed nodal motions", std::move(motions));
}

std::unique_ptr<Block> make_body_loads_block(std::vector<BodyLoadState> loads) {
  return std::make_unique<BodyLoadsBlock>(std::move(loads));
}

}  // namespace mcdyna::solver
