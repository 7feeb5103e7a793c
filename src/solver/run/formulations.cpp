// The formulations the time loop runs, one line each, in the loop's order (formulations.hpp):
// internal forces (hexahedra, shells, beams, SPG parts) before body loads and contact; the SPG
// parts' velocities before the rigid bodies sum their nodes' forces; constraints, then motions,
// then walls; the ties last, as they pass every force on a slave node to its segment.
#include "solver/run/formulations.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "solver/compile.hpp"

namespace mcdyna::solver {

const std::vector<Formulation>& formulations() {
  using namespace detail;
  static const std::vector<Formulation> kLines = {
      {"solids", {}, compile_solids},
      // Materials are numbered in part order within each element kind: solids, shells, beams,
      // SPG parts.
      {"shells", {"solids"}, compile_shells},
      {"beams", {"shells"}, compile_beams},
      {"discrete", {"spg"}, compile_discrete},
      {"spg", {"beams", "constraints", "motions"}, compile_spg_parts},
      {"joints", {"rigid bodies"}, compile_joints},
      {"rigid bodies", {"solids", "shells", "beams"}, compile_rigid_bodies, true},
      {"constraints", {"rigid bodies"}, compile_constraints},
      {"motions", {"rigid bodies"}, compile_motions},
      // Nodes given a velocity move with it, rigid bodies with the fit of theirs; particles
      // take it once they exist.
      {"initial velocities", {"spg", "rigid bodies"}, nullptr, false, compile_initial_velocities},
      // Walls track the nodes that have mass, particles included.
      {"rigid walls", {"spg"}, compile_planar_walls},
      {"geometric walls", {"spg"}, compile_geometric_walls},
      {"body loads", {}, compile_body_loads},
      {"applied loads", {"rigid bodies", "shells"}, compile_applied_loads},
      {"global damping", {}, compile_global_damping},
      // Particles are slave nodes.
      {"contact", {"spg", "rigid bodies", "ties"}, compile_contacts},
      // After every force (the slaves' go to their masters); compiled before the contacts, which
      // see the tied nodes where the ties moved them.
      {"ties", {"spg", "rigid bodies"}, compile_ties},
      // Last: reads the cycle's results and switches the blocks before it (Block::link).
      {"sensors", {}, compile_sensors},
  };
  return kLines;
}

std::vector<std::size_t> compile_order(const std::vector<Formulation>& lines) {
  const std::size_t n = lines.size();
  std::vector<std::vector<std::size_t>> needs(n);
  for (std::size_t i = 0; i < n; ++i)
    for (const char* name : lines[i].after) {
      std::size_t k = 0;
      while (k < n && std::strcmp(lines[k].name, name) != 0)
        ++k;
      if (k == n)
        throw std::logic_error(std::string("formulation '") + lines[i].name + "' follows '" + name +
                               "', which is not in the registry");
      needs[i].push_back(k);
    }
  std::vector<std::size_t> order;
  std::vector<bool> done(n, false);
  while (order.size() < n) {
    std::size_t next = n;
    for (std::size_t i = 0; i < n && next == n; ++i) {
      if (done[i]) continue;
      bool ready = true;
      for (const std::size_t k : needs[i])
        ready = ready && done[k];
      if (ready) next = i;
    }
    if (next == n) throw std::logic_error("the formulations' compile passes wait on each other");
    done[next] = true;
    order.push_back(next);
  }
  return order;
}

State::State() = default;
State::~State() = default;
State::State(State&&) noexcept = default;
State& State::operator=(State&&) noexcept = default;

Blocks make_blocks(std::vector<Blocks> compiled) {
  Blocks blocks;
  for (Blocks& line : compiled)
    for (auto& b : line)
      blocks.push_back(std::move(b));
  return blocks;
}

}  // namespace mcdyna::solver
