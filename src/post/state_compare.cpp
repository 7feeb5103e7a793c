#include "post/state_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

namespace mcdyna::post {

namespace {

using io::d3plot::Elements;
using io::d3plot::Reader;
using io::d3plot::StateData;

struct Sum {
  double max = 0.0, time = 0.0, squares = 0.0, peak = 0.0;
  std::size_t n = 0;
};

class Sums {
 public:
  void add(std::int64_t part, const char* field, double difference, double b, double time) {
    Sum& s = sums_[{part, field}];
    if (s.n == 0 || difference > s.max) {
      s.max = difference;
      s.time = time;
    }
    s.squares += difference * difference;
    s.peak = std::max(s.peak, std::abs(b));
    ++s.n;
  }
  [[nodiscard]] std::vector<StateFieldDifference> rows() const {
    std::vector<StateFieldDifference> out;
    for (const auto& [key, s] : sums_)
      out.push_back({key.first, key.second, s.max, s.time,
                     std::sqrt(s.squares / static_cast<double>(s.n)), s.peak, s.n});
    return out;
  }

 private:
  std::map<std::pair<std::int64_t, std::string>, Sum> sums_;
};

// Index of each ID in `ids`.
std::unordered_map<std::int64_t, std::size_t> index_of(const std::vector<std::int64_t>& ids) {
  std::unordered_map<std::int64_t, std::size_t> out;
  for (std::size_t k = 0; k < ids.size(); ++k)
    out.emplace(ids[k], k);
  return out;
}

// The pairs (index in A, index in B) of the IDs both lists hold; counts the others.
std::vector<std::pair<std::size_t, std::size_t>> pairs(const std::vector<std::int64_t>& a,
                                                       const std::vector<std::int64_t>& b,
                                                       std::size_t& only_a, std::size_t& only_b) {
  const auto in_b = index_of(b);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const auto it = in_b.find(a[k]);
    if (it == in_b.end()) {
      ++only_a;
    } else {
      out.emplace_back(k, it->second);
    }
  }
  only_b += b.size() - out.size();
  return out;
}

// The part of each node: that of the first element or particle on it (0: none).
std::vector<std::int64_t> node_parts(const Reader& r) {
  std::vector<std::int64_t> part(r.node_ids().size(), 0);
  for (const Elements* e : {&r.solids(), &r.shells(), &r.beams(), &r.particles()})
    for (std::size_t k = 0; k < e->count(); ++k)
      for (int c = 0; c < e->corners; ++c) {
        const auto n = static_cast<std::size_t>(
            e->nodes[k * static_cast<std::size_t>(e->corners) + static_cast<std::size_t>(c)]);
        if (n < part.size() && part[n] == 0) part[n] = e->parts[k];
      }
  return part;
}

// Where each element's words start in its class's state array (rigid shells have none: -1).
std::vector<std::int64_t> word_starts(const Elements& e, std::int64_t words) {
  std::vector<std::int64_t> at(e.count(), -1);
  std::int64_t next = 0;
  for (std::size_t k = 0; k < e.count(); ++k)
    if (e.rigid.empty() || !e.rigid[k]) {
      at[k] = next;
      next += words;
    }
  return at;
}

// An element class's stress (6 words at `stress`, or -1) and plastic strain (at `strain`, or
// -1) compared element by element.
struct ClassLayout {
  const char* stress_name = "stress";
  std::int64_t words = 0, stress = -1, strain = -1;
};

void compare_class(const char* element_class, const Elements& ea, const Elements& eb,
                   const ClassLayout& la, const ClassLayout& lb, const std::vector<double>& wa,
                   const std::vector<double>& wb, const std::vector<std::uint8_t>& deleted_a,
                   const std::vector<std::uint8_t>& deleted_b,
                   const std::vector<std::pair<std::size_t, std::size_t>>& matched, double time,
                   Sums& sums, DifferenceSink* sink) {
  const std::vector<std::int64_t> at_a = word_starts(ea, la.words),
                                  at_b = word_starts(eb, lb.words);
  for (const auto& [i, j] : matched) {
    if ((i < deleted_a.size() && deleted_a[i]) || (j < deleted_b.size() && deleted_b[j])) continue;
    if (at_a[i] < 0 || at_b[j] < 0) continue;
    const auto pa = static_cast<std::size_t>(at_a[i]), pb = static_cast<std::size_t>(at_b[j]);
    if (la.stress >= 0 && lb.stress >= 0) {
      double d = 0.0, b = 0.0, diff[6];
      for (std::size_t c = 0; c < 6; ++c) {
        const double va = wa[pa + static_cast<std::size_t>(la.stress) + c];
        const double vb = wb[pb + static_cast<std::size_t>(lb.stress) + c];
        diff[c] = va - vb;
        d = std::max(d, std::abs(va - vb));
        b = std::max(b, std::abs(vb));
      }
      sums.add(eb.parts[j], la.stress_name, d, b, time);
      if (sink) sink->element(element_class, j, la.stress_name, diff, 6);
    }
    if (la.strain >= 0 && lb.strain >= 0) {
      const double va = wa[pa + static_cast<std::size_t>(la.strain)];
      const double vb = wb[pb + static_cast<std::size_t>(lb.strain)];
      sums.add(eb.parts[j], "plastic_strain", std::abs(va - vb), vb, time);
      const double diff = va - vb;
      if (sink) sink->element(element_class, j, "plastic_strain", &diff, 1);
    }
  }
}

ClassLayout solid_layout(const io::d3plot::Control& c) {
  return {"stress", c.nv3d, c.nv3d >= 6 ? 0 : -1, c.nv3d >= 7 ? 6 : -1};
}
ClassLayout shell_layout(const io::d3plot::Control& c) {
  return {"stress", c.nv2d, c.nv2d >= 6 ? 0 : -1, c.nv2d >= 7 ? 6 : -1};
}
ClassLayout beam_layout(const io::d3plot::Control& c) {
  return {"resultants", c.nv1d, c.nv1d >= 6 ? 0 : -1, -1};
}
// The SPH words: the material word, then as the flags say: radius, pressure, stress (6),
// plastic strain, ...
ClassLayout particle_layout(const io::d3plot::Control& c) {
  ClassLayout l{"stress", c.sph_words, -1, -1};
  const auto& f = c.sph_flags;
  if (f.size() < 4) return l;
  const std::int64_t stress = 1 + f[0] + f[1];
  if (f[2] == 6) l.stress = stress;
  if (f[3] == 1) l.strain = stress + f[2];
  return l;
}

}  // namespace

