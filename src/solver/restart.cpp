// The member lists of everything a restart dump holds. A member missing here is a restart that
// silently differs from the run it continues, so the sizes of the structs are pinned below on the
// platform CI builds on: adding a member to one of them stops the build until it is listed here
// (or, if it is deck data, said to be left out). tests/unit/solver/restart_test.cpp checks that a
// run continued from a dump writes the same bits as one that never stopped.
#include "solver/restart.hpp"

#include <array>
#include <stdexcept>

namespace mcdyna::solver {

// The dumped structs' sizes: written into every dump (dump_layout) and pinned here.
constexpr std::array<std::size_t, 27> kDumpedSizes = {sizeof(Nodes),
                                                      sizeof(Solids),
                                                      sizeof(SolidBlock),
                                                      sizeof(MaterialPoints),
                                                      sizeof(Shells),
                                                      sizeof(ShellBlock),
                                                      sizeof(ShellPoints),
                                                      sizeof(RigidBody),
                                                      sizeof(RigidMotion),
                                                      sizeof(NodalConstraints),
                                                      sizeof(NodalMotion),
                                                      sizeof(RigidWallState),
                                                      sizeof(State),
                                                      sizeof(spg::Domain),
                                                      sizeof(spg::SpgSettings),
                                                      sizeof(spg::StepBound),
                                                      sizeof(contact::Interface),
                                                      sizeof(contact::Pass),
                                                      sizeof(contact::Surface),
                                                      sizeof(ResumePoint),
                                                      sizeof(JointState),
                                                      sizeof(PointLoadState),
                                                      sizeof(PressureLoadState),
                                                      sizeof(JointStiffnessState),
                                                      sizeof(Beams),
                                                      sizeof(BeamBlock),
                                                      sizeof(WeldState)};

#if defined(__x86_64__) && defined(__GLIBCXX__) && !defined(_GLIBCXX_DEBUG)
static_assert(kDumpedSizes == std::array<std::size_t, 27>{416, 512, 72,  80,  488, 256,  80,
                                                          584, 72,  112, 128, 240, 3072, 1984,
                                                          96,  112, 456, 352, 144, 192,  136,
                                                          56,  64,  304, 624, 432, 120},
              "a struct of kDumpedSizes changed (same order): list its new member in fields() "
              "below, or note it among the deck data left out");
#endif

template <class Ar>
void fields(Ar& ar, Nodes& n) {
  ar(n.ids, n.initial, n.position, n.velocity, n.acceleration, n.force, n.mass, n.added_mass,
     n.rigid_body, n.smoothed, n.corner_offsets, n.corners);
  ar(n.angular_velocity, n.previous_angular_velocity, n.moment, n.rotary_inertia,
     n.shell_corner_offsets, n.shell_corners, n.beam_end_offsets, n.beam_ends);
}

template <class Ar>
void fields(Ar& ar, HourglassParams& h) {
  ar(h.type, h.coefficient);
}

template <class Ar>
void fields(Ar& ar, BulkViscosityParams& b) {
  ar(b.quadratic, b.linear);
}

template <class Ar>
void fields(Ar& ar, SolidBlock& b) {
  ar(b.part, b.begin, b.end, b.point_begin, b.points_per_element, b.formulation, b.material,
     b.hourglass, b.bulk_viscosity, b.objective);
}

template <class Ar>
void fields(Ar& ar, MaterialPoints& p) {
  ar(p.deviator, p.back_stress, p.plastic_strain, p.damage);
}

template <class Ar>
void fields(Ar& ar, Solids& s) {
  ar(s.ids, s.nodes, s.part, s.initial_volume, s.volume, s.mass, s.pressure, s.eos_energy,
     s.temperature, s.internal_energy, s.hourglass_energy, s.hourglass_force, s.viscosity,
     s.time_step, s.added_mass, s.eroded, s.corner_force, s.blocks, s.points);
}

template <class Ar>
void fields(Ar& ar, ShellBlock& b) {
  ar(b.part, b.begin, b.end, b.point_begin, b.in_plane_points, b.layers, b.formulation,
     b.sort_triangles, b.material, b.hourglass, b.bending_hourglass, b.warping_hourglass,
     b.shear_factor, b.thickness_update, b.plane_stress_iterations, b.reference_surface, b.layer_z,
     b.layer_weight);
}

template <class Ar>
void fields(Ar& ar, ShellPoints& p) {
  ar(p.stress, p.back_stress, p.plastic_strain, p.damage);
}

template <class Ar>
void fields(Ar& ar, Shells& s) {
  ar(s.ids, s.nodes, s.part, s.initial_thickness, s.thickness, s.initial_area, s.mass,
     s.corner_inertia, s.temperature, s.internal_energy, s.hourglass_energy, s.hourglass_force,
     s.time_step, s.added_mass, s.eroded, s.corner_force, s.blocks, s.points);
}

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
     b.blocks, b.points);
}

