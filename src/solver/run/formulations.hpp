#pragma once
/// The formulations, one line each in the time loop's order (design.md §7): the compile pass that
/// turns its keywords into the blocks it runs as, each owning its data. make_blocks() puts the
/// blocks in exactly this order; compile() runs the passes in it too, but moves a pass after
/// the lines whose compiled data it reads (`after`: an SPG part's particles pinned by the
/// constraints and motions, a joint's reduced mass from the rigid bodies).
#include <cstddef>
#include <vector>

#include "core/diagnostics.hpp"
#include "model/model_database.hpp"
#include "solver/block.hpp"

namespace mcdyna::solver {

/// A pass reads the model, the state compiled so far and the blocks of the lines before it (its
/// `after` lines among them).
using CompilePass = void (*)(const model::ModelDatabase&, State&, const CompiledBlocks&,
                             core::Diagnostics&);
/// A pass that makes blocks owning their data (design.md §7), into the line's own list.
using CompileBlocks = void (*)(const model::ModelDatabase&, State&, const CompiledBlocks&, Blocks&,
                               core::Diagnostics&);

struct Formulation {
  const char* name = "";
  std::vector<const char*> after;  ///< lines whose compiled data its pass reads
  /// Its pass, which makes its blocks (none when the deck holds none of it).
  CompileBlocks compile_blocks = nullptr;
  /// The passes after it read the elements' and rigid bodies' arrays whole: compile() stops at
  /// the errors reported so far.
  bool stop_on_errors = false;
  /// A line without blocks (initial conditions): its pass sets the state's initial values.
  CompilePass compile = nullptr;
};

/// The registry (formulations.cpp).
const std::vector<Formulation>& formulations();

/// The order compile() runs the passes in: the registry's, each line moved just late enough to
/// follow the lines it names (of the lines ready, the first in the registry runs first). Throws
/// std::logic_error for a name not in the registry or a cycle.
std::vector<std::size_t> compile_order(const std::vector<Formulation>& lines);

}  // namespace mcdyna::solver
