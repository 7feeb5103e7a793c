// MAT_020 parts -> rigid bodies: mass, centre and inertia from their elements (Gauss quadrature)
// plus the lumped mass deformable elements put on their nodes; CMO/CON1/CON2 constraints.
#include <cmath>

#include "solver/compile.hpp"
#include "solver/fe/hex_geometry.hpp"

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

}  // namespace

void compile_rigid_bodies(const model::ModelDatabase& m, State& s, core::Diagnostics& d) {
  std::vector<MassMoments> moments;
  std::vector<std::vector<Index>> nodes;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Material* mat = m.material(m.parts[p].material);
    if (mat == nullptr || mat->kind != model::MaterialKind::rigid) continue;
    s.parts[p].rigid_body = static_cast<Index>(s.rigid_bodies.size());
    RigidBody body;
    body.part_id = m.parts[p].id;
    constraints(*mat, body, d);
    s.rigid_bodies.push_back(body);
    moments.emplace_back();
    nodes.emplace_back();
  }
  if (s.rigid_bodies.empty()) return;
  auto node_of = [&](model::Id id) { return static_cast<Index>(m.index.nodes.find(id)); };
  auto claim = [&](Index body, Index node, const core::SourceLoc& loc) {
    Index& owner = s.nodes.rigid_body[static_cast<std::size_t>(node)];
    if (owner >= 0 && owner != body) {
      d.error(loc,
              "node {} belongs to rigid parts {} and {}; merged rigid bodies are not "
              "supported",
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
    const double t = shell_thickness(el, m.section(m.parts[p].section));
    add_shell(s, conn, m.material(m.parts[p].material)->density * t,
              moments[static_cast<std::size_t>(b)]);
  }
  for (std::size_t b = 0; b < s.rigid_bodies.size(); ++b) {
    RigidBody& body = s.rigid_bodies[b];
    MassMoments& mm = moments[b];
    body.nodes = nodes[b];
    std::sort(body.nodes.begin(), body.nodes.end());
    // Lumped mass that deformable elements attached to the body put on its nodes.
    for (const Index n : body.nodes)
      mm.add(s.nodes.mass[static_cast<std::size_t>(n)], s.nodes.initial.col(n));
    if (!(mm.mass > 0.0)) {
      d.error(core::SourceLoc{}, "rigid part {} has no mass (density or thickness zero)",
              body.part_id);
      continue;
    }
    body.mass = mm.mass;
    body.center = body.initial_center = mm.first / mm.mass;
    const Mat3 about_centre = mm.second - mm.mass * body.center * body.center.transpose();
    body.inertia0 = about_centre.trace() * Mat3::Identity() - about_centre;
    body.offsets.resize(3, static_cast<Index>(body.nodes.size()));
    for (std::size_t k = 0; k < body.nodes.size(); ++k)
      body.offsets.col(static_cast<Index>(k)) = s.nodes.initial.col(body.nodes[k]) - body.center;
  }
}

}  // namespace mcdyna::solver::detail
