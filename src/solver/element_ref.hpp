#pragma once
/// Which element an element index names. Elements are numbered solids first, then shells, then
/// beams (ForceReport::controlling_element, State::controlling_element).
#include "solver/state.hpp"

namespace mcdyna::solver {

/// An element as outputs name it: its kind ("solid", "shell", "beam"), user ID and part ID.
struct ElementRef {
  const char* kind = "solid";
  model::Id id = 0;
  model::Id part = 0;
};
ElementRef element_ref(const State& s, Index element);  // fe/element_names.cpp

}  // namespace mcdyna::solver
