#pragma once
/// The beams' restart dump: the member lists of what changes during a run (dump.hpp).
#include "solver/beams/beams.hpp"
#include "solver/fe/fe_dump.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, BeamBlock& b) {
  ar(b.part, b.begin, b.end, b.point_begin, b.points, b.formulation, b.material, b.shear_factor,
     b.constrained_iterations, b.point_s, b.point_t, b.point_weight);
}

template <class Ar>
void fields(Ar& ar, Beams& b) {
  ar(b.ids, b.nodes, b.part, b.s_axis, b.initial_length, b.mass, b.area, b.inertia_s, b.inertia_t,
     b.torsion, b.shear_area, b.width_s, b.width_t, b.end_inertia, b.flexural_step, b.resultants,
     b.temperature, b.internal_energy, b.time_step, b.added_mass, b.eroded, b.corner_force,
     b.blocks, b.points, b.end_offsets, b.ends);
}

inline constexpr auto kBeamsDumpedSizes = core::sizes_of<Beams, BeamBlock>();
static_assert(!core::kSizesPinned || kBeamsDumpedSizes == decltype(kBeamsDumpedSizes){672, 432},
              "Beams or BeamBlock changed: list the new member in fields() above");

}  // namespace mcdyna::solver
