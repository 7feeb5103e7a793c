#pragma once
/// A contact interface's restart dump: the member lists of what changes during a run (dump.hpp).
#include "core/pinned_sizes.hpp"
#include "solver/contact/interface.hpp"

namespace mcdyna::solver::contact {

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
     c.damping, c.birth, c.death, c.switched_off, c.soft_constraint, c.soft_scale, c.penalty_scale,
     c.sort_interval, c.initial_step, c.initial_penetration, c.segment_based, c.segment_based_scale,
     c.sensor);
  ar(c.last_sort, c.sorted_positions, c.tracked, c.capture, c.force_a, c.force_b, c.moment_a,
     c.moment_b, c.mass_in_contact, c.energy, c.applied, c.computed);
}

inline constexpr auto kInterfaceDumpedSizes = core::sizes_of<Interface, Pass, Surface>();
static_assert(!core::kSizesPinned ||
                  kInterfaceDumpedSizes == decltype(kInterfaceDumpedSizes){456, 352, 144},
              "contact::Interface, Pass or Surface changed: list the new member in fields() above");

}  // namespace mcdyna::solver::contact
