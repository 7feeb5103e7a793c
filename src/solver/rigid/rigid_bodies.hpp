#pragma once
/// Rigid-body dynamics for MAT_020 parts. Translation with the mass; rotation with the angular
/// momentum L as the integrated variable and omega = I(t)^-1 L, so a free body keeps L to
/// round-off whatever its inertia. Constraints and prescribed motion fix velocity components in
/// chosen directions; the free components follow from the momentum equations of the rest.
#include "solver/nodal_forces.hpp"
#include "solver/state.hpp"
#include "solver/step_times.hpp"

namespace mcdyna::solver {

/// Sums nodal forces into each body, integrates its velocities under constraints and prescribed
/// motion, then sets its nodes' velocities (half step) and accelerations. Returns the first node
/// of the first body whose velocities are not finite, or -1.
Index advance_rigid_bodies(State& state, const NodalForces& forces, const StepTimes& t);

/// The least mass rigid body `b` answers a force at `point` with, over the force's directions:
/// 1 / lambda_max(W), dv = W f, W = P_t / M + [r]x^T P_r J^-1 P_r [r]x at the current geometry
/// (r from the centre, J the current inertia, P the directions its CMO constraints leave free);
/// infinite for a body held in every direction.
double point_mass(const State& state, Index b, const Vec3& point);

/// The mass a force on `node` at `point` moves: its rigid body's point_mass there, else the
/// node's own mass.
double node_mass_at(const State& state, Index node, const Vec3& point);

/// The reduced mass a b / (a + b) of two sides; an infinite side (a held body) leaves the other.
double reduced_mass(double a, double b);

/// Moves rigid-body nodes to x = c + R X (after the body positions are advanced).
void place_rigid_nodes(State& state, double step);

/// Value of a prescribed motion's curve at time t (SF applied, abscissa shifted by BIRTH).
double motion_value(const State& state, Index curve, double scale, double birth, double t);

/// Displacement-type (VAD 2) target to velocity over [t, t + step] given the current value.
double displacement_velocity(const State& state, Index curve, double scale, double birth,
                             double current, double time, double step);

}  // namespace mcdyna::solver
