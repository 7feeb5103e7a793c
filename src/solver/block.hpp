#pragma once
/// A formulation of the model behind the time loop's phases (design.md §7): hexahedra, an SPG
/// domain, rigid bodies, nodal constraints, prescribed nodal motions, rigid walls, body loads, a
/// contact interface. The loop (driver.cpp) calls each phase on every block in the blocks' order,
/// which is the order the physics needs: internal forces before body loads and contact, the SPG
/// parts' velocities before the rigid bodies sum their nodes' forces, the constraints before the
/// SPG parts take up what the constraints changed. A block does nothing in the phases it has no
/// part in. Blocks are made from the compiled state by the registry (formulations.cpp).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/binary_archive.hpp"
#include "core/diagnostics.hpp"
#include "model/sensors.hpp"  // SensedEntity
#include "solver/element_ref.hpp"
#include "solver/energy.hpp"
#include "solver/history_records.hpp"
#include "solver/nodal_forces.hpp"
#include "solver/state.hpp"
#include "solver/state_sink.hpp"
#include "solver/step_times.hpp"

namespace mcdyna::solver {

/// What the force phase found: the smallest stable step of the blocks (before TSSFAC), who sets
/// it, and the first failure (an inverted or non-finite element or particle, named).
struct ForceReport {
  double critical_step = std::numeric_limits<double>::infinity();
  Index controlling_element = -1;
  std::size_t controlling_domain = 0;
  Index controlling_particle = -1;
  std::string failure;
  bool inverted = false;
  /// Keeps the first failure only.
  void fail(std::string what, bool inverted_entity) {
    if (!failure.empty()) return;
    failure = std::move(what);
    inverted = inverted_entity;
  }
};

class Block {
 public:
  virtual ~Block() = default;
  /// The timing phase its work is charged to.
  [[nodiscard]] virtual PhaseTimes::Phase phase() const = 0;
  /// Once before the first cycle of a run that does not continue from a restart dump.
  virtual void initialise(State& /*s*/) {}
  /// Forces and moments at t^n added to `f` (positions x^n, velocities v^{n-1/2}); the block's
  /// stable step and failures into `report`.
  virtual void forces(State& /*s*/, NodalForces& /*f*/, ForceReport& /*report*/) {}
  /// v^{n-1/2} -> v^{n+1/2} over t.mean by the forces `f` at t^n for the nodes the block moves
  /// itself (the other nodes took a = f / m before). Returns the lowest node with a non-finite
  /// velocity, or -1.
  virtual Index advance_velocities(State& /*s*/, const NodalForces& /*f*/, const StepTimes& /*t*/) {
    return -1;
  }
  /// Velocity-level conditions, after every block's velocities.
  virtual void constrain(State& /*s*/, const StepTimes& /*t*/) {}
  /// After every condition: take up what the conditions changed.
  virtual void after_constraints(State& /*s*/) {}
  /// x^n -> x^{n+1} for the nodes the block places itself, after the other nodes moved.
  virtual void advance_positions(State& /*s*/, double /*dt*/) {}
  /// Entity updates per cycle (element and particle counts of the timing summary).
  [[nodiscard]] virtual long elements() const { return 0; }
  [[nodiscard]] virtual long particles() const { return 0; }
  /// Over several processes (run/halo.hpp): a block that every process computes whole
  /// marks the nodes it reads or moves, which every process then moves itself. Blocks split
  /// over the processes (hexahedra) and node-wise conditions mark nothing.
  virtual void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& /*nodes*/) const {}
  /// ORs into `held` (one mask per node) the translations whose velocity it prescribes whatever
  /// the node's forces: bit 0 x, 1 y, 2 z (SPC, *NODE TC), bit 3 a direction of its own (a
  /// prescribed motion). An SPG particle on a held node is pinned (compile_spg.cpp); a discrete
  /// element's massless node must be held in x, y and z (compile_discrete).
  virtual void mark_held(std::vector<std::uint8_t>& /*held*/) const {}
  /// The slave nodes its contact passes visit every cycle, one entry per pass and node (the
  /// decomposition's contact cost, run/decomposition.cpp).
  virtual void add_contact_nodes(std::vector<Index>& /*nodes*/) const {}
  /// What it is for the user when it cannot run over several processes ("tied contacts
  /// (*CONTACT_TIED_...)"), or empty.
  [[nodiscard]] virtual std::string one_process_only() const { return {}; }
  /// Over several processes, after the decomposition and initialise (or a restart): what a
  /// block split over the processes needs beyond the node owners (an SPG part's share of
  /// particles, spg/distribution.hpp). Collective.
  virtual void distribute(State& /*s*/) {}
  /// What a synchronisation is for: the histories or a d3plot state (written by process 0), or
  /// a restart dump (every process dumps the whole block).
  enum class Gather { histories, state, dump };
  /// Over several processes, before an output or a restart dump: the values of the block's
  /// entities from their owners, to process 0 what the output reads or to every process all of
  /// them. Collective.
  virtual void synchronise(State& /*s*/, Gather /*what*/) {}
  /// The elements it numbers (finite-element blocks): elements are numbered block by block in
  /// the blocks' order (solids, shells, beams), as ForceReport::controlling_element and the
  /// outputs name them; element(s, k) names its k-th.
  [[nodiscard]] virtual Index numbered_elements() const { return 0; }
  [[nodiscard]] virtual ElementRef element(const State& /*s*/, Index /*k*/) const { return {}; }
  /// What it shows in a d3plot state (state_sink.hpp): its cells, in the blocks' order.
  virtual void write_state(const State& /*s*/, StateSink& /*sink*/) const {}
  /// At the end of a run: moves the seconds of its finer phases (SPG neighbour search, ...) out
  /// of the phase it was charged to.
  virtual void split_times(const State& /*s*/, PhaseTimes& /*phases*/) const {}
  /// What it adds to the global energies, momentum and mass at t^n (glstat, energy.hpp), from
  /// `previous` = v^{n-1/2} and the state's v^{n+1/2}. The blocks add in their order, each term
  /// a plain sum; the nodes' own kinetic energy and mass come after.
  virtual void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                            EnergySummary& /*e*/) const {}
  /// What it adds to its parts' energies and momenta (matsum; `parts` in deck order).
  virtual void add_part_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                                 std::vector<PartSummary>& /*parts*/) const {}
  /// Adds to each node's added mass (`nodal`, zeroed before the first block) its elements' share
  /// of their DT2MS mass, in the fixed order of its force gather (fe/added_mass.hpp).
  virtual void spread_added_mass(const State& /*s*/, std::vector<double>& /*nodal*/) const {}
  /// Adds to `added` the mass DT2MS mass scaling gave it beyond the nodes' (SPG particles).
  virtual void add_added_mass(const State& /*s*/, double& /*added*/) const {}
  /// Its lines of the ASCII histories (rwforc and glstat's walls, rcforc, bndout, spcforc:
  /// history_records.hpp), at the state's time.
  virtual void add_history_records(const State& /*s*/, HistoryRecords& /*records*/) const {}
  /// Once compile() has made every block: resolves what it reads or drives in the other blocks'
  /// entities (a sensor's contact, a control's wall), reporting what it cannot find at its deck
  /// location. Runs again when a run restarts, before the dump is read.
  virtual void link(State& /*s*/, const Blocks& /*all*/, core::Diagnostics& /*d*/) {}
  /// *SENSOR_DEFINE_FORCE: the force of its entity `kind` `id`, this cycle, into `force`; false
  /// when it holds no such entity.
  virtual bool sensed_force(const State& /*s*/, model::SensedEntity /*kind*/, model::Id /*id*/,
                            Vec3& /*force*/) const {
    return false;
  }
  /// *SENSOR_CONTROL: turns its entity `kind` `id` on or off (off: it acts as it does outside
  /// its birth and death times); false when it holds no such entity.
  virtual bool switch_entity(State& /*s*/, model::SensedEntity /*kind*/, model::Id /*id*/,
                             bool /*on*/) {
    return false;
  }
  /// Marks in `nodes` the nodes of its entity `kind` `id` (a prescribed motion's: the sensor that
  /// reads its force has every process move them).
  virtual void mark_entity_nodes(model::SensedEntity /*kind*/, model::Id /*id*/,
                                 std::vector<std::uint8_t>& /*nodes*/) const {}
  /// Lines for the end-of-run summary (a control's switches: what turned off, when).
  virtual void add_notes(const State& /*s*/, std::vector<std::string>& /*notes*/) const {}
  /// Its section of a restart dump (restart.hpp), named for the user ("beams", "contact 3"), or
  /// empty when nothing of it changes during a run.
  [[nodiscard]] virtual std::string dump_name() const { return {}; }
  /// The sizes of the structs it dumps (dump.hpp), written into the dump's layout line.
  [[nodiscard]] virtual std::string dump_layout() const { return {}; }
  /// What of it changes during a run, bit for bit (a block with a dump_name derives from
  /// DumpedBlock, which gives both from one member list).
  virtual void save(core::OutArchive& /*ar*/, const State& /*s*/) const {}
  virtual void load(core::InArchive& /*ar*/, State& /*s*/) {}
};

