#pragma once
/// Velocity-level boundary conditions applied after the free velocity update, in this order:
/// nodal constraints (SPC, *NODE TC), prescribed nodal motion (then the walls, walls/). Each
/// records the force it applied (m dv / dt) for spcforc and bndout.
#include "solver/loads/load_state.hpp"
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// *LOAD_BODY: adds -m a(t) to every deformable node's force (SPG particles with the mass their
/// velocity update divides by, so every particle gets the same acceleration) and sets each rigid
/// body's body_force to -M a(t).
void apply_body_loads(State& state, const std::vector<BodyLoadState>& loads,
                      Eigen::Matrix3Xd& force);

void apply_nodal_constraints(State& state, NodalConstraints& c, const StepTimes& t);
void apply_nodal_motions(State& state, std::vector<NodalMotion>& motions, const StepTimes& t);

/// What landing a node on a wall did (rigid walls, planar and geometric).
struct WallLanding {
  Vec3 change = Vec3::Zero();  ///< its velocity change
  double normal_change = 0.0;  ///< the part along the wall's normal, -gap / dt
  Vec3 start = Vec3::Zero();   ///< v^{n-1/2}, for the work of the impulse
  Vec3 end = Vec3::Zero();     ///< its velocity after landing
};

/// Lands node `n`, which the coming step would carry `gap` (< 0) past a wall along its unit
/// `normal`, on the wall: the normal velocity change -gap / dt, then Coulomb friction (FRIC < 1:
/// at most FRIC times that change; >= 1: no sliding) on its velocity across the normal relative
/// to the wall's `wall_velocity`. Sets the node's velocity and acceleration.
WallLanding land_on_wall(Nodes& nd, Index n, const StepTimes& t, double gap, const Vec3& normal,
                         const Vec3& wall_velocity, double friction);
/// The nodal mass a wall's impulse acts on (with what mass scaling added), and the work of an
/// impulse that takes a node from v_start to v_end (the trapezoid over the step).
double nodal_mass(const Nodes& nd, Index n);
double impulse_work(const Vec3& impulse, const Vec3& v_start, const Vec3& v_end);

}  // namespace mcdyna::solver
