// SPC and *NODE TC constraints, prescribed motions, initial velocities and planar rigid walls.
#include <Eigen/Dense>

#include <algorithm>
#include <map>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/loads/load_state.hpp"

namespace mcdyna::solver::detail {

namespace {

const model::Box* box_of(const model::ModelDatabase& m, model::Id id) {
  if (id == 0) return nullptr;
  const auto i = m.index.boxes.find(id);
  return i == model::IdIndex::kNone ? nullptr : &m.boxes[static_cast<std::size_t>(i)];
}

bool inside(const model::Box* box, const Vec3& x) {
  if (box == nullptr) return true;
  for (int k = 0; k < 3; ++k)
    if (x[k] < box->min[static_cast<std::size_t>(k)] ||
        x[k] > box->max[static_cast<std::size_t>(k)])
      return false;
  return true;
}

std::vector<Index> all_nodes(const State& s) {
  std::vector<Index> out(static_cast<std::size_t>(s.nodes.count()));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<Index>(i);
  return out;
}

std::vector<Index> nodes_of_parts(const model::ModelDatabase& m, const State& s,
                                  const std::vector<model::Id>& parts) {
  std::vector<char> in_part(m.parts.size(), 0);
  for (const model::Id p : parts) {
    const auto i = m.index.parts.find(p);
    if (i != model::IdIndex::kNone) in_part[static_cast<std::size_t>(i)] = 1;
  }
  std::vector<char> mark(static_cast<std::size_t>(s.nodes.count()), 0);
  auto take = [&](model::Id part, auto const& ids) {
    const auto i = m.index.parts.find(part);
    if (i == model::IdIndex::kNone || !in_part[static_cast<std::size_t>(i)]) return;
    for (const model::Id n : ids) {
      const auto k = m.index.nodes.find(n);
      if (k != model::IdIndex::kNone) mark[static_cast<std::size_t>(k)] = 1;
    }
  };
  for (const auto& e : m.solids)
    take(e.part, e.nodes);
  for (const auto& e : m.shells)
    take(e.part, e.nodes);
  std::vector<Index> out;
  for (std::size_t i = 0; i < mark.size(); ++i)
    if (mark[i]) out.push_back(static_cast<Index>(i));
  return out;
}

// Velocity of the rigid motion that best fits the velocities of the body's nodes a record gave
// one (exact for a rigid field): centroid velocity plus the spin from sum r x v = (sum r^2 I - r
// r^T) omega.
void fit_rigid_velocity(const State& s, RigidBody& body, const std::vector<std::uint8_t>& given) {
  // The nodes given a velocity; all of them when none is (the body then stays at rest).
  std::vector<Index> fitted;
  for (const Index n : body.nodes)
    if (given[static_cast<std::size_t>(n)]) fitted.push_back(n);
  if (fitted.empty()) fitted = body.nodes;
  if (fitted.empty()) return;
  Vec3 xm = Vec3::Zero(), vm = Vec3::Zero();
  for (const Index n : fitted) {
    xm += s.nodes.initial.col(n);
    vm += s.nodes.velocity.col(n);
  }
  xm /= static_cast<double>(fitted.size());
  vm /= static_cast<double>(fitted.size());
  Mat3 a = Mat3::Zero();
  Vec3 h = Vec3::Zero();
  const Nodes& nd = s.nodes;
  for (const Index n : fitted) {
    const Vec3 r = nd.initial.col(n) - xm;
    a += r.squaredNorm() * Mat3::Identity() - r * r.transpose();
    h += r.cross(Vec3(nd.velocity.col(n)) - vm);
    // A shell node's own spin counts with its radius of gyration squared, I / m: it is all
    // there is to fit for a body of coincident nodes (a weld joining two shells).
    const auto i = static_cast<std::size_t>(n);
    if (!nd.rotary_inertia.empty() && nd.rotary_inertia[i] > 0.0 && nd.mass[i] > 0.0) {
      const double gyration = nd.rotary_inertia[i] / nd.mass[i];
      a += gyration * Mat3::Identity();
      h += gyration * Vec3(nd.angular_velocity.col(n));
    }
  }
  const Vec3 omega = a.completeOrthogonalDecomposition().solve(h);
  body.omega = omega;
  body.velocity = vm + omega.cross(body.center - xm);
  body.angular_momentum = body.inertia0 * omega;
}

// *PART_INERTIA card 4: a velocity given there (any of the six non-zero) is the body's.
void given_velocity(const model::ModelDatabase& m, RigidBody& body) {
  const model::Part* part = body.part_id != 0 ? m.part(body.part_id) : nullptr;
  if (part == nullptr || !part->inertia) return;
  const model::PartInertia& in = *part->inertia;
  const Vec3 v(in.velocity[0], in.velocity[1], in.velocity[2]);
  const Vec3 w(in.angular_velocity[0], in.angular_velocity[1], in.angular_velocity[2]);
  if (v.isZero(0.0) && w.isZero(0.0)) return;
  body.velocity = v;
  body.omega = w;
  body.angular_momentum = body.inertia0 * w;
}

}  // namespace

Vec3 vector_direction(const model::ModelDatabase& m, model::Id id, const core::SourceLoc& loc,
                      core::Diagnostics& d) {
  for (const model::Vector& v : m.vectors) {
    if (v.id != id) continue;
    const Vec3 dir(v.head[0] - v.tail[0], v.head[1] - v.tail[1], v.head[2] - v.tail[2]);
    if (dir.norm() > 0.0) return dir.normalized();
  }
  d.error(loc, "*DEFINE_VECTOR {} is missing or has zero length", id);
  return Vec3::UnitX();
}

void compile_constraints(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                         Blocks& own, core::Diagnostics& d) {
  struct Entry {
    std::uint8_t mask = 0;
    double birth = 0.0, death = 1.0e20;
  };
  std::map<Index, Entry> merged;
  auto add = [&](Index n, std::uint8_t mask, double birth, double death,
                 const core::SourceLoc& loc) {
    if (mask == 0) return;
    if (s.nodes.rigid_body[static_cast<std::size_t>(n)] >= 0) {
      d.warning(loc,
                "constraint on node {} of a rigid body is ignored (constrain the rigid part "
                "with CMO/CON1/CON2 on *MAT_RIGID)",
                s.nodes.ids[static_cast<std::size_t>(n)]);
      return;
    }
    auto [it, fresh] = merged.try_emplace(n, Entry{mask, birth, death});
    if (!fresh) {
      it->second.mask |= mask;
      it->second.birth = std::min(it->second.birth, birth);
      it->second.death = std::max(it->second.death, death);
    }
  };
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    static constexpr std::uint8_t kCodes[8] = {0, 1, 2, 4, 3, 6, 5, 7};
    const int tc = m.nodes[i].translation_constraint;
    const int rc = m.nodes[i].rotation_constraint;
    const std::uint8_t mask = static_cast<std::uint8_t>((tc > 0 && tc <= 7 ? kCodes[tc] : 0) |
                                                        (rc > 0 && rc <= 7 ? kCodes[rc] << 3 : 0));
    add(static_cast<Index>(i), mask, 0.0, 1.0e20, m.nodes[i].loc);
  }
  for (const model::SpcConstraint& c : m.spcs) {
    if (c.coordinate_system != 0) {
      d.error(c.loc, "SPC in local coordinate system {} is not supported", c.coordinate_system);
      continue;
    }
    std::uint8_t mask = 0;
    for (int k = 0; k < 6; ++k)
      if (c.fixed[static_cast<std::size_t>(k)]) mask |= static_cast<std::uint8_t>(1U << k);
    if (c.is_set) {
      for (const Index n : node_set_nodes(m, c.target))
        add(n, mask, c.birth, c.death, c.loc);
    } else {
      add(static_cast<Index>(m.index.nodes.find(c.target)), mask, c.birth, c.death, c.loc);
    }
  }
  if (merged.empty()) return;
  NodalConstraints nc;
  for (const auto& [n, e] : merged) {
    nc.nodes.push_back(n);
    nc.masks.push_back(e.mask);
    nc.birth.push_back(e.birth);
    nc.death.push_back(e.death);
  }
  nc.reaction.setZero(3, static_cast<Index>(nc.nodes.size()));
  own.push_back(make_nodal_constraints_block(std::move(nc)));
}

