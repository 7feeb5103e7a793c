#pragma once
/// Member lists of the material state at integration points and particles, for the restart
/// dumps of the blocks that hold them (dump.hpp).
#include "core/pinned_sizes.hpp"
#include "solver/material/material.hpp"
#include "solver/material/point_kinematics.hpp"

namespace mcdyna::solver {

template <class Ar>
void fields(Ar& ar, BulkViscosityParams& b) {
  ar(b.quadratic, b.linear);
}

template <class Ar>
void fields(Ar& ar, MaterialPoints& p) {
  ar(p.deviator, p.back_stress, p.plastic_strain, p.damage);
}

inline constexpr auto kMaterialPointSizes = core::sizes_of<MaterialPoints>();
static_assert(!core::kSizesPinned || kMaterialPointSizes == decltype(kMaterialPointSizes){80},
              "MaterialPoints changed: list the new member in fields() above");

}  // namespace mcdyna::solver