template <class Ar>
void fields(Ar& ar, RigidMotion& m) {
  ar(m.rotation, m.axis, m.kind, m.curve, m.scale, m.birth, m.death, m.rotated);
}

template <class Ar>
void fields(Ar& ar, RigidBody& b) {
  ar(b.part_id, b.mass, b.center, b.initial_center, b.inertia0, b.rotation, b.velocity,
     b.angular_momentum, b.omega, b.previous_velocity, b.previous_omega, b.nodes, b.offsets,
     b.fixed_translation, b.fixed_rotation, b.motions, b.body_force, b.load_force, b.load_moment,
     b.force, b.moment, b.constraint_force, b.constraint_moment, b.constraint_work, b.released);
}

template <class Ar>
void fields(Ar& ar, WeldState& w) {
  ar(w.id, w.body, w.first, w.last, w.normal_force, w.shear_force, w.normal_exponent,
     w.shear_exponent, w.failure_time, w.plastic_strain, w.force, w.normal, w.shear, w.failed_at);
}

template <class Ar>
void fields(Ar& ar, JointState& j) {
  ar(j.id, j.heading, j.kind, j.nodes, j.pairs, j.relative_stiffness, j.reduced_mass, j.stiffness,
     j.initial_step, j.energy, j.force);
}

template <class Ar>
void fields(Ar& ar, PointLoadState& p) {
  ar(p.nodes, p.body, p.axis, p.moment, p.curve, p.scale, p.last);
}

template <class Ar>
void fields(Ar& ar, PressureLoadState& p) {
  ar(p.segments, p.curve, p.scale, p.arrival, p.last);
}

template <class Ar>
void fields(Ar& ar, JointStiffnessState& j) {
  ar(j.id, j.body_a, j.body_b, j.frame_a, j.frame_b, j.curves, j.elastic, j.friction,
     j.friction_moment, j.angles, j.moment, j.work);
}

template <class Ar>
void fields(Ar& ar, NodalConstraints& c) {
  ar(c.nodes, c.masks, c.birth, c.death, c.reaction);
}

template <class Ar>
void fields(Ar& ar, NodalMotion& m) {
  ar(m.id, m.nodes, m.axis, m.kind, m.curve, m.scale, m.birth, m.death, m.node_force, m.node_work);
}

template <class Ar>
void fields(Ar& ar, RigidWallState& w) {
  ar(w.id, w.point, w.normal, w.finite, w.edge_l, w.edge_m, w.length_l, w.length_m, w.friction,
     w.birth, w.death, w.moving, w.mass, w.velocity, w.displacement, w.nodes, w.force, w.energy);
}

template <class Ar>
void fields(Ar& ar, PhaseTimes& p) {
  ar(p.seconds);
}

template <class Ar>
void fields(Ar& ar, ResumePoint& r) {
  ar(r.critical_step, r.controlling_element, r.controlling_domain, r.controlling_particle,
     r.first_step, r.phases, r.wall_seconds, r.core_seconds, r.element_cycles, r.particle_cycles);
}

