#include "solver/rigid/rigid_bodies.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <array>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mcdyna::solver {

double motion_value(const State& state, Index curve, double scale, double birth, double t) {
  return scale * state.curves[static_cast<std::size_t>(curve)](t - birth);
}

double displacement_velocity(const State& state, Index curve, double scale, double birth,
                             double current, double time, double step) {
  return (motion_value(state, curve, scale, birth, time + step) - current) / step;
}

namespace {

// Velocity constraints on one vector quantity (v or omega), kept as an orthonormal basis of
// the constrained directions (modified Gram-Schmidt, in the order they come) and the
// coordinates along it of the smallest vector that meets them: x0 = sum_j coord_j basis_j with
// x0 . d_k = value_k. A direction already in the span of the earlier ones (its remainder
// shorter than kParallel) adds nothing: the earlier constraint holds, and the material's CON1 /
// CON2 flags come before the prescribed motions, in deck order. Closed forms on 3-vectors: an
// SVD of the constraint matrix did the same and took two thirds of this file's compile (24.6 s
// of Release compile -> 8.2 s without it).
class DirectionConstraints {
 public:
  void add(const Vec3& d, double value) {
    if (rank_ == 3) return;
    Vec3 r = d;
    double rest = value;
    for (int j = 0; j < rank_; ++j) {
      const double p = basis_[static_cast<std::size_t>(j)].dot(r);
      r -= p * basis_[static_cast<std::size_t>(j)];
      rest -= p * coord_[static_cast<std::size_t>(j)];
    }
    const double length = r.norm();
    if (length <= kParallel * d.norm()) return;
    basis_[static_cast<std::size_t>(rank_)] = r / length;
    coord_[static_cast<std::size_t>(rank_)] = rest / length;
    ++rank_;
  }
  int rank() const { return rank_; }

  // Solves for x with x . d_k = value_k on the constrained directions and A x = b on the
  // free ones (A = M I for translation, the inertia tensor for rotation, symmetric positive
  // definite): x = x0 + F y with F an orthonormal basis of the free directions and
  // (F^T A F) y = F^T (b - A x0), closed form for one or two free directions.
  Vec3 solve(const Mat3& a, const Vec3& b) const {
    if (rank_ == 0) return a.ldlt().solve(b);
    Vec3 x0 = Vec3::Zero();
    for (int j = 0; j < rank_; ++j)
      x0 += coord_[static_cast<std::size_t>(j)] * basis_[static_cast<std::size_t>(j)];
    if (rank_ == 3) return x0;
    const Vec3 residual = b - a * x0;
    if (rank_ == 2) {
      const Vec3 f = basis_[0].cross(basis_[1]);  // unit: the two are orthonormal
      return x0 + (f.dot(residual) / f.dot(a * f)) * f;
    }
    // One constrained direction q: the free plane spanned by the coordinate axis least along
    // q (made orthogonal to it) and q x that.
    const Vec3& q = basis_[0];
    Index axis = 0;
    q.cwiseAbs().minCoeff(&axis);
    const Vec3 f1 = (Vec3::Unit(axis) - q[axis] * q).normalized();
    const Vec3 f2 = q.cross(f1);
    const double a11 = f1.dot(a * f1), a12 = f1.dot(a * f2), a22 = f2.dot(a * f2);
    const double r1 = f1.dot(residual), r2 = f2.dot(residual);
    const double det = a11 * a22 - a12 * a12;  // > 0: A is positive definite
    return x0 + ((a22 * r1 - a12 * r2) / det) * f1 + ((a11 * r2 - a12 * r1) / det) * f2;
  }

 private:
  static constexpr double kParallel = 1e-9;  // a remainder this short is round-off of d
  std::array<Vec3, 3> basis_{};
  std::array<double, 3> coord_{};
  int rank_ = 0;
};

bool active(const RigidMotion& m, double t) {
  return t >= m.birth && t <= m.death;
}

// Target velocity component of a prescribed motion over the step starting at t.
double target(const State& s, const RigidBody& b, const RigidMotion& m, double previous,
              double rotated, const StepTimes& t) {
  const double t_half = t.time + 0.5 * t.step;
  switch (m.kind) {
    case MotionKind::acceleration:
      return previous + t.mean * motion_value(s, m.curve, m.scale, m.birth, t.time);
    case MotionKind::displacement: {
      const double now = m.rotation ? rotated : m.axis.dot(b.center - b.initial_center);
      return displacement_velocity(s, m.curve, m.scale, m.birth, now, t.time, t.step);
    }
    case MotionKind::velocity:
      break;
  }
  return motion_value(s, m.curve, m.scale, m.birth, t_half);
}

Mat3 rotation_increment(const Vec3& omega, double dt) {
  const double angle = omega.norm() * dt;
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix();
}

// The resultant force and moment (about the centre) of the forces on a body's nodes, as exact
// sums (core::ExactSum): each node on the process that owns it, then over the processes, so
// the bits do not depend on their number (issue 25). Nodes without force are skipped.
std::pair<Vec3, Vec3> node_resultants(const State& state, const NodalForces& forces,
                                      const RigidBody& b) {
  const Nodes& nd = state.nodes;
  const parallel::Ownership& own = state.ownership;
  std::vector<core::ExactSum> sums(6);
  const bool rotations = forces.rotations();  // shell nodes carry moments too
  for (const Index n : b.nodes) {
    const Vec3 f = forces.force.col(n);
    const Vec3 couple = rotations ? Vec3(forces.moment.col(n)) : Vec3::Zero();
    if (!own.owns_node(n) || (f.isZero(0.0) && couple.isZero(0.0))) continue;
    const Vec3 m = (Vec3(nd.position.col(n)) - b.center).cross(f) + couple;
    for (int k = 0; k < 3; ++k) {
      sums[static_cast<std::size_t>(k)].add(f[k]);
      sums[static_cast<std::size_t>(3 + k)].add(m[k]);
    }
  }
  const std::vector<double> total = own.comm.sum(sums);
  return {Vec3(total[0], total[1], total[2]), Vec3(total[3], total[4], total[5])};
}

}  // namespace