/// A block whose dump is one member list for both directions: Derived has
///   template <class Ar> void dumped(Ar& ar, State& s) { ar(shells_, kept_); }
/// (an OutArchive writes nothing to the state or the block).
template <class Derived>
class DumpedBlock : public Block {
 public:
  void save(core::OutArchive& ar, const State& s) const override {
    const_cast<Derived*>(static_cast<const Derived*>(this))->dumped(ar, const_cast<State&>(s));
  }
  void load(core::InArchive& ar, State& s) override { static_cast<Derived*>(this)->dumped(ar, s); }
};

/// The blocks of a compiled state, in the loop's order (formulations.cpp): for each registry line,
/// the blocks its compile pass made (`compiled`, by line).
Blocks make_blocks(std::vector<Blocks> compiled);

/// The state's first block of type B, or nullptr: how the accessors for tests reach a block's
/// own data (beams_of, planar_walls_of, joint_stiffnesses_of).
template <class B>
const B* find_block(const State& s) {
  for (const std::unique_ptr<Block>& b : s.blocks)
    if (const auto* found = dynamic_cast<const B*>(b.get())) return found;
  return nullptr;
}

/// What the state's block of type B owns, through its accessor `get` (`&TieBlock::ties`), or
/// an empty T when the state holds no such block: the accessors for tests and reports
/// (planar_walls_of, joint_stiffnesses_of, ties_of, welds_of).
template <class B, class T>
const T& owned_by(const State& s, const T& (B::*get)() const) {
  static const T kNone{};
  const B* b = find_block<B>(s);
  return b != nullptr ? (b->*get)() : kNone;
}

