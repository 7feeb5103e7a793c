// *CONSTRAINED_JOINT_* -> joints: node indices and the reduced mass that sizes their penalty
// springs, and the generalized stiffness joints' frames and curves, into the joints' block
// (rigid/joints.cpp applies both).
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/rigid/joint_state.hpp"
#include "solver/rigid/rigid_bodies.hpp"

namespace mcdyna::solver::detail {

namespace {

// *CONSTRAINED_JOINT_SPHERICAL / REVOLUTE / ...: the penalty springs on the node pairs.
void compile_joint_pairs(const model::ModelDatabase& m, const State& s, core::Diagnostics& d,
                         std::vector<JointState>& out) {
  for (std::size_t k = 0; k < m.joints.size(); ++k) {
    const model::Joint& j = m.joints[k];
    JointState js;
    js.id = j.id > 0 ? j.id : static_cast<model::Id>(k + 1);
    js.heading = j.heading;
    js.kind = j.kind;
    js.pairs = j.kind == model::JointKind::spherical       ? 1
               : j.kind == model::JointKind::translational ? 3
                                                           : 2;
    js.relative_stiffness = j.relative_stiffness > 0.0 ? j.relative_stiffness : 1.0;
    js.reduced_mass = std::numeric_limits<double>::infinity();
    bool ok = true;
    for (int p = 0; p < js.pairs; ++p) {
      double pair_mass[2] = {};
      for (int side = 0; side < 2; ++side) {
        const auto i = static_cast<std::size_t>(2 * p + side);
        const auto n = m.index.nodes.find(j.nodes[i]);
        if (n == model::IdIndex::kNone) {
          ok = false;  // reported by check
          continue;
        }
        js.nodes[i] = static_cast<Index>(n);
        pair_mass[side] = node_mass_at(s, js.nodes[i], s.nodes.initial.col(js.nodes[i]));
      }
      if (!ok) break;
      if (!(pair_mass[0] > 0.0) || !(pair_mass[1] > 0.0)) {
        d.error(j.loc,
                "joint {}: node {} or {} has no mass (it belongs to no element and no rigid "
                "body)",
                js.id, j.nodes[static_cast<std::size_t>(2 * p)],
                j.nodes[static_cast<std::size_t>(2 * p + 1)]);
        ok = false;
        break;
      }
      if (js.nodes[static_cast<std::size_t>(2 * p)] ==
          js.nodes[static_cast<std::size_t>(2 * p + 1)]) {
        d.error(j.loc, "joint {}: a pair joins node {} to itself", js.id,
                j.nodes[static_cast<std::size_t>(2 * p)]);
        ok = false;
        break;
      }
      // A held body's side is infinitely heavy: the pair then moves the other side alone.
      js.reduced_mass = std::min(js.reduced_mass, reduced_mass(pair_mass[0], pair_mass[1]));
    }
    if (!ok) continue;
    if (std::isinf(js.reduced_mass)) {
      d.note(j.loc, "joint {}: both its bodies are held (CMO), so it has nothing to do", js.id);
      continue;
    }
    if (j.kind == model::JointKind::cylindrical || j.kind == model::JointKind::translational) {
      if ((s.nodes.initial.col(js.nodes[2]) - s.nodes.initial.col(js.nodes[0])).norm() == 0.0) {
        d.error(j.loc, "joint {}: N1 and N3 coincide, so they give no axis", js.id);
        continue;
      }
    }
    if (j.damping != 1.0) {
      d.note(j.loc, "joint {}: DAMP = {:g} has no effect (mcdyna's joint springs are undamped)",
             js.id, j.damping);
    }
    out.push_back(js);
  }
}

// The axes of a *DEFINE_COORDINATE_NODE system at the initial positions (columns x y z).
Mat3 coordinate_axes(const model::ModelDatabase& m, const State& s, model::Id cid) {
  for (const model::CoordinateSystem& c : m.coordinate_systems) {
    if (c.id != cid) continue;
    auto x = [&](std::size_t k) {
      return Vec3(s.nodes.initial.col(static_cast<Index>(m.index.nodes.find(c.nodes[k]))));
    };
    const Vec3 ex = (x(1) - x(0)).normalized();
    const Vec3 ez = ex.cross(x(2) - x(0)).normalized();
    Mat3 axes;
    axes.col(0) = ex;
    axes.col(1) = ez.cross(ex);
    axes.col(2) = ez;
    return axes;
  }
  return Mat3::Identity();
}

// *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: rotational springs between two rigid bodies.
void compile_joint_stiffnesses(const model::ModelDatabase& m, const State& s, core::Diagnostics& d,
                               std::vector<JointStiffnessState>& out) {
  for (const model::JointStiffness& j : m.joint_stiffnesses) {
    JointStiffnessState js;
    js.id = j.id;
    js.body_a = rigid_body_of(m, s, j.part_a);
    js.body_b = rigid_body_of(m, s, j.part_b);
    if (js.body_a < 0 || js.body_b < 0) continue;  // reported by check
    const Mat3 a = coordinate_axes(m, s, j.system_a), b = coordinate_axes(m, s, j.system_b);
    if (!a.allFinite() || !b.allFinite()) {
      d.error(j.loc, "joint stiffness {}: a local system's nodes coincide or lie on a line", j.id);
      continue;
    }
    js.frame_a = a;
    js.frame_b = b;
    for (std::size_t k = 0; k < 3; ++k) {
      js.curves[k] = j.curves[k] > 0 ? curve_index(m, j.curves[k]) : -1;
      // ES acts with FM only: the friction's elastic part (LS-DYNA: 0 FM, no friction).
      if (j.friction[k] > 0.0 && !(j.elastic[k] > 0.0)) {
        d.error(j.loc,
                "joint stiffness {}: a friction moment limit needs its elastic stiffness (ES)",
                j.id);
      }
      js.elastic[static_cast<Index>(k)] = j.friction[k] > 0.0 ? j.elastic[k] : 0.0;
      js.friction[static_cast<Index>(k)] = j.friction[k];
    }
    out.push_back(js);
  }
}

}  // namespace

void compile_joints(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                    Blocks& own, core::Diagnostics& d) {
  std::vector<JointState> joints;
  std::vector<JointStiffnessState> stiffnesses;
  compile_joint_pairs(m, s, d, joints);
  compile_joint_stiffnesses(m, s, d, stiffnesses);
  if (!joints.empty() || !stiffnesses.empty())
    own.push_back(make_joints_block(std::move(joints), std::move(stiffnesses)));
}

}  // namespace mcdyna::solver::detail
