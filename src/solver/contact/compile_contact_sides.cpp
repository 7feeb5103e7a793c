// The sides of a contact (contact_sides.hpp): the parts' segments and their penalty, each
// node's penalty, and a side's nodes and segments by its type code.
#include <algorithm>
#include <cmath>

#include "solver/contact/contact_sides.hpp"
#include "solver/material/constitutive.hpp"
#include "solver/solids/hex_geometry.hpp"

namespace mcdyna::solver::detail {

namespace {

// The LS-DYNA hexahedron's faces, node order giving the outward normal of a positive element.
constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

struct Element {
  std::array<Index, 8> nodes;
  double volume;
};

double hex_volume(const State& s, const std::array<Index, 8>& conn) {
  hex::Corners x{};
  for (std::size_t c = 0; c < 8; ++c)
    for (std::size_t k = 0; k < 3; ++k)
      x[c][k] = s.nodes.initial(static_cast<Index>(k), conn[c]);
  const hex::GaussPoints& gauss = hex::gauss_points();
  double v = 0.0;
  for (int q = 0; q < 8; ++q)
    v += std::abs(hex::gradients(x, gauss.gradients[q]).det);
  return v;
}

double area_of(const State& s, const Face& f) {
  const auto x = [&](std::size_t k) { return Vec3(s.nodes.initial.col(f[k])); };
  return 0.5 * ((x(2) - x(0)).cross(x(3) - x(1))).norm();
}

double longest_diagonal(const State& s, const Face& f) {
  const auto x = [&](std::size_t k) { return Vec3(s.nodes.initial.col(f[k])); };
  return std::max((x(2) - x(0)).norm(), (x(3) - x(1)).norm());
}

void add_segment(Surface& out, const Face& f, double stiffness, double area, bool rigid) {
  out.segments.push_back(f);
  out.stiffness.push_back(stiffness);
  out.half_thickness.push_back(0.0);
  out.two_sided.push_back(0);
  out.area.push_back(area);
  out.smallest_node_mass.push_back(rigid ? std::numeric_limits<double>::infinity() : 0.0);
}

// Free faces (used once within the part) with outward normals; repeated nodes of degenerate
// hexahedra make triangles, or drop the face when fewer than three remain.
void add_free_faces(const State& s, const std::vector<Element>& solids, double bulk, bool rigid,
                    PartSurface& out) {
  std::map<Face, int> uses;
  auto face_of = [](const Element& e, const int(&face)[4]) {
    Face f{};
    for (std::size_t k = 0; k < 4; ++k)
      f[k] = e.nodes[static_cast<std::size_t>(face[k])];
    return f;
  };
  for (const Element& e : solids)
    for (const auto& face : kFaces)
      ++uses[sorted(face_of(e, face))];
  for (const Element& e : solids) {
    Vec3 centre = Vec3::Zero();
    for (const Index n : e.nodes)
      centre += s.nodes.initial.col(n) / 8.0;
    for (const auto& face : kFaces) {
      const Face f = face_of(e, face);
      if (uses[sorted(f)] != 1) continue;
      Face seg{};
      std::size_t distinct = 0;
      for (const Index n : f)
        if (std::find(seg.begin(), seg.begin() + static_cast<long>(distinct), n) ==
            seg.begin() + static_cast<long>(distinct))
          seg[distinct++] = n;
      if (distinct < 3) continue;
      if (distinct == 3) seg[3] = seg[2];
      const double area = area_of(s, seg);
      if (!(area > 0.0)) continue;
      out.surface.segments.push_back(seg);  // orientation checked just below
      Vec3 middle = Vec3::Zero();
      for (const Index n : seg)
        middle += s.nodes.initial.col(n) / 4.0;
      const auto x = [&](std::size_t k) { return Vec3(s.nodes.initial.col(seg[k])); };
      if (((x(2) - x(0)).cross(x(3) - x(1))).dot(middle - centre) < 0.0) {
        std::reverse(seg.begin(), seg.begin() + static_cast<long>(distinct));
        if (distinct == 3) seg[3] = seg[2];
      }
      out.surface.segments.pop_back();
      add_segment(out.surface, seg, bulk * area * area / e.volume, area, rigid);
      out.shell_thickness.push_back(0.0);
    }
  }
}

}  // namespace

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

std::vector<PartSurface> part_surfaces(const model::ModelDatabase& m, const State& s,
                                       const CompiledBlocks& before) {
  const Solids& so = solids_of(before);
  const Shells& shells = shells_of(before);
  const std::size_t parts = s.parts.size();
  std::vector<double> bulk(parts, 0.0);
  for (std::size_t p = 0; p < parts; ++p) {
    const PartInfo& info = s.parts[p];
    if (info.material >= 0) {
      bulk[p] = reference_bulk_modulus(s.materials[static_cast<std::size_t>(info.material)]);
    } else if (const model::Material* mat = m.material(info.material_id)) {
      const double e = mat->rigid.youngs_modulus, nu = mat->rigid.poisson_ratio;
      bulk[p] = e / (3.0 * (1.0 - 2.0 * nu));
    }
  }
  std::vector<std::vector<Element>> solids(parts);
  for (Index e = 0; e < so.count(); ++e) {
    const auto ee = static_cast<std::size_t>(e);
    solids[static_cast<std::size_t>(so.part[ee])].push_back({so.nodes[ee], so.initial_volume[ee]});
  }
  for (std::size_t k = 0; k < s.rigid_cells.solids.size(); ++k)
    solids[static_cast<std::size_t>(s.rigid_cells.solid_parts[k])].push_back(
        {s.rigid_cells.solids[k], hex_volume(s, s.rigid_cells.solids[k])});
  std::vector<PartSurface> out(parts);
  for (std::size_t p = 0; p < parts; ++p)
    add_free_faces(s, solids[p], bulk[p], s.parts[p].rigid_body >= 0, out[p]);
  // Rigid shells, in m.shells' order as compile_rigid_bodies put them in rigid_cells.
  std::size_t next = 0;
  for (const model::ShellElement& el : m.shells) {
    const auto p = static_cast<std::size_t>(m.index.parts.find(el.part));
    if (s.parts[p].rigid_body < 0) continue;
    const Face& seg = s.rigid_cells.shells[next++];
    const double area = area_of(s, seg);
    if (!(area > 0.0)) continue;
    add_segment(out[p].surface, seg, bulk[p] * area / longest_diagonal(s, seg), area, true);
    out[p].shell_thickness.push_back(shell_thickness(el, m.section(m.parts[p].section)));
  }
  // Deformable shells: segments at their mid-surfaces, penalty K A / longest diagonal as the
  // rigid ones.
  for (std::size_t e = 0; e < shells.ids.size(); ++e) {
    const auto p = static_cast<std::size_t>(shells.part[e]);
    const Face& seg = shells.nodes[e];
    const double area = area_of(s, seg);
    if (!(area > 0.0)) continue;
    add_segment(out[p].surface, seg, bulk[p] * area / longest_diagonal(s, seg), area, false);
    out[p].shell_thickness.push_back(shells.initial_thickness[e]);
  }
  for (const spg::Domain* d : spg::domains_of(before))
    out[static_cast<std::size_t>(d->part)].particles = d->particles.nodes;
  for (Index e = 0; e < so.count(); ++e) {
    const auto ee = static_cast<std::size_t>(e);
    std::vector<Index>& nodes = out[static_cast<std::size_t>(so.part[ee])].solid_nodes;
    nodes.insert(nodes.end(), so.nodes[ee].begin(), so.nodes[ee].end());
  }
  for (PartSurface& p : out) {
    std::sort(p.solid_nodes.begin(), p.solid_nodes.end());
    p.solid_nodes.erase(std::unique(p.solid_nodes.begin(), p.solid_nodes.end()),
                        p.solid_nodes.end());
  }
  return out;
}

std::vector<double> node_stiffness(const State& s, const CompiledBlocks& before,
                                   const std::vector<PartSurface>& parts) {
  const Solids& so = solids_of(before);
  std::vector<double> k(static_cast<std::size_t>(s.nodes.count()), 0.0);
  for (const PartSurface& p : parts)
    for (std::size_t j = 0; j < p.surface.segments.size(); ++j)
      for (const Index n : p.surface.segments[j]) {
        double& kn = k[static_cast<std::size_t>(n)];
        kn = std::max(kn, p.surface.stiffness[j]);
      }
  for (const spg::Domain* dp : spg::domains_of(before)) {
    const spg::Domain& d = *dp;
    const double bulk = reference_bulk_modulus(
        s.materials[static_cast<std::size_t>(s.parts[static_cast<std::size_t>(d.part)].material)]);
    for (std::size_t i = 0; i < d.particles.nodes.size(); ++i)
      k[static_cast<std::size_t>(d.particles.nodes[i])] =
          bulk * std::cbrt(d.particles.initial_volume[i]);
  }
  std::vector<double> interior(k.size(), 0.0);
  for (std::size_t e = 0; e < so.ids.size(); ++e) {
    const PartInfo& part = s.parts[static_cast<std::size_t>(so.part[e])];
    if (part.material < 0) continue;
    const double ke = reference_bulk_modulus(s.materials[static_cast<std::size_t>(part.material)]) *
                      std::cbrt(so.initial_volume[e]);
    for (const Index n : so.nodes[e])
      interior[static_cast<std::size_t>(n)] = std::max(interior[static_cast<std::size_t>(n)], ke);
  }
  for (std::size_t n = 0; n < k.size(); ++n)
    if (k[n] == 0.0) k[n] = interior[n];
  return k;
}

Side resolve_side(const model::ModelDatabase& m, const std::vector<PartSurface>& parts,
                  const FaceOwners& face_owner, core::Diagnostics& d, const model::Contact& c,
                  model::Id number, const model::ContactSide& side, const char* name, bool& ok) {
  Side out;
  std::vector<std::size_t> members;
  auto add_part = [&](model::Id id) {
    const auto p = m.index.parts.find(id);
    if (p == model::IdIndex::kNone) {
      d.error(c.loc, "contact {}: side {}: part {} is not defined", number, name, id);
      ok = false;
    } else {
      members.push_back(static_cast<std::size_t>(p));
    }
  };
  if (side.type == 3) {
    add_part(side.id);
  } else if (side.type == 2) {
    const model::PartSet* ps = m.part_set(side.id);
    if (ps == nullptr) {
      d.error(c.loc, "contact {}: side {}: part set {} is not defined", number, name, side.id);
      ok = false;
    } else {
      for (const model::Id id : ps->parts)
        add_part(id);
    }
  } else if (side.type == 5) {
    for (std::size_t p = 0; p < parts.size(); ++p)
      members.push_back(p);
  } else if (side.type == 4) {
    out.nodes = node_set_nodes(m, side.id);
    if (out.nodes.empty()) {
      d.error(c.loc, "contact {}: side {}: node set {} is not defined or empty", number, name,
              side.id);
      ok = false;
    }
  } else if (side.type == 0 || side.type == 1) {
    // A segment set, or a shell element set (each shell its own segment).
    std::vector<std::array<model::Id, 4>> segments;
    bool defined = false;
    if (side.type == 0) {
      const auto set = m.index.segment_sets.find(side.id);
      if (set != model::IdIndex::kNone) {
        defined = true;
        segments = m.segment_sets[static_cast<std::size_t>(set)].segments;
      }
    } else {
      for (const model::ElementSet& es : m.element_sets) {
        if (es.kind != model::ElementSetKind::shell || es.id != side.id) continue;
        defined = true;
        for (const model::Id e : es.elements) {
          const auto i = m.index.shells.find(e);
          if (i != model::IdIndex::kNone)
            segments.push_back(m.shells[static_cast<std::size_t>(i)].nodes);
        }
      }
    }
    const char* kind = side.type == 0 ? "segment set" : "shell set";
    if (!defined) {
      d.error(c.loc, "contact {}: side {}: {} {} is not defined", number, name, kind, side.id);
      ok = false;
    } else {
      for (const auto& ids : segments) {
        Face f{};
        for (std::size_t k = 0; k < 4; ++k)
          f[k] = static_cast<Index>(m.index.nodes.find(ids[k]));
        const auto owner = face_owner.find(sorted(f));
        if (owner == face_owner.end()) {
          d.error(c.loc,
                  "contact {}: side {}: segment {} {} {} {} of {} {} is not a free face of a "
                  "solid or a shell, so its penalty stiffness is unknown",
                  number, name, ids[0], ids[1], ids[2], ids[3], kind, side.id);
          ok = false;
          continue;
        }
        const PartSurface& ps = parts[owner->second.first];
        const std::size_t j = owner->second.second;
        add_segment(out.surface, f, ps.surface.stiffness[j], ps.surface.area[j],
                    std::isinf(ps.surface.smallest_node_mass[j]));
        out.shell_thickness.push_back(ps.shell_thickness[j]);
        out.nodes.insert(out.nodes.end(), f.begin(), f.end());
      }
    }
  } else {
    d.error(c.loc,
            "contact {}: side {} type {} is not supported (0 segment set, 1 shell set, 2 part "
            "set, 3 part, 4 node set, 5 all parts)",
            number, name, side.type);
    ok = false;
  }
  for (const std::size_t p : members) {
    const PartSurface& ps = parts[p];
    for (std::size_t j = 0; j < ps.surface.segments.size(); ++j) {
      add_segment(out.surface, ps.surface.segments[j], ps.surface.stiffness[j], ps.surface.area[j],
                  std::isinf(ps.surface.smallest_node_mass[j]));
      out.shell_thickness.push_back(ps.shell_thickness[j]);
      out.nodes.insert(out.nodes.end(), ps.surface.segments[j].begin(),
                       ps.surface.segments[j].end());
    }
    out.nodes.insert(out.nodes.end(), ps.particles.begin(), ps.particles.end());
    out.has_particles = out.has_particles || !ps.particles.empty();
    out.slave_nodes.insert(out.slave_nodes.end(), ps.solid_nodes.begin(), ps.solid_nodes.end());
  }
  std::sort(out.nodes.begin(), out.nodes.end());
  out.nodes.erase(std::unique(out.nodes.begin(), out.nodes.end()), out.nodes.end());
  out.slave_nodes.insert(out.slave_nodes.end(), out.nodes.begin(), out.nodes.end());
  std::sort(out.slave_nodes.begin(), out.slave_nodes.end());
  out.slave_nodes.erase(std::unique(out.slave_nodes.begin(), out.slave_nodes.end()),
                        out.slave_nodes.end());
  return out;
}

FaceOwners face_owners(const std::vector<PartSurface>& parts) {
  FaceOwners owners;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (std::size_t j = 0; j < parts[p].surface.segments.size(); ++j)
      owners.emplace(sorted(parts[p].surface.segments[j]), std::make_pair(p, j));
  return owners;
}

std::vector<Index> all_nodes(const Side& side) {
  std::vector<Index> nodes = side.nodes;
  nodes.insert(nodes.end(), side.slave_nodes.begin(), side.slave_nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace mcdyna::solver::detail
