#pragma once
/// The rigid bodies', welds' and joints' restart dumps: the member lists of what changes during
/// a run (dump.hpp).
#include "core/pinned_sizes.hpp"
#include "solver/rigid/joint_state.hpp"
#include "solver/rigid/welds.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

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
     j.initial_step, j.energy, j.force, j.switched_off);
}

template <class Ar>
void fields(Ar& ar, JointStiffnessState& j) {
  ar(j.id, j.body_a, j.body_b, j.frame_a, j.frame_b, j.curves, j.elastic, j.friction,
     j.friction_moment, j.angles, j.moment, j.work);
}

inline constexpr auto kRigidDumpedSizes = core::sizes_of<RigidBody, RigidMotion, WeldState>();
static_assert(!core::kSizesPinned || kRigidDumpedSizes == decltype(kRigidDumpedSizes){584, 72, 120},
              "RigidBody, RigidMotion or WeldState changed: list the new member in fields() above");
inline constexpr auto kJointsDumpedSizes = core::sizes_of<JointState, JointStiffnessState>();
static_assert(!core::kSizesPinned || kJointsDumpedSizes == decltype(kJointsDumpedSizes){144, 304},
              "JointState or JointStiffnessState changed: list the new member in fields() above");

}  // namespace mcdyna::solver
