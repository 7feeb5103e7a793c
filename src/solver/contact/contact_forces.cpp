// Penalty forces of node-to-segment contact, as LS-DYNA's standard penalty formulation: a slave
// node that has passed through a master segment is pushed back by k d along the segment normal
// (d the penetration), with Coulomb friction on an elastic tangential spring of the same k and
// normal viscous damping; the opposite force goes to the segment's nodes with the weights of the
// contact point.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/exact_sum.hpp"
#include "solver/contact/contact.hpp"
#include "solver/contact/segment_geometry.hpp"
#include "solver/parallel/owned_gather.hpp"

namespace mcdyna::solver::contact {

namespace {

// Runs `exchange` (a collective) and adds its wall seconds to `seconds`.
template <class Exchange>
auto timed(double& seconds, Exchange&& exchange) {
  const auto start = std::chrono::steady_clock::now();
  auto result = exchange();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// A node whose closest point lies beyond the segment's edges by more than this share of the
// segment's size is not in contact with it (its neighbour segment, or none, holds it).
constexpr double kEdgeTolerance = 0.1;
// A node that has passed more than this share of the segment's size beyond its contact surface
// is released: it is then on the far side of a thin part, not inside the body.
constexpr double kReleaseDepth = 0.5;

struct Hit {
  Index segment = -1;
  std::array<double, 4> weights{};
  Vec3 force = Vec3::Zero();     ///< on the slave node
  Vec3 friction = Vec3::Zero();  ///< tangential force to carry to the next cycle
  Vec3 push = Vec3::Zero();      ///< the side the node is held on (Pass::side)
  double initial = 0.0;          ///< what is left of the initial penetration (Pass)
};

// The segment the node touches (the nearest candidate, the deeper of equals) and how.
struct Touch {
  Index segment = -1;
  SegmentPoint at;
  Vec3 push = Vec3::Zero();  ///< unit, from the segment towards where the node must go
  double depth = 0.0;
};

Touch find_touch(const State& s, const Pass& p, std::size_t i) {
  const Index node = p.nodes[i];
  const Vec3 x = s.nodes.position.col(node);
  Touch best;
  double nearest = std::numeric_limits<double>::infinity();
  for (Index c = p.candidate_offsets[i]; c < p.candidate_offsets[i + 1]; ++c) {
    const Index k = p.candidates[static_cast<std::size_t>(c)];
    const auto kk = static_cast<std::size_t>(k);
    const std::array<Index, 4>& seg = p.surface.segments[kk];
    if (std::find(seg.begin(), seg.end(), node) != seg.end()) continue;
    std::array<Vec3, 4> corners;
    for (std::size_t j = 0; j < 4; ++j)
      corners[j] = s.nodes.position.col(seg[j]);
    const SegmentPoint at = closest_on_segment(x, corners);
    const Vec3 r = x - at.point;
    const double gap = r.dot(at.normal);
    const double size = std::sqrt(p.surface.area[kk]);
    const double beyond_edge = (r - gap * at.normal).norm();
    const double h = p.surface.half_thickness[kk] + p.node_half_thickness[i];
    // A segment touched at a distance (shell thickness) is the set of points within h of it:
    // its offset faces and, beyond its edges, a rounded rim of radius h, as LS-DYNA's
    // automatic contacts wrap shell edges. The depth is then h minus the distance to the
    // closest point, continuous from one segment to the next over a fold's crest, where
    // offset faces alone leave a wedge the node enters freely and then is thrown out of
    // whenever h reaches beyond the edge tolerance.
    // Thinner than the edge tolerance, the tolerance band already covers every point within h
    // of an edge, and the faces act as before. Rigid segments (a tool's nominal skin, as the
    // FDS screw's 0.02 mm on its facets) keep the faces too: their rims wait for the FDS study
    // to be measured again with them.
    const bool rim = h > kEdgeTolerance * size && beyond_edge > 1e-9 * size &&
                     std::isfinite(p.surface.smallest_node_mass[kk]);
    if (!rim && beyond_edge > kEdgeTolerance * size) continue;
    double side = 1.0;  // one-sided: the normal's side
    if (p.surface.two_sided[kk]) {
      // The side it was held on last cycle, else the side it is on now.
      const Vec3 held = p.side.col(static_cast<Eigen::Index>(i));
      const double was = held.dot(at.normal);
      side = was != 0.0 ? (was > 0.0 ? 1.0 : -1.0) : (gap >= 0.0 ? 1.0 : -1.0);
    }
    double depth = h - side * gap;
    Vec3 push = side * at.normal;
    if (rim) {
      const double distance = r.norm();
      depth = h - distance;
      push = r / distance;
    }
    if (depth > kReleaseDepth * size + h) continue;
    const double distance = r.norm();
    const bool nearer = distance < nearest * (1.0 - 1e-12);
    const bool tie = !nearer && distance <= nearest * (1.0 + 1e-12);
    if (nearer || (tie && depth > best.depth)) {
      nearest = distance;
      best = {k, at, push, depth};
    }
  }
  if (best.depth <= 0.0) best.segment = -1;
  return best;
}

// SOFT 2: the spring of the node's mass and the segment's (the mean of its nodes', +inf for a
// rigid segment) in series, stiff enough that its period is 2 pi / sqrt(scale) steps.
double segment_based_penalty(const State& s, const Interface& c, const Pass& p, std::size_t k,
                             double node_mass) {
  const double dt = s.step > 0.0 ? s.step : c.initial_step;
  if (!(dt > 0.0)) return 0.0;
  double segment_mass = std::numeric_limits<double>::infinity();
  if (std::isfinite(p.surface.smallest_node_mass[k])) {
    segment_mass = 0.0;
    for (const Index n : p.surface.segments[k])
      segment_mass += 0.25 * s.nodes.mass[static_cast<std::size_t>(n)];
  }
  const double pair =
      std::isinf(segment_mass) ? node_mass : node_mass * segment_mass / (node_mass + segment_mass);
  const auto pass = static_cast<std::size_t>(&p - c.passes.data());
  return c.segment_based_scale[pass] * pair / (dt * dt);
}

double penalty(const State& s, const Interface& c, const Pass& p, std::size_t i, std::size_t k,
               double node_mass) {
  if (c.segment_based) return segment_based_penalty(s, c, p, k, node_mass);
  const double segment = p.surface.stiffness[k];
  const double node = p.stiffness[i] > 0.0 ? p.stiffness[i] : segment;  // a node on no element
  double stiffness = c.penalty_scale == PenaltyScale::segment ? segment
                     : c.penalty_scale == PenaltyScale::node  ? node
                                                              : std::min(node, segment);
  if (c.soft_constraint && c.initial_step > 0.0) {
    // Soft constraint: a spring whose period matches the initial step for the smaller mass.
    const double m = std::min(node_mass, p.surface.smallest_node_mass[k]);
    stiffness = std::max(stiffness, 0.5 * c.soft_scale * m / (c.initial_step * c.initial_step));
  }
  return stiffness;
}

Hit contact_force(const State& s, const Interface& c, const Pass& p, std::size_t i) {
  Hit h;
  Touch t = find_touch(s, p, i);
  if (t.segment < 0) return h;
  // An initial penetration kept as an offset: the node is pushed only beyond it, and as it
  // moves out the offset follows it down to zero.
  const double initial = p.initial_penetration[i];
  h.initial = std::min(initial, t.depth);
  t.depth -= initial;
  if (t.depth <= 0.0) {
    h.push = t.push;  // held on its side while inside its initial depth
    return h;
  }
  const auto k = static_cast<std::size_t>(t.segment);
  const Index node = p.nodes[i];
  const double m = s.nodes.mass[static_cast<std::size_t>(node)];
  const double stiffness = penalty(s, c, p, i, k, m);
  const std::array<Index, 4>& seg = p.surface.segments[k];
  Vec3 v_segment = Vec3::Zero();
  for (std::size_t j = 0; j < 4; ++j)
    v_segment += t.at.weights[j] * s.nodes.velocity.col(seg[j]);
  const Vec3 v = s.nodes.velocity.col(node) - v_segment;
  const double v_normal = v.dot(t.push);  // > 0: separating

  // Normal force: penalty plus damping (a share of critical for the node's mass, the segment
  // counted as rigid when it is heavier), never pulling the node back in.
  const double m_pair =
      std::isfinite(p.surface.smallest_node_mass[k])
          ? m * p.surface.smallest_node_mass[k] / (m + p.surface.smallest_node_mass[k])
          : m;
  const double damping = c.damping * 2.0 * std::sqrt(stiffness * m_pair);
  const double normal = std::max(0.0, stiffness * t.depth - damping * v_normal);
  h.segment = t.segment;
  h.weights = t.at.weights;
  h.push = t.push;
  h.force = normal * t.push;

  // Coulomb friction on an elastic spring: the carried tangential force, turned into the
  // current tangent plane, minus k times the slip of this step, capped at mu N (and VC A).
  if (c.static_friction > 0.0 || c.dynamic_friction > 0.0) {
    const Vec3 v_tangent = v - v_normal * t.push;
    const Vec3 carried = p.friction.col(static_cast<Eigen::Index>(i));
    Vec3 f = carried - carried.dot(t.push) * t.push;
    f -= stiffness * s.step * v_tangent;
    const double mu = c.dynamic_friction + (c.static_friction - c.dynamic_friction) *
                                               std::exp(-c.decay * v_tangent.norm());
    double limit = mu * normal;
    if (c.viscous_friction > 0.0) limit = std::min(limit, c.viscous_friction * p.surface.area[k]);
    const double magnitude = f.norm();
    if (magnitude > limit) f *= limit / magnitude;
    h.friction = f;
    h.force += f;
  }
  return h;
}

// Nodes that may be moved out of an initial penetration: FE nodes, not SPG particles or the
// nodes of rigid bodies.
bool movable(const State& s, const std::vector<std::uint8_t>& particle, Index node) {
  const auto n = static_cast<std::size_t>(node);
  return s.nodes.rigid_body[n] < 0 && particle[n] == 0;
}

}  // namespace

InitialPenetrations resolve_initial_penetrations(State& s, Interface& c,
                                                 const std::vector<std::uint8_t>& particle) {
  InitialPenetrations r;
  sort_buckets(s, c);
  for (Pass& p : c.passes) {
    p.initial_penetration.assign(p.nodes.size(), 0.0);
    for (const Index near : p.near) {
      const auto i = static_cast<std::size_t>(near);
      const Touch t = find_touch(s, p, i);
      if (t.segment < 0) continue;
      const Index node = p.nodes[i];
      ++r.count;
      if (t.depth > r.deepest) {
        r.deepest = t.depth;
        r.node = node;
      }
      if (c.initial_penetration == InitialPenetration::move && movable(s, particle, node)) {
        s.nodes.position.col(node) += t.depth * t.push;
        s.nodes.initial.col(node) = s.nodes.position.col(node);
        ++r.moved;
      } else {
        p.initial_penetration[i] = t.depth;
      }
    }
  }
  return r;
}

namespace {

// What one pass sums over its hits: force and moment on side A (0) and B (1), the mass of the A
// nodes in contact, the work taken from the structure.
struct Resultants {
  std::array<core::ExactSum, 12> force_moment;  // per side: force x y z, moment x y z
  core::ExactSum mass, work;
  void add(int side, const Vec3& f, const Vec3& m) {
    for (int k = 0; k < 3; ++k) {
      force_moment[static_cast<std::size_t>(6 * side + k)].add(f[k]);
      force_moment[static_cast<std::size_t>(6 * side + 3 + k)].add(m[k]);
    }
  }
  // The totals over the processes (each holds the partial sums of the nodes it owns).
  void store(Interface& c, const core::Communicator& comm, double& exchange_seconds) const {
    std::vector<core::ExactSum> partials(force_moment.begin(), force_moment.end());
    partials.push_back(mass);
    partials.push_back(work);
    const std::vector<double> total = timed(exchange_seconds, [&] { return comm.sum(partials); });
    auto v = [&](std::size_t first) {
      return Vec3(total[first], total[first + 1], total[first + 2]);
    };
    c.force_a = v(0);
    c.moment_a = v(3);
    c.force_b = v(6);
    c.moment_b = v(9);
    c.mass_in_contact = total[12];
    c.energy -= total[13];
  }
};

// One node's share of a hit: the slave node's force (slot 0) or a segment node's (slot 1 + its
// corner). `key` orders them as one process adds them: pass, slave node, slot.
struct Contribution {
  std::int64_t key = 0;
  Index node = 0;
  Vec3 force = Vec3::Zero();
};

std::int64_t contribution_key(std::size_t pass, std::size_t node_index, std::size_t slot) {
  return (static_cast<std::int64_t>(pass) << 40) | (static_cast<std::int64_t>(node_index) << 3) |
         static_cast<std::int64_t>(slot);
}

// Every force of the interface's hits, in the order one process adds them: each process
// computes the hits of the slave nodes it owns, keeps their state (friction, side, initial
// penetration) and sends each segment node's share to the node's owner, which adds all shares
// of its nodes in the order of their keys (pass, slave node, slot): the same sums, bit for bit,
// on any number of processes. A replicated node (moved by every process: a shell's, an ITB 1
// part's) gets its shares on every process. The hits it computed go to Interface::computed
// whole.
std::vector<Contribution> owned_contributions(const State& s, Interface& c,
                                              double& exchange_seconds) {
  const parallel::Ownership& own = s.ownership;
  const int processes = own.comm.size();
  const bool split = processes > 1 && !own.owner.empty();
  const int me = own.comm.rank();
  auto owner = [&](Index node) { return split ? own.owner[static_cast<std::size_t>(node)] : me; };
  std::vector<Contribution> mine;
  std::vector<std::vector<double>> to(static_cast<std::size_t>(processes));
  c.computed.clear();
  Index hit_base = 0;  // the node counts of the passes before
  auto emit = [&](std::size_t pass, std::size_t i, std::size_t slot, Index node, const Vec3& f) {
    c.computed.push_back({node, hit_base + static_cast<Index>(i), static_cast<Index>(slot), f});
    const std::int64_t key = contribution_key(pass, i, slot);
    auto send = [&](int r) {
      std::vector<double>& out = to[static_cast<std::size_t>(r)];
      out.insert(out.end(),
                 {static_cast<double>(key), static_cast<double>(node), f[0], f[1], f[2]});
    };
    if (split && own.replicated_node(node)) {
      mine.push_back({key, node, f});
      for (int r = 0; r < processes; ++r)
        if (r != me) send(r);
      return;
    }
    const int r = owner(node);
    if (r == me) {
      mine.push_back({key, node, f});
      return;
    }
    send(r);
  };
  for (std::size_t pass = 0; pass < c.passes.size(); ++pass) {
    Pass& p = c.passes[pass];
    if (pass > 0) hit_base += static_cast<Index>(c.passes[pass - 1].nodes.size());
    // The near nodes this process owns (all of them after a sort over several processes;
    // those of the first sort, made whole before the split, are filtered here).
    std::vector<Index> owned;
    owned.reserve(p.near.size());
    for (std::size_t k = 0; k < p.near.size(); ++k)
      if (owner(p.nodes[static_cast<std::size_t>(p.near[k])]) == me)
        owned.push_back(static_cast<Index>(k));
    const auto n = static_cast<Index>(owned.size());
    std::vector<Hit> hits(owned.size());
#pragma omp parallel for schedule(static, 64) if (n > 512)
    for (Index q = 0; q < n; ++q)
      hits[static_cast<std::size_t>(q)] =
          contact_force(s, c, p,
                        static_cast<std::size_t>(
                            p.near[static_cast<std::size_t>(owned[static_cast<std::size_t>(q)])]));
    for (std::size_t q = 0; q < owned.size(); ++q) {
      const Hit& h = hits[q];
      const auto i = static_cast<std::size_t>(p.near[static_cast<std::size_t>(owned[q])]);
      p.friction.col(static_cast<Eigen::Index>(i)) = h.friction;
      p.side.col(static_cast<Eigen::Index>(i)) = h.push;
      p.initial_penetration[i] = h.initial;
      if (h.segment < 0) continue;
      emit(pass, i, 0, p.nodes[i], h.force);
      const std::array<Index, 4>& seg = p.surface.segments[static_cast<std::size_t>(h.segment)];
      for (std::size_t j = 0; j < 4; ++j)
        if (h.weights[j] != 0.0) emit(pass, i, 1 + j, seg[j], -h.weights[j] * h.force);
    }
  }
  if (!split) return mine;
  const std::vector<std::vector<double>> from =
      timed(exchange_seconds, [&] { return own.comm.all_to_all(to); });
  for (const std::vector<double>& in : from)
    for (std::size_t k = 0; k + 5 <= in.size(); k += 5)
      mine.push_back({static_cast<std::int64_t>(in[k]), static_cast<Index>(in[k + 1]),
                      Vec3(in[k + 2], in[k + 3], in[k + 4])});
  // Each list is in key order already; the merge puts them in the order of one process.
  std::stable_sort(mine.begin(), mine.end(),
                   [](const Contribution& a, const Contribution& b) { return a.key < b.key; });
  return mine;
}

}  // namespace

void interface_pass(State& s, Interface& c, bool sort, Eigen::Matrix3Xd& force,
                    double& exchange_seconds) {
  // What the interface took from the structure (penalty springs and friction), the glstat
  // sliding energy: the work of the contact forces over each step with the trapezoidal rule,
  // half the force at either end times x^{n+1} - x^n = dt^{n+1/2} v^{n+1/2} (exact for a
  // linear spring, so an elastic impact gives it all back). This half: last cycle's forces.
  // The work and the resultants are exact sums (core::ExactSum): over several processes each
  // adds the forces on the nodes it owns (`applied` holds those only) and the partial sums
  // merge exactly.
  const double step = s.step;
  Resultants sums;
  auto charge = [&](Index node, const Vec3& f) {
    sums.work.add(0.5 * step * f.dot(s.nodes.velocity.col(node)));
  };
  for (const AppliedForce& a : c.applied)
    charge(a.node, a.force);
  c.applied.clear();
  if (c.initial_step == 0.0 && s.step > 0.0) c.initial_step = s.step;
  if (!c.acting(s.time)) {
    for (Pass& p : c.passes) {
      p.friction.setZero();
      p.side.setZero();
    }
    sums.store(c, s.ownership.comm, exchange_seconds);
    return;
  }
  if (sort) sort_buckets(s, c);
  for (const Contribution& f : owned_contributions(s, c, exchange_seconds)) {
    const Pass& p = c.passes[static_cast<std::size_t>(f.key >> 40)];
    const auto slot = static_cast<Index>(f.key & 7);
    force.col(f.node) += f.force;
    // A replicated node's force is on every process; its owner alone counts it in the sums.
    if (!s.ownership.owned_now(f.node)) continue;
    c.applied.push_back({f.node, 0, slot, f.force});
    charge(f.node, f.force);
    // Side A (0) holds the slave nodes of a pass whose nodes are on side A.
    const bool on_slave_side = slot == 0;
    const int side = (on_slave_side == p.nodes_on_side_a) ? 0 : 1;
    sums.add(side, f.force, Vec3(s.nodes.position.col(f.node)).cross(f.force));
    if (on_slave_side && p.nodes_on_side_a)
      sums.mass.add(s.nodes.mass[static_cast<std::size_t>(f.node)]);
  }
  sums.store(c, s.ownership.comm, exchange_seconds);
}

void transducer_pass(State& s, Interface& t, std::span<const Interface* const> contacts,
                     double& exchange_seconds) {
  // Each process sums the hits it computed (Interface::computed: whole hits, their nodes'
  // positions current here) and the processes' partial sums merge exactly; a node touched by
  // hits of several processes counts its mass once, on its owner.
  const core::Communicator& comm = s.ownership.comm;
  Resultants sums;
  if (!t.acting(s.time)) {
    sums.store(t, comm, exchange_seconds);
    return;
  }
  const Transducer& sensor = t.sensor;
  auto on = [](const std::vector<Index>& nodes, Index n) {
    return std::binary_search(nodes.begin(), nodes.end(), n);
  };
  auto add = [&](int side, const AppliedForce& a) {
    sums.add(side, a.force, s.nodes.position.col(a.node).cross(a.force));
  };
  std::vector<Index> touched;  // side A nodes that took a force, for the mass in contact
  for (const Interface* c : contacts) {
    const std::vector<AppliedForce>& f = c->computed;
    for (std::size_t begin = 0; begin < f.size();) {
      // One hit: f[begin] is the slave node's force, the rest its segment's nodes'.
      std::size_t end = begin + 1;
      while (end < f.size() && f[end].hit == f[begin].hit)
        ++end;
      if (sensor.nodes_b.empty()) {
        for (std::size_t k = begin; k < end; ++k)
          if (on(sensor.nodes_a, f[k].node)) {
            add(0, f[k]);
            touched.push_back(f[k].node);
          }
      } else {
        // Between A and B only: the node on one side, its whole segment on the other.
        bool segment_on_a = true, segment_on_b = true;
        for (std::size_t k = begin + 1; k < end; ++k) {
          segment_on_a = segment_on_a && on(sensor.nodes_a, f[k].node);
          segment_on_b = segment_on_b && on(sensor.nodes_b, f[k].node);
        }
        const bool node_on_a = on(sensor.nodes_a, f[begin].node);
        const bool node_on_b = on(sensor.nodes_b, f[begin].node);
        int node_side = -1;
        if (node_on_a && segment_on_b)
          node_side = 0;
        else if (node_on_b && segment_on_a)
          node_side = 1;
        if (node_side < 0) {
          begin = end;
          continue;
        }
        add(node_side, f[begin]);
        if (node_side == 0) touched.push_back(f[begin].node);
        for (std::size_t k = begin + 1; k < end; ++k) {
          add(1 - node_side, f[k]);
          if (node_side == 1) touched.push_back(f[k].node);
        }
      }
      begin = end;
    }
  }
  if (comm.size() > 1) {
    const std::vector<double> everyone = timed(exchange_seconds, [&] {
      return comm.all_gather_varying(std::vector<double>(touched.begin(), touched.end()));
    });
    touched.clear();
    for (const double n : everyone)
      if (s.ownership.owned_now(static_cast<Index>(n))) touched.push_back(static_cast<Index>(n));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (const Index n : touched)
    sums.mass.add(s.nodes.mass[static_cast<std::size_t>(n)]);
  sums.store(t, comm, exchange_seconds);
}

}  // namespace mcdyna::solver::contact
