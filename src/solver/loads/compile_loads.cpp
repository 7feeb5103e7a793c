// *LOAD_BODY_X/Y/Z -> the body loads' block (loads/condition_blocks.cpp); *LOAD_NODE_POINT /
// _SET, *LOAD_RIGID_BODY and *LOAD_SEGMENT / _SET -> the point and pressure loads' block
// (loads/applied_loads.cpp); *DAMPING_GLOBAL -> its block (loads/global_damping.cpp). Each block
// owns what it applies (load_state.hpp).
#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/loads/load_state.hpp"

namespace mcdyna::solver::detail {

void compile_body_loads(const model::ModelDatabase& m, State& /*s*/,
                        const CompiledBlocks& /*before*/, Blocks& own, core::Diagnostics& /*d*/) {
  std::vector<BodyLoadState> loads;
  for (const model::BodyLoad& b : m.body_loads) {
    const Index curve = curve_index(m, b.curve);
    if (curve < 0) continue;  // reported by the reference checks
    loads.push_back(BodyLoadState{b.axis, curve, b.scale});
  }
  if (!loads.empty()) own.push_back(make_body_loads_block(std::move(loads)));
}

void compile_global_damping(const model::ModelDatabase& m, State& /*s*/,
                            const CompiledBlocks& /*before*/, Blocks& own,
                            core::Diagnostics& /*d*/) {
  if (!m.controls.damping) return;
  const model::GlobalDamping& g = *m.controls.damping;
  GlobalDampingState ds;
  ds.curve = g.curve > 0 ? curve_index(m, g.curve) : -1;
  ds.value = g.value;
  ds.scale = g.scale;
  if (g.curve == 0 || ds.curve >= 0) own.push_back(make_global_damping_block(ds));
}

void compile_applied_loads(const model::ModelDatabase& m, State& s,
                           const CompiledBlocks& /*before*/, Blocks& own, core::Diagnostics& d) {
  std::vector<PointLoadState> points;
  std::vector<PressureLoadState> pressures;
  for (const model::PointLoad& p : m.point_loads) {
    PointLoadState l;
    l.curve = curve_index(m, p.curve);
    if (l.curve < 0) continue;  // reported by the reference checks
    l.scale = p.scale;
    l.moment = p.dof >= 5;
    l.axis = (p.dof - 1) % 4;  // 1-3 and 5-7
    switch (p.target_kind) {
      case model::LoadTarget::rigid_part:
        l.body = rigid_body_of(m, s, p.target);
        if (l.body < 0) continue;  // reported by the reference checks
        break;
      case model::LoadTarget::node_set:
        l.nodes = node_set_nodes(m, p.target);
        break;
      case model::LoadTarget::node:
        l.nodes = {static_cast<Index>(m.index.nodes.find(p.target))};
        break;
    }
    if (l.moment) {
      for (const Index n : l.nodes) {
        const auto i = static_cast<std::size_t>(n);
        if (s.nodes.rotary_inertia.empty() || !(s.nodes.rotary_inertia[i] > 0.0)) {
          d.error(p.loc,
                  "*LOAD_NODE: a moment (DOF {}) on node {}, which has no rotations (only shell "
                  "nodes do)",
                  p.dof, s.nodes.ids[i]);
          break;
        }
      }
    }
    points.push_back(std::move(l));
  }
  for (const model::SegmentLoad& g : m.segment_loads) {
    PressureLoadState l;
    l.curve = curve_index(m, g.curve);
    if (l.curve < 0) continue;
    l.scale = g.scale;
    l.arrival = g.arrival;
    auto node = [&](model::Id id) { return static_cast<Index>(m.index.nodes.find(id)); };
    std::vector<std::array<model::Id, 4>> segments;
    if (g.is_set) {
      if (const model::SegmentSet* set = m.segment_set(g.set)) segments = set->segments;
    } else {
      segments.push_back(g.nodes);
    }
    for (std::array<model::Id, 4> seg : segments) {
      if (seg[3] == 0) seg[3] = seg[2];
      std::array<Index, 4> conn{};
      for (std::size_t k = 0; k < 4; ++k)
        conn[k] = node(seg[k]);
      l.segments.push_back(conn);
    }
    l.last.setZero(3, 4 * static_cast<Index>(l.segments.size()));
    pressures.push_back(std::move(l));
  }
  if (!points.empty() || !pressures.empty())
    own.push_back(make_applied_loads_block(std::move(points), std::move(pressures)));
}

}  // namespace mcdyna::solver::detail
