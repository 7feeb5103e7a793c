// What an element index names: the blocks number their elements in the blocks' order (solids,
// shells, beams; block.hpp).
#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/fe/element_loop.hpp"

namespace mcdyna::solver {

ElementRef element_ref(const State& s, Index e) {
  for (const std::unique_ptr<Block>& b : s.blocks) {
    const Index n = b->numbered_elements();
    if (e < n) return b->element(s, e);
    e -= n;
  }
  return {"element", 0, 0};  // past the numbered elements: not reached by the solver's indices
}

Index first_element(const State& s, const Block& b) {
  Index first = 0;
  for (const std::unique_ptr<Block>& other : s.blocks) {
    if (other.get() == &b) break;
    first += other->numbered_elements();
  }
  return first;
}

Index numbered_elements(const State& s) {
  Index count = 0;
  for (const std::unique_ptr<Block>& b : s.blocks)
    count += b->numbered_elements();
  return count;
}

std::string element_name(const State& s, Index e) {
  const ElementRef r = element_ref(s, e);
  return fmt::format("{} element {} (part {})", r.kind, r.id, r.part);
}

std::string runaway_message(const State& s, Index e, const char* measure) {
  return fmt::format(
      "{} grew to over {:.0e} times its initial {}: the motion is unstable (the step is too large "
      "for the element's highest mode; a lone element with free corners needs a TSSFAC below "
      "0.877 for shells, 0.73 for hexahedra at Poisson's ratio 0.3)",
      element_name(s, e), fe::kRunawayGrowth, measure);
}

}  // namespace mcdyna::solver