void compile_motions(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                     Blocks& own, core::Diagnostics& d) {
  std::vector<NodalMotion> motions;
  for (const model::PrescribedMotion& pm : m.prescribed_motions) {
    const int dof = pm.dof;
    if (pm.kind < 0 || pm.kind > 2) {
      d.error(pm.loc,
              "prescribed motion VAD = {} is not supported (0 velocity, 1 acceleration, 2 "
              "displacement)",
              pm.kind);
      continue;
    }
    const Index curve = curve_index(m, pm.curve);
    if (curve < 0) {
      d.error(pm.curve_loc, "prescribed motion: LCID {} is not a defined curve", pm.curve);
      continue;
    }
    const double death = pm.death == 0.0 ? 1.0e28 : pm.death;
    if (pm.target_kind == model::MotionTarget::rigid_part) {
      const Index b = rigid_body_of(m, s, pm.target);
      if (b < 0) {
        d.error(pm.loc,
                "*BOUNDARY_PRESCRIBED_MOTION_RIGID: part {} is not a *MAT_RIGID part or a nodal "
                "rigid body",
                pm.target);
        continue;
      }
      if (dof < 1 || dof > 8) {
        d.error(pm.loc, "*BOUNDARY_PRESCRIBED_MOTION_RIGID: DOF = {} is not supported (1-8)", dof);
        continue;
      }
      RigidMotion rm;
      rm.rotation = dof >= 5;
      rm.axis = dof == 4 || dof == 8 ? vector_direction(m, pm.vector, pm.vector_loc, d)
                                     : Vec3::Unit((dof - 1) % 4);
      rm.kind = static_cast<MotionKind>(pm.kind);  // VAD 0-2, checked above
      rm.curve = curve;
      rm.scale = pm.scale;
      rm.birth = pm.birth;
      rm.death = death;
      s.rigid_bodies[static_cast<std::size_t>(b)].motions.push_back(rm);
      continue;
    }
    if (dof < 1 || dof > 4) {
      d.error(pm.loc,
              "prescribed nodal motion DOF = {} is not supported: solid nodes have "
              "translations only (1-3 x/y/z, 4 along VID)",
              dof);
      continue;
    }
    NodalMotion nm;
    nm.id = pm.id;
    nm.nodes = pm.target_kind == model::MotionTarget::node_set
                   ? node_set_nodes(m, pm.target)
                   : std::vector<Index>{static_cast<Index>(m.index.nodes.find(pm.target))};
    for (const Index n : nm.nodes) {
      if (s.nodes.rigid_body[static_cast<std::size_t>(n)] >= 0) {
        d.error(pm.loc,
                "prescribed motion on node {} of a rigid body; use "
                "*BOUNDARY_PRESCRIBED_MOTION_RIGID",
                s.nodes.ids[static_cast<std::size_t>(n)]);
      }
    }
    nm.axis = dof == 4 ? vector_direction(m, pm.vector, pm.vector_loc, d) : Vec3::Unit(dof - 1);
    nm.kind = static_cast<MotionKind>(pm.kind);  // VAD 0-2, checked above
    nm.curve = curve;
    nm.scale = pm.scale;
    nm.birth = pm.birth;
    nm.death = death;
    nm.node_force.setZero(3, static_cast<Index>(nm.nodes.size()));
    nm.node_work.assign(nm.nodes.size(), 0.0);
    motions.push_back(std::move(nm));
  }
  if (!motions.empty()) own.push_back(make_nodal_motions_block(std::move(motions)));
}

