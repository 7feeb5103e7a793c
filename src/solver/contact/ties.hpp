#pragma once
/// Tied contacts (*CONTACT_TIED_NODES_TO_SURFACE / _SURFACE_TO_SURFACE), LS-DYNA's constraint
/// form: at the start each slave node is moved onto the nearest point of a master segment, whose
/// corners' weights it keeps; every cycle its force goes to those corners, which move with its
/// mass as well as theirs, and it is carried at the weighted mean of their velocities. Only the
/// translations are tied (a shell node keeps its own rotations).
#include <array>
#include <memory>
#include <vector>

#include "solver/contact/interface.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// A slave node of a tied contact (*CONTACT_TIED_NODES_TO_SURFACE / _SURFACE_TO_SURFACE) held
/// on its master segment at the point `weights` name (contact/ties.cpp).
struct Tie {
  Index slave = 0;
  std::array<Index, 4> masters{};
  std::array<double, 4> weights{};
};

class Block;  // block.hpp

}  // namespace mcdyna::solver

namespace mcdyna::solver::contact {

struct TieResult {
  std::vector<Tie> ties;
  std::vector<Index> untied;  ///< slave nodes with no segment within the tolerance
  double farthest = 0.0;      ///< the longest move onto the surface
  Index farthest_node = -1;
};

/// Ties `nodes` to the nearest point of `surface`'s segments within `tolerance[segment]` of the
/// node (its segment's own nodes excepted), moving each tied node there (initial and current
/// position).
TieResult tie_nodes(State& s, const std::vector<Index>& nodes, const Surface& surface,
                    const std::vector<double>& tolerance);

/// The block of every tie of the deck (`ties` by slave node, each slave tied once).
std::unique_ptr<Block> make_tie_block(std::vector<Tie> ties);
/// Its ties, or none (for tests).
const std::vector<Tie>& ties_of(const State& s);

}  // namespace mcdyna::solver::contact
