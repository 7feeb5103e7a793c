#pragma once
/// Member lists of the integration-point and element parameters the finite-element blocks share
/// (solids, shells, beams), for their restart dumps (dump.hpp).
#include "solver/fe/hourglass.hpp"
#include "solver/fe/shell_points.hpp"
#include "solver/material/material_dump.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, HourglassParams& h) {
  ar(h.form, h.coefficient);
}

template <class Ar>
void fields(Ar& ar, ShellPoints& p) {
  ar(p.stress, p.back_stress, p.plastic_strain, p.damage);
}

inline constexpr auto kShellPointSizes = core::sizes_of<ShellPoints>();
static_assert(!core::kSizesPinned || kShellPointSizes == decltype(kShellPointSizes){80},
              "ShellPoints changed: list the new member in fields() above");

}  // namespace mcdyna::solver
