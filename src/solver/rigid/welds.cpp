#include "solver/rigid/welds.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/exact_sum.hpp"
#include "solver/shells/shells.hpp"
#include "solver/solids/solids.hpp"

namespace mcdyna::solver {

namespace {

// Mean plastic strain over the points of element `e` of one kind (shells or solids): its block's
// `points(block)` points from the block's point_begin, in element order.
template <class Block, class PointsOf>
double mean_plastic_strain(const std::vector<Block>& blocks, const std::vector<double>& strain,
                           Index e, PointsOf points) {
  for (const Block& b : blocks) {
    if (e < b.begin || e >= b.end) continue;
    const int n = points(b);
    const Index first = b.point_begin + n * (e - b.begin);
    double sum = 0.0;
    for (Index p = first; p < first + n; ++p)
      sum += strain[static_cast<std::size_t>(p)];
    return sum / n;
  }
  return 0.0;
}

double shell_plastic_strain(const Shells& sh, Index e) {
  return mean_plastic_strain(sh.blocks, sh.points.plastic_strain, e,
                             [](const ShellBlock& b) { return b.in_plane_points * b.layers; });
}

double solid_plastic_strain(const Solids& so, Index e) {
  return mean_plastic_strain(so.blocks, so.points.plastic_strain, e,
                             [](const SolidBlock& b) { return b.points_per_element; });
}

// The largest mean plastic strain of the deformable shells and solids at the node.
double node_plastic_strain(const State& s, Index node) {
  const auto n = static_cast<std::size_t>(node);
  double most = 0.0;
  const Shells& sh = shells_of(s);
  if (!sh.corner_offsets.empty())
    for (Index k = sh.corner_offsets[n]; k < sh.corner_offsets[n + 1]; ++k)
      most = std::max(most,
                      shell_plastic_strain(sh, sh.node_corners[static_cast<std::size_t>(k)] / 4));
  const Solids& so = solids_of(s);
  if (!so.corner_offsets.empty())
    for (Index k = so.corner_offsets[n]; k < so.corner_offsets[n + 1]; ++k)
      most = std::max(most,
                      solid_plastic_strain(so, so.node_corners[static_cast<std::size_t>(k)] / 8));
  return most;
}

// The force the weld's body puts on node `n` this cycle, summed over the processes (the force
// is whole on the node's owner only), so every process decides the same.
Vec3 constraint_force(const State& s, const Eigen::Matrix3Xd& force, Index n) {
  const Nodes& nd = s.nodes;
  std::vector<core::ExactSum> sums(3);
  if (s.ownership.owns_node(n)) {
    const Vec3 f =
        nd.mass[static_cast<std::size_t>(n)] * Vec3(nd.acceleration.col(n)) - Vec3(force.col(n));
    for (int k = 0; k < 3; ++k)
      sums[static_cast<std::size_t>(k)].add(f[k]);
  }
  const std::vector<double> total = s.ownership.comm.sum(sums);
  return {total[0], total[1], total[2]};
}

// Frees the weld's nodes: from now on they move by their own forces, with the velocity the
// body gave them this cycle.
void release(State& s, WeldState& w, double time) {
  RigidBody& b = s.rigid_bodies[static_cast<std::size_t>(w.body)];
  for (const Index n : b.nodes)
    s.nodes.rigid_body[static_cast<std::size_t>(n)] = -1;
  b.nodes.clear();
  b.offsets.resize(3, 0);
  b.released = true;
  w.failed_at = time;
}

}  // namespace

void check_welds(State& state, std::vector<WeldState>& welds, const Eigen::Matrix3Xd& force,
                 const StepTimes& t) {
  for (WeldState& w : welds) {
    if (w.failed_at >= 0.0) continue;
    const Vec3 f = constraint_force(state, force, w.last);
    const Vec3 axis =
        (Vec3(state.nodes.position.col(w.last)) - Vec3(state.nodes.position.col(w.first)))
            .normalized();
    w.force = f;
    w.normal = -f.dot(axis);  // pulling N2 back toward N1: the weld in tension
    w.shear = (f - f.dot(axis) * axis).norm();
    double criterion = 0.0;
    if (w.normal_force > 0.0)
      criterion += std::pow(std::max(w.normal, 0.0) / w.normal_force, w.normal_exponent);
    if (w.shear_force > 0.0) criterion += std::pow(w.shear / w.shear_force, w.shear_exponent);
    const bool by_force = (w.normal_force > 0.0 || w.shear_force > 0.0) && criterion >= 1.0;
    const bool by_strain = w.plastic_strain < 1.0e20 &&
                           std::max(node_plastic_strain(state, w.first),
                                    node_plastic_strain(state, w.last)) >= w.plastic_strain;
    if (by_force || t.time >= w.failure_time || by_strain) release(state, w, t.time);
  }
}

}  // namespace mcdyna::solver
