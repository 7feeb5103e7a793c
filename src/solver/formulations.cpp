// The formulations the time loop runs, one line each, in the loop's order (formulations.hpp):
// internal forces (hexahedra, shells, beams, SPG parts) before body loads and contact; the SPG
// parts' velocities before the rigid bodies sum their nodes' forces; constraints, then motions,
// then walls; the ties last, as they pass every force on a slave node to its segment.
#include "solver/formulations.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "solver/compile.hpp"

namespace mcdyna::solver {

const std::vector<Formulation>& formulations() {
  using namespace detail;
  static const std::vector<Formulation> kLines = {
      {"solids", nullptr, nullptr, {}, false, compile_solids},
      // Materials are numbered in part order within each element kind: solids, shells, beams,
      // SPG parts.
      {"shells", nullptr, nullptr, {"solids"}, false, compile_shells},
      {"beams", nullptr, nullptr, {"shells"}, false, compile_beams},
      {"discrete", nullptr, nullptr, {"spg"}, false, compile_discrete},
      {"spg", nullptr, nullptr, {"beams", "constraints", "motions"}, false, compile_spg_parts},
      {"joints", nullptr, nullptr, {"rigid bodies"}, false, compile_joints},
      {"rigid bodies", nullptr, nullptr, {"solids", "shells", "beams"}, true, compile_rigid_bodies},
      {"constraints", nullptr, nullptr, {"rigid bodies"}, false, compile_constraints},
      {"motions", nullptr, nullptr, {"rigid bodies"}, false, compile_motions},
      // Nodes given a velocity move with it, rigid bodies with the fit of theirs; particles
      // take it once they exist.
      {"initial velocities", compile_initial_velocities, nullptr, {"spg", "rigid bodies"}},
      // Walls track the nodes that have mass, particles included.
      {"rigid walls", nullptr, nullptr, {"spg"}, false, compile_planar_walls},
      {"geometric walls", nullptr, nullptr, {"spg"}, false, compile_geometric_walls},
      {"body loads", nullptr, nullptr, {}, false, compile_body_loads},
      {"applied loads", nullptr, nullptr, {"rigid bodies", "shells"}, false, compile_applied_loads},
      {"global damping", nullptr, nullptr, {}, false, compile_global_damping},
      // Particles are slave nodes.
      {"contact", nullptr, nullptr, {"spg", "rigid bodies", "ties"}, false, compile_contacts},
      // After every force (the slaves' go to their masters); compiled before the contacts, which
      // see the tied nodes where the ties moved them.
      {"ties", nullptr, nullptr, {"spg", "rigid bodies"}, false, compile_ties},
      // Last: reads the cycle's results and switches the blocks before it (Block::link).
      {"sensors", nullptr, nullptr, {}, false, compile_sensors},
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

Blocks make_blocks(State& s, std::vector<Blocks> compiled) {
  const std::vector<Formulation>& lines = formulations();
  compiled.resize(lines.size());
  Blocks blocks;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    for (auto& b : compiled[k])
      blocks.push_back(std::move(b));
    if (lines[k].add_blocks != nullptr) lines[k].add_blocks(s, blocks);
  }
  return blocks;
}

}  // namespace mcdyna::solver