void compile_initial_velocities(const model::ModelDatabase& m, State& s,
                                const CompiledBlocks& /*before*/, core::Diagnostics& d) {
  auto& v = s.nodes.velocity;
  const Nodes& nd = s.nodes;
  // The nodes a record gives a velocity: a rigid body's motion is fitted to those of its nodes
  // (its extra nodes and weld nodes, given none, would pull it towards rest).
  std::vector<std::uint8_t> given(static_cast<std::size_t>(nd.count()), 0);
  auto rotates = [&](Index n) {
    return !nd.rotary_inertia.empty() && nd.rotary_inertia[static_cast<std::size_t>(n)] > 0.0;
  };
  // VXR, VYR, VZR: the angular velocity of the nodes that have rotations (shell nodes).
  auto spin = [&](Index n, const Vec3& w) {
    if (rotates(n)) s.nodes.angular_velocity.col(n) = w;
  };
  for (const model::InitialVelocity& iv : m.initial_velocities) {
    const Vec3 vel(iv.velocity[0], iv.velocity[1], iv.velocity[2]);
    const Vec3 omega(iv.angular_velocity[0], iv.angular_velocity[1], iv.angular_velocity[2]);
    switch (iv.kind) {
      case model::InitialVelocityKind::per_node: {
        const auto n = static_cast<Index>(m.index.nodes.find(iv.target));
        v.col(n) = vel;
        given[static_cast<std::size_t>(n)] = 1;
        spin(n, omega);
        if (omega != Vec3::Zero() && !rotates(n))
          d.warning(iv.loc,
                    "*INITIAL_VELOCITY_NODE: VXR/VYR/VZR of node {} are ignored: it has no "
                    "rotations (only shell nodes do)",
                    iv.target);
        break;
      }
      case model::InitialVelocityKind::by_set: {
        const model::Box* box = box_of(m, iv.box);
        std::vector<Index> nodes = iv.target == 0 ? all_nodes(s) : node_set_nodes(m, iv.target);
        std::vector<Index> exempt =
            iv.exempted_set == 0 ? std::vector<Index>{} : node_set_nodes(m, iv.exempted_set);
        const Vec3 ve(iv.exempted_velocity[0], iv.exempted_velocity[1], iv.exempted_velocity[2]);
        for (const Index n : nodes) {
          if (!inside(box, s.nodes.initial.col(n))) continue;
          const bool ex = std::binary_search(exempt.begin(), exempt.end(), n);
          v.col(n) = ex ? ve : vel;
          given[static_cast<std::size_t>(n)] = 1;
          if (!ex) spin(n, omega);
        }
        if (omega != Vec3::Zero() &&
            std::none_of(nodes.begin(), nodes.end(), [&](Index n) { return rotates(n); })) {
          d.warning(iv.loc,
                    "*INITIAL_VELOCITY: rotational velocities VXR/VYR/VZR apply to nodal "
                    "rotations, which only shell nodes have; ignored");
        }
        break;
      }
      case model::InitialVelocityKind::generation: {
        std::vector<Index> nodes;
        if (iv.target == 0) {
          nodes = all_nodes(s);
        } else if (iv.target_type == 3) {
          nodes = node_set_nodes(m, iv.target);
        } else if (iv.target_type == 2) {
          nodes = nodes_of_parts(m, s, {iv.target});
        } else {
          const model::PartSet* ps = m.part_set(iv.target);
          if (ps != nullptr) nodes = nodes_of_parts(m, s, ps->parts);
        }
        Vec3 axis(iv.axis_direction[0], iv.axis_direction[1], iv.axis_direction[2]);
        if (iv.omega != 0.0 && !(axis.norm() > 0.0)) {
          d.error(iv.loc,
                  "*INITIAL_VELOCITY_GENERATION: OMEGA = {} needs an axis direction "
                  "(NX = -999, axis by nodes, is not supported)",
                  iv.omega);
          break;
        }
        if (axis.norm() > 0.0) axis.normalize();
        const Vec3 c(iv.axis_point[0], iv.axis_point[1], iv.axis_point[2]);
        for (const Index n : nodes) {
          v.col(n) = vel + iv.omega * axis.cross(Vec3(s.nodes.initial.col(n)) - c);
          given[static_cast<std::size_t>(n)] = 1;
          spin(n, iv.omega * axis);  // a shell node turns with the body
        }
        break;
      }
    }
  }
  for (RigidBody& body : s.rigid_bodies) {
    fit_rigid_velocity(s, body, given);
    given_velocity(m, body);
    for (std::size_t k = 0; k < body.nodes.size(); ++k)
      v.col(body.nodes[k]) =
          body.velocity + body.omega.cross(Vec3(body.offsets.col(static_cast<Index>(k))));
  }
}

std::vector<Index> wall_nodes(const model::ModelDatabase& m, const State& s,
                              const model::RigidWall& w, const Vec3& point, const Vec3& normal) {
  const model::Box* box = box_of(m, w.box);
  std::vector<Index> nodes = w.node_set == 0 ? all_nodes(s) : node_set_nodes(m, w.node_set);
  std::vector<Index> exempt =
      w.exempted_set == 0 ? std::vector<Index>{} : node_set_nodes(m, w.exempted_set);
  std::vector<Index> out;
  for (const Index node : nodes) {
    const auto i = static_cast<std::size_t>(node);
    if (s.nodes.rigid_body[i] >= 0 || !(s.nodes.mass[i] > 0.0)) continue;
    if (std::binary_search(exempt.begin(), exempt.end(), node)) continue;
    const Vec3 x = s.nodes.initial.col(node);
    if (!inside(box, x)) continue;
    if (w.node_set == 0 && w.offset > 0.0) {
      const double dist = (x - point).dot(normal);
      if (dist < 0.0 || dist > w.offset) continue;
    }
    out.push_back(node);
  }
  return out;
}

}  // namespace mcdyna::solver::detail
