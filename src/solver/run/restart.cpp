// The dump's sections: the nodes and the clock here, each block's own part through
// Block::save / load (its member lists and their size pins live beside its code, dump.hpp).
// tests/unit/solver/restart_test.cpp checks that a run continued from a dump writes the same bits
// as one that never stopped.
#include "solver/run/restart.hpp"

#include <stdexcept>

#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"

namespace mcdyna::solver {

// (Outside the anonymous namespace: the archive finds fields() by argument-dependent lookup.)
template <class Ar>
void fields(Ar& ar, Nodes& n) {
  ar(n.ids, n.initial, n.position, n.velocity, n.acceleration, n.mass, n.added_mass, n.rigid_body,
     n.smoothed);
  ar(n.angular_velocity, n.previous_angular_velocity, n.rotary_inertia);
}

template <class Ar>
void fields(Ar& ar, PhaseTimes& p) {
  ar(p.seconds);
}

template <class Ar>
void fields(Ar& ar, NodalForces& f) {
  ar(f.force, f.moment);
}

template <class Ar>
void fields(Ar& ar, ResumePoint& r) {
  ar(r.forces, r.critical_step, r.controlling_element, r.controlling_domain, r.controlling_particle,
     r.first_step, r.phases, r.wall_seconds, r.core_seconds, r.element_cycles, r.particle_cycles);
}

namespace {

// State's own members: the nodes, the clock and the energies. The rest is the blocks' (each dumps
// its part) or deck data compiled again on restart: title, parts, materials, rigid_cells,
// curves, time_control, mass_scaling_dt (from DT2MS and TSSFAC; both changed by --fixed-step).
constexpr auto kStateDumpedSizes = core::sizes_of<Nodes, State, ResumePoint>();
static_assert(!core::kSizesPinned ||
                  kStateDumpedSizes == decltype(kStateDumpedSizes){240, 904, 224},
              "Nodes, State or ResumePoint changed: list the new member here, or note it among "
              "the deck data left out");

template <class Ar>
void clock_and_energies(Ar& ar, State& s) {
  // Of s.ownership only the owners: a restart on the same process count takes them (each dump
  // holds the SPG rows its process read); the time loop rebuilds the rest.
  ar(s.ownership.owner, s.time, s.cycle, s.step, s.critical_step, s.controlling_element,
     s.controlling_domain, s.controlling_particle, s.external_work, s.eroded_kinetic,
     s.eroded_internal, s.eroded_hourglass, s.initial_energy, s.initial_mass);
}

// The blocks with a dump section, in the blocks' order.
std::vector<Block*> dumped_blocks(const State& s) {
  std::vector<Block*> out;
  for (const auto& b : s.blocks)
    if (!b->dump_name().empty()) out.push_back(b.get());
  return out;
}

template <class Ar, class SaveOrLoad>
void state_section(Ar& ar, State& s, std::size_t section, SaveOrLoad&& block_part) {
  const std::vector<Block*> blocks = dumped_blocks(s);
  if (section == 0) return ar(s.nodes);
  if (section <= blocks.size()) return block_part(*blocks[section - 1]);
  if (section == blocks.size() + 1) return clock_and_energies(ar, s);
  throw std::logic_error("no such dump section");
}

}  // namespace

std::vector<std::string> state_sections(const State& state) {
  std::vector<std::string> names{"nodes"};
  for (const Block* b : dumped_blocks(state))
    names.push_back(b->dump_name());
  names.emplace_back("time and energies");
  return names;
}

std::string dump_layout(const State& state) {
  std::string out = core::sizes_text(kStateDumpedSizes);
  for (const Block* b : dumped_blocks(state))
    out += b->dump_name() + ": " + b->dump_layout();
  return out;
}

void save_state_section(core::OutArchive& ar, const State& state, std::size_t section) {
  // The member lists serve both directions; nothing is written to `state`.
  state_section(ar, const_cast<State&>(state), section, [&](const Block& b) { b.save(ar, state); });
}

void load_state_section(core::InArchive& ar, State& state, std::size_t section) {
  state_section(ar, state, section, [&](Block& b) { b.load(ar, state); });
}

void save_resume_point(core::OutArchive& ar, const ResumePoint& point) {
  ar(const_cast<ResumePoint&>(point));
}

void load_resume_point(core::InArchive& ar, ResumePoint& point) {
  ar(point);
}

}  // namespace mcdyna::solver
