#include "solver/spg/angular_budget.hpp"

#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver::spg {

void AngularBudget::record(const State& s, const Domain& d, const Eigen::Matrix3Xd& force,
                           double position_step, double velocity_step) {
  Vec3 l = Vec3::Zero(), a = Vec3::Zero(), b = Vec3::Zero(), c = Vec3::Zero();
  Vec3 centre = Vec3::Zero();
  double mass = 0.0;
  const Eigen::Matrix3Xd positions = particle_positions(s, d);
  for (Index j = 0; j < d.count(); ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (d.kernel.pinned[jj]) pinned = true;
    const Index node = d.particles.nodes[jj];
    const Vec3 x = positions.col(j);
    const Vec3 f = force.col(node);
    // A pinned particle keeps a plain velocity: its force is taken at its own position (its
    // gather may be 0/0 where it reaches no smoothed row, as on the FDS plate's FE coupling).
    const Vec3 xbar = d.kernel.pinned[jj] ? x : gathered(d, j, positions);
    l += d.particles.mass[jj] * x.cross(d.fields.unsmoothed.col(j));
    a += position_step * d.particles.mass[jj] *
         s.nodes.velocity.col(node).cross(d.fields.unsmoothed.col(j));
    b += velocity_step * xbar.cross(f);
    c += velocity_step * x.cross(f);
    centre += d.particles.mass[jj] * x;
    mass += d.particles.mass[jj];
  }
  if (started) {
    sum_a += pending_a;
    sum_b += b;
    sum_c += c;
  } else {
    first = l;
    centre /= mass;
    for (Index j = 0; j < d.count(); ++j) {
      const auto jj = static_cast<std::size_t>(j);
      scale += d.particles.mass[jj] * (positions.col(j) - centre).norm() *
               d.fields.unsmoothed.col(j).norm();
    }
    started = true;
  }
  pending_a = a;
  last = l;
}

}  // namespace mcdyna::solver::spg
