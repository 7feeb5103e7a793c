// The joints as one block of the time loop (*CONSTRAINED_JOINT_*): a penalty spring on each node
// pair pulls body B's node back onto body A's along the directions the joint holds: all three
// (spherical: one pair; revolute: two pairs on the axis, which leaves the turning about it), or
// those normal to the axis N1 -> N3 (cylindrical: two pairs, sliding and turning free;
// translational: a third pair off the axis, which stops the turning).
//
// The spring is k = RPS m* / (4 dt0^2), m* the smallest reduced mass of the pairs (a rigid body's
// node counts the least mass its point answers a force with, compile_joints.cpp) and dt0 the
// first cycle's step: the pair's own period is
// then 4 pi dt0, far inside the central-difference limit of pi dt0 for any step up to four times
// the first. LS-DYNA's joint stiffness and damping are not published; these springs are
// undamped, and the energy they store counts as internal energy.
//
// Every process computes every joint whole and moves its nodes itself (mark_replicated).
#include <algorithm>
#include <cmath>

#include "model/conditions.hpp"
#include "solver/block.hpp"
#include "solver/rigid/joint_state.hpp"
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/rigid/rigid_dump.hpp"
#include "solver/sensors/switchable.hpp"

namespace mcdyna::solver {

namespace {

Vec3 at(const State& s, Index n) {
  return s.nodes.position.col(n);
}

// Spherical and revolute: each pair's B node is pulled onto its A node, all three directions.
void hold_points(const State& s, JointState& j, Eigen::Matrix3Xd& force) {
  for (int p = 0; p < j.pairs; ++p) {
    const Index a = j.nodes[static_cast<std::size_t>(2 * p)];
    const Index b = j.nodes[static_cast<std::size_t>(2 * p + 1)];
    const Vec3 d = at(s, b) - at(s, a);
    const Vec3 f = j.stiffness * d;  // pulls a towards b and b towards a
    force.col(a) += f;
    force.col(b) -= f;
    j.force -= f;
    j.energy += 0.5 * j.stiffness * d.squaredNorm();
  }
}

// The spring of a pair held on a line: sized, like the others, to the reduced mass of its two
// sides, but where A is pulled, at the B node's place along the line. On a rigid A that is the
// body's mass at that point (the couple on N1 and N3 turns it as a force there would); on
// deformable nodes the couple's lever t = s / l raises the stiffness they feel by up to
// (1 + |t|)^2, and the spring softens by as much. Either way the joint stays inside the step
// however far it slides.
double line_stiffness(const State& s, const JointState& j, Index anchor, Index b, const Vec3& point,
                      double lever) {
  const Index body = s.nodes.rigid_body[static_cast<std::size_t>(anchor)];
  const bool rigid_line = body >= 0 &&
                          s.nodes.rigid_body[static_cast<std::size_t>(j.nodes[0])] == body &&
                          s.nodes.rigid_body[static_cast<std::size_t>(j.nodes[2])] == body;
  if (!rigid_line) {
    const double soften = 1.0 + std::abs(lever);
    return j.stiffness / (soften * soften);
  }
  const double reduced = reduced_mass(point_mass(s, body, point), node_mass_at(s, b, at(s, b)));
  if (std::isinf(reduced)) return 0.0;
  return 0.25 * j.relative_stiffness * reduced / (j.initial_step * j.initial_step);
}

// Cylindrical and translational: each pair's B node is pulled onto the line through its anchor
// (N1 for the axis pairs, N5 for the translational third) along A's axis N1 -> N3. The pull on A
// acts where the B node is along the line, not at the anchor: the force at the anchor plus the
// couple s/l f on N3 and -s/l f on N1 (s the B node's distance along the axis from the anchor,
// l = |N3 - N1|), the statics of a rigid line. At the anchor alone it would be a follower
// moment that grows with the slide and feeds the motion.
void hold_on_lines(const State& s, JointState& j, Eigen::Matrix3Xd& force) {
  const Index n1 = j.nodes[0], n3 = j.nodes[2];
  const Vec3 axis = at(s, n3) - at(s, n1);
  const double length = axis.norm();
  const Vec3 unit = axis / length;
  for (int p = 0; p < j.pairs; ++p) {
    const Index anchor = p < 2 ? n1 : j.nodes[4];
    const Index b = j.nodes[static_cast<std::size_t>(2 * p + 1)];
    const Vec3 r = at(s, b) - at(s, anchor);
    const double along = r.dot(unit);
    const Vec3 d = r - along * unit;
    const double k = line_stiffness(s, j, anchor, b, at(s, anchor) + along * unit, along / length);
    const Vec3 f = k * d;
    force.col(anchor) += f;
    force.col(n3) += (along / length) * f;
    force.col(n1) -= (along / length) * f;
    force.col(b) -= f;
    j.force -= f;
    j.energy += 0.5 * k * d.squaredNorm();
  }
}

void joint_forces(const State& s, JointState& j, Eigen::Matrix3Xd& force) {
  if (j.stiffness == 0.0) {
    if (!(s.step > 0.0)) return;  // the first cycle: the pairs still coincide
    j.initial_step = s.step;
    j.stiffness = 0.25 * j.relative_stiffness * j.reduced_mass / (s.step * s.step);
  }
  j.energy = 0.0;
  j.force.setZero();
  if (j.switched_off) return;
  const model::JointKind kind = j.kind;
  if (kind == model::JointKind::cylindrical || kind == model::JointKind::translational)
    hold_on_lines(s, j, force);
  else
    hold_points(s, j, force);
}

// A generalized joint stiffness: the rotation that takes A's local axes to B's, as a rotation
// vector on A's axes, gives the angles (phi, theta, psi); about each axis the moment is the
// curve's at that angle plus an elastic-plastic friction moment, ES times the angle's change
// capped at FM. It turns B back (and A the other way) about A's axis.
void joint_stiffness(State& s, JointStiffnessState& j) {
  RigidBody& a = s.rigid_bodies[static_cast<std::size_t>(j.body_a)];
  RigidBody& b = s.rigid_bodies[static_cast<std::size_t>(j.body_b)];
  const Mat3 axes_a = a.rotation * j.frame_a, axes_b = b.rotation * j.frame_b;
  const Eigen::AngleAxisd turn(axes_a.transpose() * axes_b);
  const Vec3 angles = turn.angle() * turn.axis();
  Vec3 moment = Vec3::Zero();  // on B, about A's axes
  for (int k = 0; k < 3; ++k) {
    double m = 0.0;
    if (j.curves[static_cast<std::size_t>(k)] >= 0)
      m += s.curves[static_cast<std::size_t>(j.curves[static_cast<std::size_t>(k)])](angles[k]);
    if (j.friction[k] > 0.0) {
      double& f = j.friction_moment[k];
      f = std::clamp(f + j.elastic[k] * (angles[k] - j.angles[k]), -j.friction[k], j.friction[k]);
      m += f;
    }
    moment[k] = -m;
  }
  // Work done on the springs over the turn since last cycle, by the trapezoidal rule.
  j.work -= 0.5 * (j.moment + moment).dot(angles - j.angles);
  j.angles = angles;
  j.moment = moment;
  const Vec3 global = axes_a * moment;
  b.load_moment += global;
  a.load_moment -= global;
}

// The block owns its joints (joint_state.hpp).
class JointsBlock final : public DumpedBlock<JointsBlock> {
 public:
  JointsBlock(std::vector<JointState> joints, std::vector<JointStiffnessState> stiffnesses)
      : joints_(std::move(joints)), stiffnesses_(std::move(stiffnesses)) {}
  [[nodiscard]] std::string dump_name() const override { return "joints"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kJointsDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(joints_, stiffnesses_);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::rigid; }
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    for (const JointState& j : joints_)
      for (int k = 0; k < 2 * j.pairs; ++k)
        nodes[static_cast<std::size_t>(j.nodes[static_cast<std::size_t>(k)])] = 1;
  }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    for (const JointState& j : joints_)
      e.internal += j.energy;
    for (const JointStiffnessState& j : stiffnesses_)
      e.internal += j.work;
  }
  bool sensed_force(const State& /*s*/, model::SensedEntity kind, model::Id id,
                    Vec3& force) const override {
    return sensors::sensed_force_in(
        joints_, model::SensedEntity::joint, kind, id, [](const JointState& j) { return j.force; },
        force);
  }
  bool switch_entity(State& /*s*/, model::SensedEntity kind, model::Id id, bool on) override {
    return sensors::switch_in(joints_, model::SensedEntity::joint, kind, id, on);
  }
  void forces(State& s, NodalForces& f, ForceReport& /*report*/) override {
    for (JointState& j : joints_)
      joint_forces(s, j, f.force);
    for (JointStiffnessState& j : stiffnesses_)
      joint_stiffness(s, j);
  }
  [[nodiscard]] const std::vector<JointStiffnessState>& stiffnesses() const { return stiffnesses_; }

 private:
  std::vector<JointState> joints_;
  std::vector<JointStiffnessState> stiffnesses_;
};

}  // namespace

const std::vector<JointStiffnessState>& joint_stiffnesses_of(const State& s) {
  return owned_by(s, &JointsBlock::stiffnesses);
}

std::unique_ptr<Block> make_joints_block(std::vector<JointState> joints,
                                         std::vector<JointStiffnessState> stiffnesses) {
  return std::make_unique<JointsBlock>(std::move(joints), std::move(stiffnesses));
}

}  // namespace mcdyna::solver
