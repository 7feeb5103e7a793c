#pragma once
/// Which element an element index names. The blocks number their elements in the blocks' order:
/// solids first, then shells, then beams (Block::numbered_elements;
/// ForceReport::controlling_element, State::controlling_element).
#include "solver/state.hpp"

namespace mcdyna::solver {

/// An element as outputs name it: its kind ("solid", "shell", "beam"), user ID and part ID.
struct ElementRef {
  const char* kind = "solid";
  model::Id id = 0;
  model::Id part = 0;
};
ElementRef element_ref(const State& s, Index element);  // fe/element_names.cpp, over s.blocks

}  // namespace mcdyna::solver
