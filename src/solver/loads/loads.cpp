#include "solver/loads/loads.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdyna::solver {

void apply_body_loads(State& state, const std::vector<BodyLoadState>& loads,
                      Eigen::Matrix3Xd& force) {
  if (loads.empty()) return;
  Vec3 a = Vec3::Zero();
  for (const BodyLoadState& b : loads)
    a[b.axis] += b.scale * state.curves[static_cast<std::size_t>(b.curve)](state.time);
  const Nodes& nd = state.nodes;
#pragma omp parallel for schedule(static) if (nd.count() > 2048)
  for (Index n = 0; n < nd.count(); ++n)
    if (nd.rigid_body[static_cast<std::size_t>(n)] < 0)
      force.col(n) -= nd.mass[static_cast<std::size_t>(n)] * a;
  for (RigidBody& b : state.rigid_bodies)
    if (!b.released) b.body_force = -b.mass * a;
}

double nodal_mass(const Nodes& nd, Index n) {
  const auto i = static_cast<std::size_t>(n);
  return nd.mass[i] + nd.added_mass[i];
}

// Work of an impulse J applied during the cycle that took the node from v^{n-1/2} to v^{n+1/2}:
// J . (v^{n-1/2} + v^{n+1/2}) / 2. With this split the element forces and the boundary impulses
// add up exactly to the change of 1/2 m v^2 over the cycle (a node pressed against a wall at
// rest does no work).
double impulse_work(const Vec3& impulse, const Vec3& v_start, const Vec3& v_end) {
  return 0.5 * impulse.dot(v_start + v_end);
}

WallLanding land_on_wall(Nodes& nd, Index n, const StepTimes& t, double gap, const Vec3& normal,
                         const Vec3& wall_velocity, double friction) {
  WallLanding l;
  Vec3 v = nd.velocity.col(n);
  const Vec3 v_before = v;
  l.start = v - t.mean * Vec3(nd.acceleration.col(n));  // v^{n-1/2}
  l.normal_change = -gap / t.step;  // normal velocity change that lands the node on the wall
  v += l.normal_change * normal;
  if (friction > 0.0) {
    const Vec3 relative = v - wall_velocity;
    const Vec3 vt = relative - relative.dot(normal) * normal;
    const double speed = vt.norm();
    const double allowed = friction >= 1.0 ? speed : friction * l.normal_change;
    if (speed > 0.0) v -= std::min(speed, allowed) / speed * vt;
  }
  l.change = v - v_before;
  l.end = v;
  nd.velocity.col(n) = v;
  nd.acceleration.col(n) += l.change / t.mean;
  return l;
}

void apply_nodal_constraints(State& state, NodalConstraints& c, const StepTimes& t) {
  Nodes& nd = state.nodes;
  for (std::size_t k = 0; k < c.nodes.size(); ++k) {
    const Index n = c.nodes[k];
    const auto col = static_cast<Index>(k);
    c.reaction.col(col).setZero();
    if (t.time < c.birth[k] || t.time > c.death[k]) continue;
    const double m = nodal_mass(nd, n);
    for (int i = 0; i < 3; ++i) {
      if (!(c.masks[k] & (1u << i))) continue;
      c.reaction(i, col) = -m * nd.velocity(i, n) / t.mean;
      nd.velocity(i, n) = 0.0;
      nd.acceleration(i, n) = 0.0;
    }
    if (c.masks[k] >> 3 && !nd.rotary_inertia.empty() &&
        nd.rotary_inertia[static_cast<std::size_t>(n)] > 0.0)
      for (int i = 0; i < 3; ++i)
        if (c.masks[k] & (8u << i)) nd.angular_velocity(i, n) = 0.0;
  }
}

void apply_nodal_motions(State& state, std::vector<NodalMotion>& motions, const StepTimes& t) {
  Nodes& nd = state.nodes;
  for (NodalMotion& nm : motions) {
    nm.node_force.setZero();
    if (nm.switched_off || t.time < nm.birth || t.time > nm.death) continue;
    const Vec3& axis = nm.axis;
    for (std::size_t k = 0; k < nm.nodes.size(); ++k) {
      const Index n = nm.nodes[k];
      const Vec3 v = nd.velocity.col(n);
      const double now = axis.dot(v);
      double target = 0.0;
      if (nm.kind == MotionKind::acceleration) {
        // `now` includes this cycle's free acceleration; the prescribed one replaces it.
        const double before = now - t.mean * axis.dot(Vec3(nd.acceleration.col(n)));
        target = before + t.mean * motion_value(state, nm.curve, nm.scale, nm.birth, t.time);
      } else if (nm.kind == MotionKind::displacement) {
        const double u = axis.dot(Vec3(nd.position.col(n)) - Vec3(nd.initial.col(n)));
        target = displacement_velocity(state, nm.curve, nm.scale, nm.birth, u, t.time, t.step);
      } else {
        target = motion_value(state, nm.curve, nm.scale, nm.birth, t.time + 0.5 * t.step);
      }
      const Vec3 dv = (target - now) * axis;
      const Vec3 f = nodal_mass(nd, n) * dv / t.mean;
      const Vec3 v_start = v - t.mean * Vec3(nd.acceleration.col(n));  // v^{n-1/2}
      nd.velocity.col(n) = v + dv;
      nd.acceleration.col(n) += dv / t.mean;
      nm.node_force.col(static_cast<Index>(k)) = f;
      nm.node_work[k] += impulse_work(f * t.mean, v_start, v + dv);
    }
  }
}

}  // namespace mcdyna::solver
