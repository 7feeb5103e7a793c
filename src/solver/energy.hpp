#pragma once
/// Global and per-part energies and momenta at t^n, as glstat and matsum report them.
/// Kinetic energy is the central-difference form 1/2 m v^{n-1/2} . v^{n+1/2}: with it and the
/// internal energy at t^n, the total of an undamped linear system is conserved by the scheme
/// (1/2 m |mean v|^2 differs by dt^2 |a|^2 m / 8, several % for high-frequency content).
/// Momenta use the mean velocity. `previous` = v^{n-1/2}; the state holds v^{n+1/2}.
#include <Eigen/Core>

#include <vector>

#include "solver/state.hpp"

namespace mcdyna::solver {

struct EnergySummary {
  double kinetic = 0.0, internal = 0.0, hourglass = 0.0, stonewall = 0.0;
  double sliding = 0.0;        ///< work the contact interfaces took (penalty springs and friction)
  double damping = 0.0;        ///< dissipated by SPG particle damping (PDAMP)
  double external_work = 0.0;  ///< work of prescribed motions and rigid-body constraints
  double eroded_internal = 0.0, eroded_hourglass = 0.0;
  double total = 0.0;  ///< kinetic + internal + hourglass + stonewall + sliding + damping + eroded
  Vec3 momentum = Vec3::Zero();
  double mass = 0.0, added_mass = 0.0;
};

EnergySummary energy_summary(const State& state, const Eigen::Matrix3Xd& previous);

/// Mass added by DT2MS mass scaling so far: at FE nodes and to SPG particles.
double total_added_mass(const State& state);

struct PartSummary {
  model::Id part = 0;
  double internal = 0.0, kinetic = 0.0, hourglass = 0.0;
  double eroded_internal = 0.0;
  Vec3 momentum = Vec3::Zero();
  Vec3 rigid_velocity = Vec3::Zero();  ///< centre velocity of a rigid part
  double added_mass = 0.0;
  double mass = 0.0;  ///< its elements' lumped mass (a rigid part: its body's)
};

/// One entry per part, in deck order. Kinetic energy and momentum of deformable parts come from
/// each element's lumped mass (1/8 per corner), so shared nodes split between parts.
std::vector<PartSummary> part_summaries(const State& state, const Eigen::Matrix3Xd& previous);

}  // namespace mcdyna::solver
