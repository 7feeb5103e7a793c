// ID indices, duplicate IDs and dangling references.
#include <fmt/format.h>
#include <algorithm>

#include "model/checks.hpp"

namespace mcdyna::model {

std::size_t check(ModelDatabase& model, core::Diagnostics& diags) {
  const std::size_t before = diags.error_count();
  detail::build_indices(model, diags);
  detail::check_references(model, diags);
  detail::check_sanity(model, diags);
  detail::check_sensors(model, diags);
  return diags.error_count() - before;
}

namespace detail {

void build_indices(ModelDatabase& m, core::Diagnostics& diags) {
  auto& ix = m.index;
  index_one(ix.nodes, m.nodes, "node", diags);
  index_one(ix.solids, m.solids, "solid element", diags);
  index_one(ix.shells, m.shells, "shell element", diags);
  index_one(ix.beams, m.beams, "beam element", diags);
  index_one(ix.parts, m.parts, "part", diags);
  index_one(ix.sections, m.sections, "section", diags);
  index_one(ix.materials, m.materials, "material", diags);
  index_one(ix.equations_of_state, m.equations_of_state, "equation of state", diags);
  index_one(ix.hourglasses, m.hourglasses, "hourglass", diags);
  index_one(ix.curves, m.curves, "curve", diags);
  index_one(ix.vectors, m.vectors, "vector", diags);
  index_one(ix.boxes, m.boxes, "box", diags);
  index_one(ix.node_sets, m.node_sets, "node set", diags);
  index_one(ix.part_sets, m.part_sets, "part set", diags);
  index_one(ix.segment_sets, m.segment_sets, "segment set", diags);
}

namespace {

// Reports `id` at `loc` if it is not in `index` (0 allowed when `zero_ok`).
bool need(const IdIndex& index, Id id, core::SourceLoc loc, std::string_view what,
          std::string_view user, core::Diagnostics& diags, bool zero_ok = false) {
  if (zero_ok && id == 0) return true;
  if (index.contains(id)) return true;
  diags.error(loc, "{} refers to {} {}, which is not defined", user, what, id);
  return false;
}

void check_parts(const ModelDatabase& m, core::Diagnostics& diags) {
  const auto& ix = m.index;
  for (const Part& p : m.parts) {
    const std::string user = fmt::format("part {}", p.id);
    need(ix.sections, p.section, p.section_loc, "section", user, diags);
    need(ix.materials, p.material, p.material_loc, "material", user, diags);
    need(ix.equations_of_state, p.eos, p.eos_loc, "equation of state", user, diags, true);
    need(ix.hourglasses, p.hourglass, p.hourglass_loc, "*HOURGLASS", user, diags, true);
  }
  for (const Erosion& e : m.erosions) {
    need(ix.materials, e.material, e.loc, "material", "*MAT_ADD_EROSION", diags);
  }
  for (const Material& mat : m.materials) {
    if (mat.kind == MaterialKind::piecewise_linear) {
      need(ix.curves, mat.piecewise_linear.stress_strain_curve, mat.loc, "curve (LCSS)",
           fmt::format("material {}", mat.id), diags, true);
      need(ix.curves, mat.piecewise_linear.strain_rate_curve, mat.loc, "curve (LCSR)",
           fmt::format("material {}", mat.id), diags, true);
    }
    if (mat.kind == MaterialKind::spring_nonlinear_elastic) {
      need(ix.curves, mat.discrete.force_curve, mat.discrete.force_curve_loc, "curve (LCD)",
           fmt::format("material {}", mat.id), diags);
      need(ix.curves, mat.discrete.rate_curve, mat.discrete.rate_curve_loc, "curve (LCR)",
           fmt::format("material {}", mat.id), diags, true);
    }
    if (mat.kind == MaterialKind::rigid && std::abs(mat.rigid.constraint_option) == 2) {
      need(ix.nodes, mat.rigid.constraint_node, mat.loc, "node (SPCNID)",
           fmt::format("material {}", mat.id), diags, true);
    }
  }
  for (const Section& s : m.sections) {
    if (s.kind == SectionKind::solid_spg) {
      need(ix.boxes, s.spg.box, s.loc, "box (BOXID)", fmt::format("section {}", s.id), diags, true);
    }
  }
}

// Element connectivity: part and nodes. Messages are capped per kind so that a deck with a
// missing include does not print a million lines; the count stays exact.
template <typename Element>
void check_elements(const std::vector<Element>& elements, const ModelDatabase& m, const char* what,
                    core::Diagnostics& diags) {
  std::size_t missing_nodes = 0, shown = 0;
  core::SourceLoc first_loc;
  for (const Element& e : elements) {
    if (!m.index.parts.contains(e.part)) {
      if (shown++ < 20) {
        diags.error(e.loc, "{} {} refers to part {}, which is not defined", what, e.id, e.part);
      }
    }
    for (Id n : e.nodes) {
      if (m.index.nodes.contains(n)) continue;
      if (missing_nodes == 0) first_loc = e.loc;
      if (missing_nodes++ < 20) {
        if (n == 0) {
          diags.error(e.loc, "{} {} has a blank node (node 0)", what, e.id);
        } else {
          diags.error(e.loc, "{} {} refers to node {}, which is not defined", what, e.id, n);
        }
      }
    }
  }
  if (missing_nodes > 20) {
    diags.error(first_loc, "{} references to undefined nodes in {}s in all (first 20 shown)",
                missing_nodes, what);
  }
  if (shown > 20) {
    diags.error(elements.front().loc, "{} {}s refer to undefined parts in all (first 20 shown)",
                shown, what);
  }
}

// Beams: part and nodes as the other elements, plus the orientation node.
void check_beams(const ModelDatabase& m, core::Diagnostics& diags) {
  check_elements(m.beams, m, "beam element", diags);
  int shown = 0;
  for (const BeamElement& e : m.beams) {
    if (e.orientation_node != 0 && !m.index.nodes.contains(e.orientation_node) && shown++ < 20) {
      diags.error(e.loc, "beam element {} refers to orientation node {} (N3), which is not defined",
                  e.id, e.orientation_node);
    }
  }
}

void check_sets(const ModelDatabase& m, core::Diagnostics& diags) {
  for (const NodeSet& s : m.node_sets) {
    int shown = 0;
    for (Id n : s.nodes) {
      if (!m.index.nodes.contains(n) && shown++ < 10) {
        diags.error(s.loc, "node set {} contains node {}, which is not defined", s.id, n);
      }
    }
  }
  for (const PartSet& s : m.part_sets) {
    for (Id p : s.parts)
      need(m.index.parts, p, s.loc, "part", fmt::format("part set {}", s.id), diags);
  }
  for (const ElementSet& s : m.element_sets) {
    const char* kind = s.kind == ElementSetKind::shell   ? "shell"
                       : s.kind == ElementSetKind::solid ? "solid"
                                                         : "beam";
    const IdIndex& index = s.kind == ElementSetKind::shell   ? m.index.shells
                           : s.kind == ElementSetKind::solid ? m.index.solids
                                                             : m.index.beams;
    int shown = 0;
    for (const Id e : s.elements) {
      if (!index.contains(e) && shown++ < 10) {
        diags.error(s.loc, "{} set {} contains {} element {}, which is not defined", kind, s.id,
                    kind, e);
      }
    }
  }
  for (const SegmentSet& s : m.segment_sets) {
    int shown = 0;
    for (const auto& seg : s.segments) {
      for (Id n : seg) {
        if (!m.index.nodes.contains(n) && shown++ < 10) {
          diags.error(s.loc, "segment set {} uses node {}, which is not defined", s.id, n);
        }
      }
    }
  }
}

void check_contact_side(const ModelDatabase& m, const Contact& c, const ContactSide& side,
                        char name, core::Diagnostics& diags) {
  const std::string user = fmt::format("contact {} side {}", c.id, name);
  const auto& ix = m.index;
  switch (side.type) {
    case 0:
      need(ix.segment_sets, side.id, c.loc, "segment set", user, diags);
      break;
    case 1:  // shell element set
      if (std::none_of(m.element_sets.begin(), m.element_sets.end(), [&](const ElementSet& s) {
            return s.kind == ElementSetKind::shell && s.id == side.id;
          })) {
        diags.error(c.loc, "{} refers to shell set {}, which is not defined", user, side.id);
      }
      break;
    case 2:  // part set
    case 6:  // all parts except a part set
      need(ix.part_sets, side.id, c.loc, "part set", user, diags);
      break;
    case 3:
      need(ix.parts, side.id, c.loc, "part", user, diags);
      break;
    case 4:
      need(ix.node_sets, side.id, c.loc, "node set", user, diags);
      break;
    default:
      break;  // 5 = all
  }
  need(ix.boxes, side.box, c.loc, "box", user, diags, true);
}

bool is_nodal_rigid_body(const ModelDatabase& m, Id id) {
  for (const NodalRigidBody& b : m.nodal_rigid_bodies)
    if (b.id == id) return true;
  return false;
}

// A part that must be rigid (MAT_020) for `user`; reports it when it is missing or deformable.
void need_rigid_part(const ModelDatabase& m, Id id, const core::SourceLoc& loc,
                     const std::string& user, core::Diagnostics& diags) {
  if (!need(m.index.parts, id, loc, "part", user, diags)) return;
  const Material* mat = m.material(m.part(id)->material);
  if (mat != nullptr && mat->kind != MaterialKind::rigid) {
    diags.error(loc, "{}: part {} is not rigid (its material {} is not *MAT_RIGID)", user, id,
                mat->id);
  }
}

// *CONSTRAINED_EXTRA_NODES, *CONSTRAINED_RIGID_BODIES, *CONSTRAINED_NODAL_RIGID_BODY.
void check_joins(const ModelDatabase& m, core::Diagnostics& diags) {
  const auto& ix = m.index;
  for (const ExtraNodes& e : m.extra_nodes) {
    const std::string user =
        e.is_set ? "*CONSTRAINED_EXTRA_NODES_SET" : "*CONSTRAINED_EXTRA_NODES_NODE";
    need_rigid_part(m, e.part, e.loc, user, diags);
    need(e.is_set ? ix.node_sets : ix.nodes, e.target, e.loc, e.is_set ? "node set" : "node", user,
         diags);
  }
  for (const RigidMerge& r : m.rigid_merges) {
    need_rigid_part(m, r.lead, r.loc, "*CONSTRAINED_RIGID_BODIES", diags);
    need_rigid_part(m, r.constrained, r.loc, "*CONSTRAINED_RIGID_BODIES", diags);
  }
  for (const Joint& j : m.joints)
    for (const Id n : j.nodes)
      need(ix.nodes, n, j.loc, "node", "*CONSTRAINED_JOINT", diags, true);
  for (const CoordinateSystem& c : m.coordinate_systems)
    for (const Id n : c.nodes)
      need(ix.nodes, n, c.loc, "node", "*DEFINE_COORDINATE_NODE", diags);
  for (const JointStiffness& j : m.joint_stiffnesses) {
    const std::string user = "*CONSTRAINED_JOINT_STIFFNESS_GENERALIZED";
    need_rigid_part(m, j.part_a, j.loc, user, diags);
    need_rigid_part(m, j.part_b, j.loc, user, diags);
    for (const Id cid : {j.system_a, j.system_b}) {
      if (std::none_of(m.coordinate_systems.begin(), m.coordinate_systems.end(),
                       [&](const CoordinateSystem& c) { return c.id == cid; })) {
        diags.error(j.loc, "{} refers to coordinate system {}, which is not defined", user, cid);
      }
    }
    for (const Id curve : j.curves)
      need(ix.curves, curve, j.loc, "curve", user, diags, true);
  }
  for (const SpotWeld& w : m.spot_welds) {
    if (w.node_set != 0) {
      need(ix.node_sets, w.node_set, w.loc, "node set", "*CONSTRAINED_GENERALIZED_WELD_SPOT",
           diags);
    } else {
      for (const Id n : w.nodes)
        need(ix.nodes, n, w.loc, "node", "*CONSTRAINED_SPOTWELD", diags);
    }
  }
  for (const NodalRigidBody& b : m.nodal_rigid_bodies) {
    need(ix.node_sets, b.node_set, b.set_loc, "node set", "*CONSTRAINED_NODAL_RIGID_BODY", diags);
    if (ix.parts.find(b.id) != IdIndex::kNone) {
      diags.error(b.loc,
                  "*CONSTRAINED_NODAL_RIGID_BODY: PID {} is also a *PART; the body's ID must "
                  "not name a part",
                  b.id);
    }
  }
}

void check_conditions(const ModelDatabase& m, core::Diagnostics& diags) {
  const auto& ix = m.index;
  for (const Contact& c : m.contacts) {
    const bool single = c.kind == ContactKind::automatic_single_surface;
    if (!(single && c.a.id == 0)) check_contact_side(m, c, c.a, 'A', diags);
    const bool transducer_without_b = c.kind == ContactKind::force_transducer && c.b.id == 0;
    if (!single && !transducer_without_b) check_contact_side(m, c, c.b, 'B', diags);
  }
  for (const SpcConstraint& s : m.spcs) {
    need(s.is_set ? ix.node_sets : ix.nodes, s.target, s.loc, s.is_set ? "node set" : "node",
         "*BOUNDARY_SPC", diags);
  }
  for (const PrescribedMotion& p : m.prescribed_motions) {
    const std::string user = "*BOUNDARY_PRESCRIBED_MOTION";
    switch (p.target_kind) {
      case MotionTarget::node:
        need(ix.nodes, p.target, p.loc, "node", user, diags);
        break;
      case MotionTarget::node_set:
        need(ix.node_sets, p.target, p.loc, "node set", user, diags);
        break;
      case MotionTarget::rigid_part:
        if (is_nodal_rigid_body(m, p.target)) break;
        if (need(ix.parts, p.target, p.loc, "part", user, diags)) {
          const Material* mat = m.material(m.part(p.target)->material);
          if (mat != nullptr && mat->kind != MaterialKind::rigid) {
            diags.error(p.loc,
                        "*BOUNDARY_PRESCRIBED_MOTION_RIGID: part {} is not rigid "
                        "(its material {} is not *MAT_RIGID)",
                        p.target, mat->id);
          }
        }
        break;
    }
    need(ix.curves, p.curve, p.curve_loc, "curve", user, diags);
    need(ix.vectors, p.vector, p.vector_loc, "vector", user, diags, true);
  }
  for (const InitialVelocity& v : m.initial_velocities) {
    const std::string user = "*INITIAL_VELOCITY";
    switch (v.kind) {
      case InitialVelocityKind::by_set:
        need(ix.node_sets, v.target, v.loc, "node set", user, diags, true);
        need(ix.node_sets, v.exempted_set, v.loc, "node set", user, diags, true);
        need(ix.boxes, v.box, v.loc, "box", user, diags, true);
        break;
      case InitialVelocityKind::per_node:
        need(ix.nodes, v.target, v.loc, "node", user, diags);
        break;
      case InitialVelocityKind::generation:
        if (v.target == 0) break;
        if (v.target_type == 1) need(ix.part_sets, v.target, v.loc, "part set", user, diags);
        if (v.target_type == 2) need(ix.parts, v.target, v.loc, "part", user, diags);
        if (v.target_type == 3) need(ix.node_sets, v.target, v.loc, "node set", user, diags);
        break;
    }
  }
  for (const PointLoad& p : m.point_loads) {
    switch (p.target_kind) {
      case LoadTarget::node:
        need(ix.nodes, p.target, p.loc, "node", "*LOAD_NODE_POINT", diags);
        break;
      case LoadTarget::node_set:
        need(ix.node_sets, p.target, p.loc, "node set", "*LOAD_NODE_SET", diags);
        break;
      case LoadTarget::rigid_part:
        if (!is_nodal_rigid_body(m, p.target))
          need_rigid_part(m, p.target, p.loc, "*LOAD_RIGID_BODY", diags);
        break;
    }
    need(ix.curves, p.curve, p.curve_loc, "curve", "*LOAD_NODE / *LOAD_RIGID_BODY", diags);
  }
  for (const SegmentLoad& l : m.segment_loads) {
    if (l.is_set)
      need(ix.segment_sets, l.set, l.loc, "segment set", "*LOAD_SEGMENT_SET", diags);
    else
      for (const Id n : l.nodes)
        need(ix.nodes, n, l.loc, "node", "*LOAD_SEGMENT", diags);
    need(ix.curves, l.curve, l.curve_loc, "curve", "*LOAD_SEGMENT", diags);
  }
  for (const BodyLoad& b : m.body_loads)
    need(ix.curves, b.curve, b.curve_loc, "curve", "*LOAD_BODY", diags);
  for (const RigidWall& w : m.rigid_walls) {
    const char* user = w.shape == WallShape::planar ? "*RIGIDWALL_PLANAR" : "*RIGIDWALL_GEOMETRIC";
    need(ix.node_sets, w.node_set, w.loc, "node set", user, diags, true);
    need(ix.node_sets, w.exempted_set, w.loc, "node set", user, diags, true);
    need(ix.boxes, w.box, w.loc, "box", user, diags, true);
    need(ix.curves, w.motion_curve, w.motion_loc, "curve (LCID)", user, diags, true);
  }
}

void check_outputs(const ModelDatabase& m, core::Diagnostics& diags) {
  const auto& ix = m.index;
  for (const HistoryNodes& h : m.outputs.history_nodes) {
    for (Id id : h.ids) {
      need(h.is_set ? ix.node_sets : ix.nodes, id, h.loc, h.is_set ? "node set" : "node",
           "*DATABASE_HISTORY_NODE", diags);
    }
  }
  for (const AsciiRequest& a : m.outputs.ascii) {
    need(ix.curves, a.interval_curve, a.loc, "curve (LCUR)", "*DATABASE_", diags, true);
  }
  if (m.outputs.d3plot) {
    const D3plotRequest& d = *m.outputs.d3plot;
    need(ix.curves, d.interval_curve, d.loc, "curve (LCDT)", "*DATABASE_BINARY_D3PLOT", diags,
         true);
    need(ix.part_sets, d.excluded_parts, d.loc, "part set (PSETID)", "*DATABASE_BINARY_D3PLOT",
         diags, true);
  }
  if (m.controls.damping) {
    need(ix.curves, m.controls.damping->curve, m.controls.damping->curve_loc, "curve (LCID)",
         "*DAMPING_GLOBAL", diags, true);
  }
  if (m.controls.time_step) {
    need(ix.curves, m.controls.time_step->max_step_curve, m.controls.time_step->loc, "curve (LCTM)",
         "*CONTROL_TIMESTEP", diags, true);
  }
}

}  // namespace

void check_references(const ModelDatabase& m, core::Diagnostics& diags) {
  check_parts(m, diags);
  if (!m.solids.empty()) check_elements(m.solids, m, "solid element", diags);
  if (!m.shells.empty()) check_elements(m.shells, m, "shell element", diags);
  if (!m.beams.empty()) check_beams(m, diags);
  if (!m.discretes.empty()) check_elements(m.discretes, m, "discrete element", diags);
  check_sets(m, diags);
  check_conditions(m, diags);
  check_joins(m, diags);
  check_outputs(m, diags);
}

}  // namespace detail

}  // namespace mcdyna::model