/// The blocks the compile passes made so far, line by line (formulations.hpp): what a pass reads
/// of the formulations compiled before it (an SPG part's pinned particles, the nodes a discrete
/// element may leave without mass) is what their blocks give.
class CompiledBlocks {
 public:
  explicit CompiledBlocks(const std::vector<Blocks>& lines) : lines_(lines) {}
  /// `held` for every node (Block::mark_held), sized for `nodes`.
  [[nodiscard]] std::vector<std::uint8_t> held_nodes(Index nodes) const {
    std::vector<std::uint8_t> held(static_cast<std::size_t>(nodes), 0);
    for (const Blocks& line : lines_)
      for (const std::unique_ptr<Block>& b : line)
        b->mark_held(held);
    return held;
  }
  /// The blocks of type B compiled so far, in order (spg::domains_of(before)).
  template <class B>
  [[nodiscard]] std::vector<const B*> find_all() const {
    std::vector<const B*> found;
    for (const Blocks& line : lines_)
      for (const std::unique_ptr<Block>& b : line)
        if (const auto* one = dynamic_cast<const B*>(b.get())) found.push_back(one);
    return found;
  }
  /// The first block of type B compiled so far, or nullptr (solids_of(before)).
  template <class B>
  [[nodiscard]] const B* find() const {
    for (const Blocks& line : lines_)
      for (const std::unique_ptr<Block>& b : line)
        if (const auto* found = dynamic_cast<const B*>(b.get())) return found;
    return nullptr;
  }

 private:
  const std::vector<Blocks>& lines_;
};

/// The same as owned_by(state, get) from the blocks compiled so far (solids_of(before)).
template <class B, class T>
const T& owned_by(const CompiledBlocks& before, const T& (B::*get)() const) {
  static const T kNone{};
  const B* b = before.find<B>();
  return b != nullptr ? (b->*get)() : kNone;
}

/// The number of block `b`'s first element: the elements the blocks before it number.
Index first_element(const State& s, const Block& b);  // fe/element_names.cpp
/// The elements every block numbers (deformable solids, shells, beams, discrete elements):
/// glstat's "number of elements".
Index numbered_elements(const State& s);  // fe/element_names.cpp

/// Names for diagnostics: "solid element 12 (part 1)", "SPG particle at node 7 (part 2)".
std::string element_name(const State& s, Index element);
std::string particle_name(const State& s, std::size_t domain, Index particle);
/// The stop message for an element grown past fe::kRunawayGrowth (`measure`: area, volume).
std::string runaway_message(const State& s, Index element, const char* measure);

}  // namespace mcdyna::solver
