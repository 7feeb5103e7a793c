// The velocity-level conditions (SPC and *NODE TC, prescribed nodal motion) and the
// body loads as blocks of the time loop (loads.hpp).
#include "solver/block.hpp"
#include "solver/loads/loads.hpp"
#include "solver/loads/loads_dump.hpp"
#include "solver/sensors/switchable.hpp"

namespace mcdyna::solver {

namespace {

using AddEnergies = void (*)(const State&, EnergySummary&);

void motions_work(const State& s, EnergySummary& e) {
  for (const NodalMotion& m : s.nodal_motions)
    e.external_work += m.work();
}

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

// A condition applied by one of loads.hpp's functions in the constraint phase; its state is
// the member `Held` of State (its reactions, forces and work), its energy (if any) AddTo's.
template <void (*Apply)(State&, const StepTimes&), auto Held, AddEnergies AddTo = nullptr>
class ConditionBlock final : public DumpedBlock<ConditionBlock<Apply, Held, AddTo>> {
 public:
  explicit ConditionBlock(std::string name) : name_(std::move(name)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void constrain(State& s, const StepTimes& t) override { Apply(s, t); }
  void add_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    if constexpr (AddTo != nullptr) AddTo(s, e);
  }
  bool sensed_force(const State& s, model::SensedEntity kind, model::Id id,
                    Vec3& force) const override {
    return held_force(s.*Held, kind, id, force);
  }
  bool switch_entity(State& s, model::SensedEntity kind, model::Id id, bool on) override {
    return switch_held(s.*Held, kind, id, on);
  }
  void add_history_records(const State& s, HistoryRecords& out) const override {
    held_records(s, s.*Held, out);
  }
  [[nodiscard]] std::string dump_name() const override { return name_; }
  [[nodiscard]] std::string dump_layout() const override {
    return sizes_text(kConditionDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& s) const {
    ar(s.*Held);
  }

 private:
  std::string name_;
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

void add_nodal_constraint_blocks(State& s, Blocks& blocks) {
  if (!s.constraints.nodes.empty())
    blocks.push_back(std::make_unique<ConditionBlock<apply_nodal_constraints, &State::constraints>>(
        "nodal constraints"));
}

void add_nodal_motion_blocks(State& s, Blocks& blocks) {
  if (!s.nodal_motions.empty())
    blocks.push_back(
        std::make_unique<ConditionBlock<apply_nodal_motions, &State::nodal_motions, motions_work>>(
            "prescribed nodal motions"));
}

std::unique_ptr<Block> make_body_loads_block(std::vector<BodyLoadState> loads) {
  return std::make_unique<BodyLoadsBlock>(std::move(loads));
}

}  // namespace mcdyna::solver
