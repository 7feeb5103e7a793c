#pragma once
/// Velocity-level boundary conditions applied after the free velocity update, in this order:
/// nodal constraints (SPC, *NODE TC), prescribed nodal motion, planar rigid walls. Each records
/// the force it applied (m dv / dt) for spcforc, bndout and rwforc.
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// *LOAD_BODY: adds -m a(t) to every deformable node's force (SPG particles with the mass their
/// velocity update divides by, so every particle gets the same acceleration) and sets each rigid
/// body's body_force to -M a(t).
void apply_body_loads(State& state);

void apply_nodal_constraints(State& state, const StepTimes& t);
void apply_nodal_motions(State& state, const StepTimes& t);
/// Stonewall (constraint method): nodes that would cross the wall during the coming step get the
/// normal velocity that puts them on it; Coulomb friction limits the tangential impulse.
void apply_rigid_walls(State& state, const StepTimes& t);

}  // namespace mcdyna::solver