namespace spg {

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
  ar(d.part, d.material, d.settings, d.particles.nodes, d.particles.mass, d.particles.base_mass,
     d.particles.shared, d.particles.surface, d.particles.initial_volume, d.fields.volume,
     d.particles.initial_position, d.particles.initial_support);
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

}  // namespace spg

namespace contact {

template <class Ar>
void fields(Ar& ar, Surface& s) {
  ar(s.segments, s.stiffness, s.half_thickness, s.two_sided, s.smallest_node_mass, s.area);
}

template <class Ar>
void fields(Ar& ar, Pass& p) {
  ar(p.nodes, p.stiffness, p.node_half_thickness, p.nodes_on_side_a, p.surface, p.candidate_offsets,
     p.candidates, p.near, p.friction, p.side, p.initial_penetration);
}

template <class Ar>
void fields(Ar& ar, AppliedForce& f) {
  ar(f.node, f.hit, f.slot, f.force);
}

template <class Ar>
void fields(Ar& ar, Transducer& t) {
  ar(t.active, t.nodes_a, t.nodes_b);
}

template <class Ar>
void fields(Ar& ar, Interface& c) {
  ar(c.id, c.heading, c.passes, c.static_friction, c.dynamic_friction, c.decay, c.viscous_friction,
     c.damping, c.birth, c.death, c.soft_constraint, c.soft_scale, c.penalty_scale, c.sort_interval,
     c.initial_step, c.initial_penetration, c.segment_based, c.segment_based_scale, c.sensor);
  ar(c.last_sort, c.sorted_positions, c.tracked, c.capture, c.force_a, c.force_b, c.moment_a,
     c.moment_b, c.mass_in_contact, c.energy, c.applied, c.computed);
}

}  // namespace contact

// Left out, as deck data compiled again on restart: title, parts, materials, rigid_cells, ties,
// blocks, curves, body_loads, damping, time_control, mass_scaling_dt (from DT2MS and TSSFAC; both
// changed by
// --fixed-step). Each section of kStateSections is checksummed on its own in the dump, so a damaged
// one is named.
template <class Ar>
void state_section(Ar& ar, State& s, std::size_t section) {
  switch (section) {
    case 0:
      return ar(s.nodes);
    case 1:
      return ar(s.solids, s.shells, s.beams);
    case 2:
      return ar(s.spg);
    case 3:
      return ar(s.rigid_bodies, s.joints, s.joint_stiffnesses, s.welds);
    case 4:
      return ar(s.constraints, s.nodal_motions, s.point_loads, s.pressure_loads, s.load_work,
                s.damping_work);
    case 5:
      return ar(s.rigid_walls);
    case 6:
      return ar(s.contacts);
    case 7:
      // Of s.ownership only the owners: a restart on the same process count takes them (each
      // dump holds the SPG rows its process read); the time loop rebuilds the rest.
      return ar(s.ownership.owner, s.time, s.cycle, s.step, s.critical_step, s.controlling_element,
                s.controlling_domain, s.controlling_particle, s.external_work, s.eroded_kinetic,
                s.eroded_internal, s.eroded_hourglass, s.initial_energy, s.initial_mass);
    default:
      throw std::logic_error("no such dump section");
  }
}
static_assert(kStateSections.size() == 8, "state_section() lists one case per section");

std::string dump_layout() {
  std::string out;
  for (const std::size_t n : kDumpedSizes)
    out += std::to_string(n) + " ";
  return out;
}

void save_state_section(core::OutArchive& ar, const State& state, std::size_t section) {
  // fields() lists members once for both directions; nothing is written to `state`
  state_section(ar, const_cast<State&>(state), section);
}

void load_state_section(core::InArchive& ar, State& state, std::size_t section) {
  state_section(ar, state, section);
}

void save_resume_point(core::OutArchive& ar, const ResumePoint& point) {
  ar(const_cast<ResumePoint&>(point));
}

void load_resume_point(core::InArchive& ar, ResumePoint& point) {
  ar(point);
}

}  // namespace mcdyna::solver
