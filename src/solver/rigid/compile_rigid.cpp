// MAT_020 parts -> rigid bodies: mass, centre and inertia from their elements (Gauss quadrature)
// plus the lumped mass deformable elements put on their nodes; CMO/CON1/CON2 constraints.
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/rigid/welds.hpp"
#include "solver/solids/hex_geometry.hpp"

namespace mcdyna::solver::detail {

namespace {

// Accumulates mass, first moment and inertia about the origin of point masses.
struct MassMoments {
  double mass = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // sum m x x^T
  void add(double m, const Vec3& x) {
    mass += m;
    first += m * x;
    second += m * x * x.transpose();
  }
};

void add_solid(const State& s, const std::array<Index, 8>& conn, double density, MassMoments& mm) {
  hex::Corners x{};
  for (std::size_t c = 0; c < 8; ++c)
    for (std::size_t k = 0; k < 3; ++k)
      x[c][k] = s.nodes.initial(static_cast<Index>(k), conn[c]);
  const hex::GaussPoints& gauss = hex::gauss_points();
  for (int q = 0; q < 8; ++q) {
    const double* at = gauss.at[q];
    const double det = hex::gradients(x, gauss.gradients[q]).det;
    Vec3 p = Vec3::Zero();
    for (int n = 0; n < 8; ++n) {
      const double shape = 0.125 * (1 + hex::kXi[n][0] * at[0]) * (1 + hex::kXi[n][1] * at[1]) *
                           (1 + hex::kXi[n][2] * at[2]);
      p += shape * s.nodes.initial.col(conn[static_cast<std::size_t>(n)]);
    }
    mm.add(density * std::abs(det), p);
  }
}

void add_shell(const State& s, const std::array<Index, 4>& conn, double mass_per_area,
               MassMoments& mm) {
  static constexpr double kQ[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double gp = 1.0 / std::sqrt(3.0);
  for (const auto& q : kQ) {
    const double r = gp * q[0], t = gp * q[1];
    Vec3 p = Vec3::Zero(), dr = Vec3::Zero(), dt = Vec3::Zero();
    for (int n = 0; n < 4; ++n) {
      const Vec3 xn = s.nodes.initial.col(conn[static_cast<std::size_t>(n)]);
      p += 0.25 * (1 + kQ[n][0] * r) * (1 + kQ[n][1] * t) * xn;
      dr += 0.25 * kQ[n][0] * (1 + kQ[n][1] * t) * xn;
      dt += 0.25 * kQ[n][1] * (1 + kQ[n][0] * r) * xn;
    }
    mm.add(mass_per_area * dr.cross(dt).norm(), p);
  }
}

std::array<bool, 3> code_axes(int code) {
  switch (code) {
    case 1:
      return {true, false, false};
    case 2:
      return {false, true, false};
    case 3:
      return {false, false, true};
    case 4:
      return {true, true, false};
    case 5:
      return {false, true, true};
    case 6:
      return {true, false, true};
    case 7:
      return {true, true, true};
    default:
      return {false, false, false};
  }
}

void constraints(const model::Material& mat, RigidBody& body, core::Diagnostics& d) {
  const model::RigidMaterial& r = mat.rigid;
  if (r.constraint_option == 1) {
    body.fixed_translation = code_axes(r.translation_constraint);
    body.fixed_rotation = code_axes(r.rotation_constraint);
  } else if (r.constraint_option == -1) {
    if (r.translation_constraint != 0) {
      d.error(mat.loc,
              "*MAT_RIGID {}: CMO = -1 with a local coordinate system (CON1 = {}) is not "
              "supported",
              mat.id, r.translation_constraint);
    }
    const int flags = r.rotation_constraint;
    for (int k = 0; k < 6; ++k) {
      int p = 1;
      for (int j = 0; j < 5 - k; ++j)
        p *= 10;
      const bool on = (flags / p) % 10 != 0;
      if (k < 3)
        body.fixed_translation[static_cast<std::size_t>(k)] = on;
      else
        body.fixed_rotation[static_cast<std::size_t>(k - 3)] = on;
    }
  } else if (r.constraint_option != 0) {
    d.error(mat.loc,
            "*MAT_RIGID {}: CMO = {} (constraints at a point) is not supported; use CMO "
            "= 1 or -1",
            mat.id, r.constraint_option);
  }
}

// The lead of every part after *CONSTRAINED_RIGID_BODIES: the part whose body it joins (itself
// when it is not merged), following chains; -1 where a merge loops back.
std::vector<std::ptrdiff_t> rigid_leads(const model::ModelDatabase& m, core::Diagnostics& d) {
  std::vector<std::ptrdiff_t> lead(m.parts.size());
  for (std::size_t p = 0; p < lead.size(); ++p)
    lead[p] = static_cast<std::ptrdiff_t>(p);
  for (const model::RigidMerge& r : m.rigid_merges) {
    const auto l = m.index.parts.find(r.lead), c = m.index.parts.find(r.constrained);
    if (l == model::IdIndex::kNone || c == model::IdIndex::kNone) continue;  // reported by check
    lead[static_cast<std::size_t>(c)] = static_cast<std::ptrdiff_t>(l);
  }
  for (std::size_t p = 0; p < lead.size(); ++p) {
    std::ptrdiff_t q = static_cast<std::ptrdiff_t>(p);
    std::size_t steps = 0;
    while (lead[static_cast<std::size_t>(q)] != q && ++steps <= lead.size())
      q = lead[static_cast<std::size_t>(q)];
    if (steps > lead.size()) {
      d.error(m.rigid_merges.front().loc,
              "*CONSTRAINED_RIGID_BODIES: the merges of part {} loop back to it; a lead part "
              "cannot be constrained to its own constrained parts",
              m.parts[p].id);
      q = -1;
    }
    lead[p] = q;
  }
  return lead;
}

// *PART_INERTIA: the lead part's mass, centre and inertia replace those its elements give (a
// merged part's own card would be lost in its lead's body: refused).
void given_inertia(const model::ModelDatabase& m, const State& s, RigidBody& body,
                   core::Diagnostics& d) {
  const model::Part* lead = m.part(body.part_id);
  const Index b = rigid_body_of(m, s, body.part_id);
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Part& part = m.parts[p];
    if (&part != lead && part.inertia && s.parts[p].rigid_body == b) {
      d.error(part.inertia->loc,
              "*PART_INERTIA {}: the part is merged into rigid part {} (*CONSTRAINED_RIGID_BODIES);"
              " give the body's mass properties on the lead part",
              part.id, body.part_id);
    }
  }
  if (lead == nullptr || !lead->inertia) return;
  const model::PartInertia& in = *lead->inertia;
  body.mass = in.mass;
  if (in.node != 0) {
    body.center = s.nodes.initial.col(static_cast<Index>(m.index.nodes.find(in.node)));
  } else {
    body.center = Vec3(in.centre[0], in.centre[1], in.centre[2]);
  }
  body.initial_center = body.center;
  const auto& t = in.tensor;
  body.inertia0 << t[0], t[1], t[2], t[1], t[3], t[4], t[2], t[4], t[5];
}

// A weld's number in messages: its WID, else its place among the welds (from 1).
model::Id weld_number(const model::ModelDatabase& m, std::size_t k) {
  return m.spot_welds[k].id != 0 ? m.spot_welds[k].id : static_cast<model::Id>(k + 1);
}

// A weld's nodes in deck order: N1 N2, or the set's as listed.
std::vector<Index> weld_nodes(const model::ModelDatabase& m, const model::SpotWeld& w) {
  std::vector<Index> out;
  auto add = [&](model::Id id) {
    const auto i = m.index.nodes.find(id);
    if (i != model::IdIndex::kNone &&
        std::find(out.begin(), out.end(), static_cast<Index>(i)) == out.end())
      out.push_back(static_cast<Index>(i));
  };
  if (w.node_set == 0) {
    for (const model::Id n : w.nodes)
      add(n);
  } else if (const model::NodeSet* set = m.node_set(w.node_set)) {
    for (const model::Id n : set->nodes)
      add(n);
  }
  return out;
}

// The weld's failure state: two nodes apart (their line is its normal).
void compile_weld(const model::ModelDatabase& m, const model::SpotWeld& w, Index body, State& s,
                  std::vector<WeldState>& welds, core::Diagnostics& d) {
  const std::vector<Index> nodes = weld_nodes(m, w);
  const auto k = static_cast<std::size_t>(&w - m.spot_welds.data());
  if (nodes.size() != 2) {
    d.error(w.loc,
            "spot weld {} has {} distinct node(s); mcdyna's spot welds join two (welds of three "
            "or more sheets are not supported)",
            weld_number(m, k), nodes.size());
    return;
  }
  const double gap = (s.nodes.initial.col(nodes[1]) - s.nodes.initial.col(nodes[0])).norm();
  if (!(gap > 0.0)) {
    d.error(w.loc,
            "spot weld {} joins coincident nodes {} and {}: its normal is undefined (a local "
            "system CID is not supported); give nodes apart, one on each sheet",
            weld_number(m, k), s.nodes.ids[static_cast<std::size_t>(nodes[0])],
            s.nodes.ids[static_cast<std::size_t>(nodes[1])]);
    return;
  }
  WeldState ws;
  ws.id = weld_number(m, k);
  ws.body = body;
  ws.first = nodes[0];
  ws.last = nodes[1];
  ws.normal_force = w.normal_force;
  ws.shear_force = w.shear_force;
  ws.normal_exponent = w.normal_exponent;
  ws.shear_exponent = w.shear_exponent;
  ws.failure_time = w.failure_time;
  ws.plastic_strain = w.plastic_strain;
  welds.push_back(ws);
}

}  // namespace

Index rigid_body_of(const model::ModelDatabase& m, const State& s, model::Id id) {
  const auto p = m.index.parts.find(id);
  if (p != model::IdIndex::kNone) return s.parts[static_cast<std::size_t>(p)].rigid_body;
  for (std::size_t b = 0; b < s.rigid_bodies.size(); ++b)
    if (id != 0 && s.rigid_bodies[b].part_id == id) return static_cast<Index>(b);  // welds: 0
  return -1;
}

void compile_rigid_bodies(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                          Blocks& own, core::Diagnostics& d) {
  std::vector<MassMoments> moments;
  std::vector<std::vector<Index>> nodes;
  auto new_body = [&](model::Id id) {
    RigidBody body;
    body.part_id = id;
    s.rigid_bodies.push_back(body);
    moments.emplace_back();
    nodes.emplace_back();
    return static_cast<Index>(s.rigid_bodies.size() - 1);
  };
  // One body per rigid part that leads (merged parts join their lead's body, and the lead's
  // CMO constraints hold it), then one per nodal rigid body.
  const std::vector<std::ptrdiff_t> lead = rigid_leads(m, d);
  auto rigid = [&](std::size_t p) {
    const model::Material* mat = m.material(m.parts[p].material);
    return mat != nullptr && mat->kind == model::MaterialKind::rigid;
  };
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    if (!rigid(p) || lead[p] != static_cast<std::ptrdiff_t>(p)) continue;
    s.parts[p].rigid_body = new_body(m.parts[p].id);
    constraints(*m.material(m.parts[p].material), s.rigid_bodies.back(), d);
  }
  for (std::size_t p = 0; p < m.parts.size(); ++p)
    if (rigid(p) && lead[p] >= 0 && rigid(static_cast<std::size_t>(lead[p])))
      s.parts[p].rigid_body = s.parts[static_cast<std::size_t>(lead[p])].rigid_body;
  const std::size_t part_bodies = s.rigid_bodies.size();
  for (const model::NodalRigidBody& nrb : m.nodal_rigid_bodies)
    new_body(nrb.id);
  const std::size_t weld_bodies = s.rigid_bodies.size();
  for (std::size_t k = 0; k < m.spot_welds.size(); ++k)
    new_body(0);  // a weld's body answers to no part ID
  if (s.rigid_bodies.empty()) return;
  // Where a body comes from, for its messages: a nodal rigid body's or a weld's card, else none.
  auto body_loc = [&](std::size_t b) {
    if (b >= weld_bodies) return m.spot_welds[b - weld_bodies].loc;
    if (b >= part_bodies) return m.nodal_rigid_bodies[b - part_bodies].loc;
    return core::SourceLoc{};
  };
  auto body_name = [&](std::size_t b) {
    if (b >= weld_bodies) return fmt::format("spot weld {}", weld_number(m, b - weld_bodies));
    return fmt::format("{} {}", b >= part_bodies ? "nodal rigid body" : "rigid part",
                       s.rigid_bodies[b].part_id);
  };
  auto node_of = [&](model::Id id) { return static_cast<Index>(m.index.nodes.find(id)); };
  auto claim = [&](Index body, Index node, const core::SourceLoc& loc) {
    Index& owner = s.nodes.rigid_body[static_cast<std::size_t>(node)];
    if (owner >= 0 && owner != body) {
      d.error(loc,
              "node {} belongs to rigid bodies {} and {}; merge them with "
              "*CONSTRAINED_RIGID_BODIES",
              s.nodes.ids[static_cast<std::size_t>(node)],
              s.rigid_bodies[static_cast<std::size_t>(owner)].part_id,
              s.rigid_bodies[static_cast<std::size_t>(body)].part_id);
      return;
    }
    if (owner < 0) nodes[static_cast<std::size_t>(body)].push_back(node);
    owner = body;
  };
  for (const model::SolidElement& el : m.solids) {
    const auto p = static_cast<std::size_t>(m.index.parts.find(el.part));
    const Index b = s.parts[p].rigid_body;
    if (b < 0) continue;
    std::array<Index, 8> conn{};
    for (std::size_t c = 0; c < 8; ++c) {
      conn[c] = node_of(el.nodes[c]);
      claim(b, conn[c], el.loc);
    }
    s.rigid_cells.solids.push_back(conn);
    s.rigid_cells.solid_parts.push_back(static_cast<Index>(p));
    s.rigid_cells.solid_ids.push_back(el.id);
    add_solid(s, conn, m.material(m.parts[p].material)->density,
              moments[static_cast<std::size_t>(b)]);
  }
  for (const model::ShellElement& el : m.shells) {
    const auto p = static_cast<std::size_t>(m.index.parts.find(el.part));
    const Index b = s.parts[p].rigid_body;
    if (b < 0) continue;
    std::array<Index, 4> conn{};
    for (std::size_t c = 0; c < 4; ++c) {
      conn[c] = node_of(el.nodes[c]);
      claim(b, conn[c], el.loc);
    }
    s.rigid_cells.shells.push_back(conn);
    s.rigid_cells.shell_parts.push_back(static_cast<Index>(p));
    s.rigid_cells.shell_ids.push_back(el.id);
    const double t = shell_thickness(el, m.section(m.parts[p].section));
    add_shell(s, conn, m.material(m.parts[p].material)->density * t,
              moments[static_cast<std::size_t>(b)]);
  }
  // Extra nodes join their part's body; a nodal rigid body is its set's nodes.
  for (const model::ExtraNodes& e : m.extra_nodes) {
    const Index b = rigid_body_of(m, s, e.part);
    if (b < 0) continue;  // not rigid: reported by check
    if (e.is_set) {
      for (const Index n : node_set_nodes(m, e.target))
        claim(b, n, e.loc);
    } else if (m.index.nodes.find(e.target) != model::IdIndex::kNone) {
      claim(b, node_of(e.target), e.loc);
    }
  }
  for (std::size_t k = 0; k < m.nodal_rigid_bodies.size(); ++k)
    for (const Index n : node_set_nodes(m, m.nodal_rigid_bodies[k].node_set))
      claim(static_cast<Index>(part_bodies + k), n, m.nodal_rigid_bodies[k].loc);
  for (std::size_t k = 0; k < m.spot_welds.size(); ++k)
    for (const Index n : weld_nodes(m, m.spot_welds[k]))
      claim(static_cast<Index>(weld_bodies + k), n, m.spot_welds[k].loc);
  for (std::size_t b = 0; b < s.rigid_bodies.size(); ++b) {
    RigidBody& body = s.rigid_bodies[b];
    MassMoments& mm = moments[b];
    body.nodes = nodes[b];
    std::sort(body.nodes.begin(), body.nodes.end());
    // Lumped mass that deformable elements attached to the body put on its nodes, and their
    // rotary inertia (shell nodes).
    double rotary = 0.0;
    for (const Index n : body.nodes) {
      mm.add(s.nodes.mass[static_cast<std::size_t>(n)], s.nodes.initial.col(n));
      if (!s.nodes.rotary_inertia.empty())
        rotary += s.nodes.rotary_inertia[static_cast<std::size_t>(n)];
    }
    const bool nodal = b >= part_bodies;
    if (!(mm.mass > 0.0)) {
      d.error(body_loc(b), "{} has no mass ({})", body_name(b),
              nodal ? "its nodes belong to no element" : "density or thickness zero");
      continue;
    }
    body.mass = mm.mass;
    body.center = body.initial_center = mm.first / mm.mass;
    const Mat3 about_centre = mm.second - mm.mass * body.center * body.center.transpose();
    body.inertia0 =
        about_centre.trace() * Mat3::Identity() - about_centre + rotary * Mat3::Identity();
    // A body of collinear point masses (a two-node weld of solid nodes) has no inertia about
    // its line, and the forces on its nodes no moment about it: that axis takes the other
    // principal moment, so the rotation about it stays defined (and at rest).
    Eigen::SelfAdjointEigenSolver<Mat3> principal(body.inertia0);
    Vec3 principal_moments = principal.eigenvalues();  // ascending
    if (!(principal_moments[2] > 0.0)) {
      d.error(body_loc(b), "{} is a single point: it has no rotary inertia", body_name(b));
      continue;
    }
    if (principal_moments[0] <= 1e-9 * principal_moments[2]) {
      principal_moments[0] = principal_moments[1];
      body.inertia0 = principal.eigenvectors() * principal_moments.asDiagonal() *
                      principal.eigenvectors().transpose();
      if (b < weld_bodies)  // a weld of two nodes always does: nothing to tell
        d.note(body_loc(b),
               "{}: its nodes lie on a line; the inertia about that line is taken as {:.4g}, "
               "the other principal moment",
               body_name(b), principal_moments[0]);
    }
    if (b < part_bodies) given_inertia(m, s, body, d);
    body.offsets.resize(3, static_cast<Index>(body.nodes.size()));
    for (std::size_t k = 0; k < body.nodes.size(); ++k)
      body.offsets.col(static_cast<Index>(k)) = s.nodes.initial.col(body.nodes[k]) - body.center;
  }
  std::vector<WeldState> welds;
  for (std::size_t k = 0; k < m.spot_welds.size(); ++k)
    compile_weld(m, m.spot_welds[k], static_cast<Index>(weld_bodies + k), s, welds, d);
  own.push_back(make_rigid_bodies_block(std::move(welds)));
}

}  // namespace mcdyna::solver::detail
