// What an element index names: solids first, then shells, then beams (block.hpp).
#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/fe/element_loop.hpp"

namespace mcdyna::solver {

ElementRef element_ref(const State& s, Index e) {
  if (e < s.solids.count()) {
    const auto i = static_cast<std::size_t>(e);
    return {"solid", s.solids.ids[i], s.parts[static_cast<std::size_t>(s.solids.part[i])].id};
  }
  if (e >= s.solids.count() + s.shells.count()) {
    const auto i = static_cast<std::size_t>(e - s.solids.count() - s.shells.count());
    return {"beam", s.beams.ids[i], s.parts[static_cast<std::size_t>(s.beams.part[i])].id};
  }
  const auto i = static_cast<std::size_t>(e - s.solids.count());
  return {"shell", s.shells.ids[i], s.parts[static_cast<std::size_t>(s.shells.part[i])].id};
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
