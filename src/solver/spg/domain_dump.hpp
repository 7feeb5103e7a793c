#pragma once
/// An SPG part's restart dump: the member lists of what changes during a run (dump.hpp).
#include "solver/material/material_dump.hpp"
#include "solver/spg/domain.hpp"

namespace mcdyna::solver::spg {

template <class Ar>
void fields(Ar& ar, SpgSettings& s) {
  ar(s.shape, s.kernel_update, s.renewal_interval, s.renewal_strain, s.stabilization,
     s.bond_failure, s.failure_strain, s.failure_stretch, s.damping, s.surface_factor,
     s.mode_control, s.bulk_viscosity, s.step_estimate, s.objective);
}

template <class Ar>
void fields(Ar& ar, Supports& s) {
  ar(s.to_unit, s.reach);
}

template <class Ar>
void fields(Ar& ar, NeighbourList& l) {
  ar(l.offsets, l.neighbours);
}

template <class Ar>
void fields(Ar& ar, ShapeFunctions& f) {
  ar(f.value, f.gradient, f.hessian);
}

template <class Ar>
void fields(Ar& ar, Transpose& t) {
  ar(t.offsets, t.pairs, t.rows, t.gather, t.gradient);
}

template <class Ar>
void fields(Ar& ar, Bonds& b) {
  ar(b.offsets, b.partners, b.broken, b.length);
}

template <class Ar>
void fields(Ar& ar, SpgTimes& t) {
  ar(t.neighbours, t.shape_functions, t.smoothing, t.stress, t.force);
}

template <class Ar>
void fields(Ar& ar, StepBound& b) {
  ar(b.lengths, b.scale, b.initial_critical, b.critical, b.smallest_critical,
     b.smallest_critical_particle, b.smallest_critical_time, b.mode, b.pass_step, b.physical,
     b.physical_particle);
}

template <class Ar>
void fields(Ar& ar, Domain& d) {
  ar(d.part, d.material, d.index, d.settings, d.particles.nodes, d.particles.mass,
     d.particles.base_mass, d.particles.shared, d.particles.surface, d.particles.initial_volume,
     d.fields.volume, d.particles.initial_position, d.particles.initial_support);
  ar(d.kernel.support, d.kernel.reference_deformation, d.kernel.list, d.kernel.shape,
     d.kernel.transpose, d.kernel.smoothed_mass, d.particles.added_mass, d.particles.mass_request,
     d.kernel.pinned, d.kernel.length, d.kernel.mobility, d.kernel.mobility_scale,
     d.diagnostics.largest_mobility, d.diagnostics.largest_mobility_particle,
     d.diagnostics.largest_mobility_time, d.fields.step, d.kernel.renewal_volume,
     d.kernel.step_bound, d.kernel.gradient_length_scale, d.kernel.steps_since_renewal,
     d.diagnostics.renewals, d.diagnostics.renewed_rows, d.kernel.isolated,
     d.diagnostics.degenerate_events, d.diagnostics.first_degenerate,
     d.diagnostics.first_degenerate_time);
  ar(d.fields.unsmoothed, d.fields.unsmoothed_previous, d.fields.smoothed);
  ar(d.fields.points, d.fields.pressure, d.fields.eos_energy, d.fields.temperature,
     d.fields.viscosity, d.fields.internal_energy, d.fields.failed, d.fields.deformation,
     d.fields.stress_gradient, d.fields.damping_energy);
  ar(d.fields.mode_stiffness, d.fields.mode_residual, d.fields.mode_force, d.fields.mode_energy);
  ar(d.fields.gradient.moment, d.fields.gradient.strain, d.fields.gradient.stress,
     d.fields.gradient.step_scale, d.fields.gradient.bulk, d.fields.gradient.shear,
     d.fields.gradient.applied_bulk, d.fields.gradient.applied_shear);
  ar(d.kernel.bonds, d.diagnostics.broken_bonds, d.diagnostics.released, d.fields.debris, d.times);
  // d.scratch is left out: a workspace every call refills before reading it.
}

inline constexpr auto kDomainDumpedSizes = core::sizes_of<Domain, SpgSettings, StepBound>();
static_assert(
    !core::kSizesPinned || kDomainDumpedSizes == decltype(kDomainDumpedSizes){1992, 96, 112},
    "spg::Domain, SpgSettings or StepBound changed: list the new member in fields() above");

}  // namespace mcdyna::solver::spg
