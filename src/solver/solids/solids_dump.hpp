#pragma once
/// The hexahedra's restart dump: the member lists of what changes during a run (dump.hpp).
#include "solver/fe/fe_dump.hpp"
#include "solver/solids/solids.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, SolidBlock& b) {
  ar(b.part, b.begin, b.end, b.point_begin, b.points_per_element, b.formulation, b.material,
     b.hourglass, b.bulk_viscosity, b.objective);
}

template <class Ar>
void fields(Ar& ar, Solids& s) {
  ar(s.ids, s.nodes, s.part, s.initial_volume, s.volume, s.mass, s.pressure, s.eos_energy,
     s.temperature, s.internal_energy, s.hourglass_energy, s.hourglass_force, s.viscosity,
     s.time_step, s.added_mass, s.eroded, s.corner_force, s.blocks, s.points, s.corner_offsets,
     s.node_corners);
}

inline constexpr auto kSolidsDumpedSizes = core::sizes_of<Solids, SolidBlock>();
static_assert(!core::kSizesPinned || kSolidsDumpedSizes == decltype(kSolidsDumpedSizes){560, 72},
              "Solids or SolidBlock changed: list the new member in fields() above");

}  // namespace mcdyna::solver
