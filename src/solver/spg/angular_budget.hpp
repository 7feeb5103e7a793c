#pragma once
/// The angular-momentum budget of an SPG part (manual/theory.md, "Angular momentum"). With
/// L_n = sum m-hat_I x_I^n x u-hat_I^{n+1/2}, the central-difference update of MC-SPG gives
/// exactly L_n - L_{n-1} = A_{n-1} + B_n (+ the moments of constraint impulses):
///   A = dt^{n+1/2} sum_I m-hat_I u_I x u-hat_I  (Eq. 28: particles move with u = T u-hat)
///   B = dt^n sum_J xbar_J x f_J, xbar_J = sum_I T_JI x_I  (Eq. 30 applies f_J about xbar_J)
/// while the exact balance would be C = dt^n sum_J x_J x f_J. The defect A + B - C is what the
/// scheme adds to the part's angular momentum: it vanishes where the gather reproduces linear
/// fields and does not depend on the origin. Pinned particles (plain velocities) enter with
/// x-bar = x; the moments of constraint and coupling impulses are not in the forces, so with
/// them L's change is not A + B alone.
#include "solver/spg/domain.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::spg {

struct AngularBudget {
  bool started = false;
  Vec3 first = Vec3::Zero(), last = Vec3::Zero();  ///< L at the first and the last record
  Vec3 pending_a = Vec3::Zero();                   ///< A of the last record, due at the next
  Vec3 sum_a = Vec3::Zero(), sum_b = Vec3::Zero(), sum_c = Vec3::Zero();
  double scale = 0.0;   ///< sum m-hat |x - x_c| |u-hat| at the first record (x_c: mass centre)
  bool pinned = false;  ///< some particle is pinned (shares a node with FE or a constraint)

  /// Records cycle n: called after the velocities advanced to n+1/2 and before the positions
  /// move; `position_step` = dt^{n+1/2}, `velocity_step` = dt^n.
  /// `force`: the nodal forces f^n.
  void record(const State& s, const Domain& d, const Eigen::Matrix3Xd& force, double position_step,
              double velocity_step);
  /// A + B - C summed so far: the scheme's own contribution to the angular momentum.
  [[nodiscard]] Vec3 defect() const { return sum_a + sum_b - sum_c; }
};

}  // namespace mcdyna::solver::spg