Index advance_rigid_bodies(State& state, const NodalForces& forces, const StepTimes& t) {
  Nodes& nd = state.nodes;
  Index bad = -1;  // the first node of the first body whose motion is not finite
  for (RigidBody& b : state.rigid_bodies) {
    if (b.released) continue;
    auto [force, moment] = node_resultants(state, forces, b);
    force += b.body_force + b.load_force;  // at the centre of mass: no moment
    moment += b.load_moment;
    b.load_force.setZero();  // this cycle's loads and damping, taken
    b.load_moment.setZero();
    b.force = force;
    b.moment = moment;
    const Vec3 v_free = b.velocity + t.mean * force / b.mass;
    const Vec3 l_free = b.angular_momentum + t.mean * moment;
    DirectionConstraints lin, ang;
    for (int k = 0; k < 3; ++k) {
      if (b.fixed_translation[static_cast<std::size_t>(k)]) lin.add(Vec3::Unit(k), 0.0);
      if (b.fixed_rotation[static_cast<std::size_t>(k)]) ang.add(Vec3::Unit(k), 0.0);
    }
    for (RigidMotion& m : b.motions) {
      if (!active(m, t.time)) continue;
      const bool rotation = m.rotation;
      const Vec3& axis = m.axis;
      const double previous = axis.dot(rotation ? b.omega : b.velocity);
      const double value = target(state, b, m, previous, m.rotated, t);
      (rotation ? ang : lin).add(axis, value);
      if (rotation) m.rotated += value * t.step;
    }
    const Mat3 inertia = b.inertia();
    const Vec3 v_new = lin.solve(b.mass * Mat3::Identity(), b.mass * v_free);
    const Vec3 w_new = ang.solve(inertia, l_free);
    b.constraint_force = b.mass * (v_new - v_free) / t.mean;
    b.angular_momentum = ang.rank() == 0 ? l_free : Vec3(inertia * w_new);
    b.constraint_moment = (b.angular_momentum - l_free) / t.mean;
    b.constraint_work += (b.constraint_force.dot(0.5 * (v_new + b.velocity)) +
                          b.constraint_moment.dot(0.5 * (w_new + b.omega))) *
                         t.mean;
    b.previous_velocity = b.velocity;
    b.previous_omega = b.omega;
    b.velocity = v_new;
    b.omega = w_new;
    if (bad < 0 && !b.nodes.empty() && !std::isfinite(v_new.sum() + w_new.sum()))
      bad = b.nodes.front();
    // Node velocities and accelerations at the half step, positions come in place_rigid_nodes.
    const bool rotations = nd.angular_velocity.cols() > 0;
    for (const Index n : b.nodes) {
      const Vec3 r = Vec3(nd.position.col(n)) - b.center;
      const Vec3 vn = v_new + w_new.cross(r);
      nd.acceleration.col(n) = (vn - Vec3(nd.velocity.col(n))) / t.mean;
      nd.velocity.col(n) = vn;
      if (rotations) {  // a shell node on the body turns with it
        nd.previous_angular_velocity.col(n) = nd.angular_velocity.col(n);
        nd.angular_velocity.col(n) = w_new;
      }
    }
  }
  return bad;
}

double point_mass(const State& state, Index b, const Vec3& point) {
  const RigidBody& body = state.rigid_bodies[static_cast<std::size_t>(b)];
  const Vec3 r = point - body.center;
  Mat3 arm;
  arm << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  Mat3 free_translation = Mat3::Zero(), free_rotation = Mat3::Zero();
  for (int k = 0; k < 3; ++k) {
    free_translation(k, k) = body.fixed_translation[static_cast<std::size_t>(k)] ? 0.0 : 1.0;
    free_rotation(k, k) = body.fixed_rotation[static_cast<std::size_t>(k)] ? 0.0 : 1.0;
  }
  const Mat3 w = free_translation / body.mass +
                 arm.transpose() * free_rotation * body.inertia().inverse() * free_rotation * arm;
  const double most = Eigen::SelfAdjointEigenSolver<Mat3>(w).eigenvalues()[2];
  return most > 0.0 ? 1.0 / most : std::numeric_limits<double>::infinity();
}

double node_mass_at(const State& state, Index node, const Vec3& point) {
  const Index b = state.nodes.rigid_body[static_cast<std::size_t>(node)];
  return b >= 0 ? point_mass(state, b, point) : state.nodes.mass[static_cast<std::size_t>(node)];
}

double reduced_mass(double a, double b) {
  if (std::isinf(a)) return b;
  if (std::isinf(b)) return a;
  return a * b / (a + b);
}

void place_rigid_nodes(State& state, double step) {
  Nodes& nd = state.nodes;
  for (RigidBody& b : state.rigid_bodies) {
    if (b.released) continue;
    b.center += step * b.velocity;
    b.rotation = rotation_increment(b.omega, step) * b.rotation;
    for (std::size_t k = 0; k < b.nodes.size(); ++k)
      nd.position.col(b.nodes[k]) = b.center + b.rotation * b.offsets.col(static_cast<Index>(k));
  }
}

}  // namespace mcdyna::solver
