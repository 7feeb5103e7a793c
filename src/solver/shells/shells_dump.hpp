#pragma once
/// The shells' restart dump: the member lists of what changes during a run (dump.hpp).
#include "solver/fe/fe_dump.hpp"
#include "solver/shells/shells.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, ShellBlock& b) {
  ar(b.part, b.begin, b.end, b.point_begin, b.in_plane_points, b.layers, b.formulation,
     b.sort_triangles, b.material, b.hourglass, b.bending_hourglass, b.warping_hourglass,
     b.shear_factor, b.thickness_update, b.plane_stress_iterations, b.reference_surface, b.layer_z,
     b.layer_weight);
}

template <class Ar>
void fields(Ar& ar, Shells& s) {
  ar(s.ids, s.nodes, s.part, s.initial_thickness, s.thickness, s.initial_area, s.mass,
     s.corner_inertia, s.temperature, s.internal_energy, s.hourglass_energy, s.hourglass_force,
     s.time_step, s.added_mass, s.eroded, s.corner_force, s.blocks, s.points, s.corner_offsets,
     s.node_corners);
}

inline constexpr auto kShellsDumpedSizes = core::sizes_of<Shells, ShellBlock>();
static_assert(!core::kSizesPinned || kShellsDumpedSizes == decltype(kShellsDumpedSizes){536, 256},
              "Shells or ShellBlock changed: list the new member in fields() above");

}  // namespace mcdyna::solver