StateComparison compare_states(const Reader& a, const Reader& b, double time_tolerance,
                               DifferenceSink* sink) {
  StateComparison out;
  out.states_a = a.states();
  out.states_b = b.states();
  std::vector<double> times_b;
  for (std::size_t k = 0; k < b.states(); ++k)
    times_b.push_back(b.time(k));
  double tolerance = time_tolerance;
  if (tolerance < 0.0) {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j < times_b.size(); ++j)
      if (times_b[j] > times_b[j - 1]) shortest = std::min(shortest, times_b[j] - times_b[j - 1]);
    tolerance = std::isfinite(shortest) ? 0.5 * shortest : 0.0;
  }
  std::vector<std::pair<std::size_t, std::size_t>> states;
  for (std::size_t k = 0; k < a.states(); ++k) {
    const double t = a.time(k);
    std::size_t best = 0;
    for (std::size_t j = 1; j < times_b.size(); ++j)
      if (std::abs(times_b[j] - t) < std::abs(times_b[best] - t)) best = j;
    if (!times_b.empty() && std::abs(times_b[best] - t) <= tolerance) {
      states.emplace_back(k, best);
      out.matched.emplace_back(t, times_b[best]);
      out.largest_offset = std::max(out.largest_offset, std::abs(times_b[best] - t));
    }
  }
  const auto nodes = pairs(a.node_ids(), b.node_ids(), out.only_a, out.only_b);
  out.nodes = nodes.size();
  const auto solids = pairs(a.solids().ids, b.solids().ids, out.only_a, out.only_b);
  const auto shells = pairs(a.shells().ids, b.shells().ids, out.only_a, out.only_b);
  const auto beams = pairs(a.beams().ids, b.beams().ids, out.only_a, out.only_b);
  const auto particles = pairs(a.particles().ids, b.particles().ids, out.only_a, out.only_b);
  out.elements = solids.size() + shells.size() + beams.size() + particles.size();
  const std::vector<std::int64_t> part_of = node_parts(b);
  Sums sums;
  for (const auto& [ka, kb] : states) {
    const StateData sa = a.state(ka), sb = b.state(kb);
    if (sink) sink->begin_state(sb.time, sb.x.empty() ? b.initial() : sb.x);
    auto vectors = [&](const std::vector<double>& va, const std::vector<double>& vb,
                       const std::vector<double>* origin_a, const std::vector<double>* origin_b,
                       const char* field) {
      if (va.empty() || vb.empty()) return;
      for (const auto& [i, j] : nodes) {
        double d2 = 0.0, b2 = 0.0, diff[3];
        for (std::size_t c = 0; c < 3; ++c) {
          const double xa = va[3 * i + c] - (origin_a ? (*origin_a)[3 * i + c] : 0.0);
          const double xb = vb[3 * j + c] - (origin_b ? (*origin_b)[3 * j + c] : 0.0);
          diff[c] = xa - xb;
          d2 += (xa - xb) * (xa - xb);
          b2 += xb * xb;
        }
        sums.add(part_of[j], field, std::sqrt(d2), std::sqrt(b2), sb.time);
        if (sink) sink->node(j, field, diff);
      }
    };
    vectors(sa.x, sb.x, &a.initial(), &b.initial(), "displacement");
    vectors(sa.v, sb.v, nullptr, nullptr, "velocity");
    const io::d3plot::Control &ca = a.control(), &cb = b.control();
    compare_class("solid", a.solids(), b.solids(), solid_layout(ca), solid_layout(cb), sa.solids,
                  sb.solids, sa.solid_deleted, sb.solid_deleted, solids, sb.time, sums, sink);
    compare_class("shell", a.shells(), b.shells(), shell_layout(ca), shell_layout(cb), sa.shells,
                  sb.shells, sa.shell_deleted, sb.shell_deleted, shells, sb.time, sums, sink);
    compare_class("beam", a.beams(), b.beams(), beam_layout(ca), beam_layout(cb), sa.beams,
                  sb.beams, sa.beam_deleted, sb.beam_deleted, beams, sb.time, sums, sink);
    compare_class("particle", a.particles(), b.particles(), particle_layout(ca),
                  particle_layout(cb), sa.particles, sb.particles, {}, {}, particles, sb.time, sums,
                  sink);
    if (sink) sink->end_state();
  }
  out.rows = sums.rows();
  return out;
}

}  // namespace mcdyna::post
