#pragma once
/// The conditions' and loads' restart dumps: the member lists of what changes during a run
/// (dump.hpp).
#include "core/pinned_sizes.hpp"
#include "solver/loads/load_state.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, NodalConstraints& c) {
  ar(c.nodes, c.masks, c.birth, c.death, c.reaction);
}

template <class Ar>
void fields(Ar& ar, NodalMotion& m) {
  ar(m.id, m.nodes, m.axis, m.kind, m.curve, m.scale, m.birth, m.death, m.switched_off,
     m.node_force, m.node_work);
}

template <class Ar>
void fields(Ar& ar, PointLoadState& p) {
  ar(p.nodes, p.body, p.axis, p.moment, p.curve, p.scale, p.last);
}

template <class Ar>
void fields(Ar& ar, PressureLoadState& p) {
  ar(p.segments, p.curve, p.scale, p.arrival, p.last);
}

inline constexpr auto kConditionDumpedSizes = core::sizes_of<NodalConstraints, NodalMotion>();
static_assert(!core::kSizesPinned ||
                  kConditionDumpedSizes == decltype(kConditionDumpedSizes){112, 136},
              "NodalConstraints or NodalMotion changed: list the new member in fields() above");
inline constexpr auto kLoadDumpedSizes = core::sizes_of<PointLoadState, PressureLoadState>();
static_assert(!core::kSizesPinned || kLoadDumpedSizes == decltype(kLoadDumpedSizes){56, 64},
              "PointLoadState or PressureLoadState changed: list the new member in fields() above");

}  // namespace mcdyna::solver
