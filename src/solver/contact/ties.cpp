// Tied contacts: finding each slave node's master point (compile time) and the block that keeps
// it there (contact/ties.hpp).
#include "solver/contact/ties.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/block.hpp"
#include "solver/contact/segment_geometry.hpp"

namespace mcdyna::solver {

namespace contact {

TieResult tie_nodes(State& s, const std::vector<Index>& nodes, const Surface& surface,
                    const std::vector<double>& tolerance) {
  TieResult r;
  Nodes& nd = s.nodes;
  // Each segment's box widened by its tolerance, to skip the far ones quickly.
  const std::size_t count = surface.segments.size();
  std::vector<Vec3> low(count), high(count);
  for (std::size_t j = 0; j < count; ++j) {
    low[j] = high[j] = nd.position.col(surface.segments[j][0]);
    for (const Index n : surface.segments[j]) {
      low[j] = low[j].cwiseMin(Vec3(nd.position.col(n)));
      high[j] = high[j].cwiseMax(Vec3(nd.position.col(n)));
    }
    low[j].array() -= tolerance[j];
    high[j].array() += tolerance[j];
  }
  for (const Index node : nodes) {
    const Vec3 x = nd.position.col(node);
    double nearest = std::numeric_limits<double>::infinity();
    Tie best;
    Vec3 point = x;
    for (std::size_t j = 0; j < count; ++j) {
      if ((x.array() < low[j].array()).any() || (x.array() > high[j].array()).any()) continue;
      const std::array<Index, 4>& seg = surface.segments[j];
      if (std::find(seg.begin(), seg.end(), node) != seg.end()) continue;
      std::array<Vec3, 4> corners;
      for (std::size_t k = 0; k < 4; ++k)
        corners[k] = nd.position.col(seg[k]);
      const SegmentPoint at = closest_on_segment(x, corners);
      const double distance = (x - at.point).norm();
      if (distance > tolerance[j] || distance >= nearest) continue;
      nearest = distance;
      best.slave = node;
      best.masters = seg;
      best.weights = at.weights;
      point = at.point;
    }
    if (!std::isfinite(nearest)) {
      r.untied.push_back(node);
      continue;
    }
    if (nearest > r.farthest) {
      r.farthest = nearest;
      r.farthest_node = node;
    }
    nd.position.col(node) = point;
    nd.initial.col(node) = point;
    r.ties.push_back(best);
  }
  return r;
}

}  // namespace contact

namespace {

// The ties as one block at the end of the loop: after every force, a slave node's force goes to
// its master corners (forces); after the free velocity update the corners' velocities are put
// right for the slaves' mass they carry, v += dt F (1 / (m + M) - 1 / m) with M = sum w m_slave
// (advance_velocities); once every condition has acted, the slaves take the weighted mean of
// their corners' velocities (after_constraints). The slaves then move exactly with the surface:
// x_s = sum w x_i stays true step after step.
class TieBlock final : public Block {
 public:
  explicit TieBlock(std::vector<Tie> ties) : ties_(std::move(ties)) {
    for (const Tie& t : ties_)
      for (std::size_t k = 0; k < 4; ++k)
        if (t.weights[k] != 0.0) masters_.push_back(t.masters[k]);
    std::sort(masters_.begin(), masters_.end());
    masters_.erase(std::unique(masters_.begin(), masters_.end()), masters_.end());
    carried_.assign(masters_.size(), 0.0);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::contact; }
  [[nodiscard]] const std::vector<Tie>& ties() const { return ties_; }
  // A tie moves force and mass between nodes any process may own.
  [[nodiscard]] std::string one_process_only() const override {
    return "tied contacts (*CONTACT_TIED_...)";
  }

  // The initial velocities made to agree with the ties, momentum kept: each corner takes the
  // mean of its own and its slaves' momenta over their masses, (m v + sum w m_s v_s) / (m + M),
  // and the slaves the weighted mean of their corners'.
  void initialise(State& s) override {
    Nodes& nd = s.nodes;
    carry_masses(nd, ties_);
    std::vector<Vec3> momentum(masters_.size(), Vec3::Zero());
    for (const Tie& tie : ties_) {
      const auto i = static_cast<std::size_t>(tie.slave);
      const double m = nd.mass[i] + nd.added_mass[i];
      for (std::size_t k = 0; k < 4; ++k)
        if (tie.weights[k] != 0.0)
          momentum[slot(tie.masters[k])] += tie.weights[k] * m * nd.velocity.col(tie.slave);
    }
    for (std::size_t j = 0; j < masters_.size(); ++j) {
      const Index n = masters_[j];
      const auto i = static_cast<std::size_t>(n);
      const double m = nd.mass[i] + nd.added_mass[i];
      if (m + carried_[j] > 0.0)
        nd.velocity.col(n) = (m * nd.velocity.col(n) + momentum[j]) / (m + carried_[j]);
    }
    after_constraints(s);
  }

  void forces(State& /*s*/, NodalForces& forces, ForceReport& /*report*/) override {
    for (const Tie& t : ties_) {
      const Vec3 f = forces.force.col(t.slave);
      for (std::size_t k = 0; k < 4; ++k)
        if (t.weights[k] != 0.0) forces.force.col(t.masters[k]) += t.weights[k] * f;
      forces.force.col(t.slave).setZero();
    }
  }

  Index advance_velocities(State& s, const NodalForces& f, const StepTimes& t) override {
    Nodes& nd = s.nodes;
    carry_masses(nd, ties_);
    for (std::size_t j = 0; j < masters_.size(); ++j) {
      const Index n = masters_[j];
      const auto i = static_cast<std::size_t>(n);
      const double m = nd.mass[i] + nd.added_mass[i];
      if (!(m > 0.0)) continue;
      nd.velocity.col(n) += t.mean * (1.0 / (m + carried_[j]) - 1.0 / m) * f.force.col(n);
    }
    return -1;
  }

  void after_constraints(State& s) override {
    Nodes& nd = s.nodes;
    for (const Tie& t : ties_) {
      Vec3 v = Vec3::Zero();
      for (std::size_t k = 0; k < 4; ++k)
        v += t.weights[k] * nd.velocity.col(t.masters[k]);
      nd.velocity.col(t.slave) = v;
    }
  }

 private:
  // M = sum w m_slave per master corner, with the masses of now (DT2MS adds to them).
  void carry_masses(const Nodes& nd, const std::vector<Tie>& ties) {
    std::fill(carried_.begin(), carried_.end(), 0.0);
    for (const Tie& tie : ties) {
      const auto i = static_cast<std::size_t>(tie.slave);
      const double m = nd.mass[i] + nd.added_mass[i];
      for (std::size_t k = 0; k < 4; ++k)
        if (tie.weights[k] != 0.0) carried_[slot(tie.masters[k])] += tie.weights[k] * m;
    }
  }
  [[nodiscard]] std::size_t slot(Index master) const {
    return static_cast<std::size_t>(std::lower_bound(masters_.begin(), masters_.end(), master) -
                                    masters_.begin());
  }
  std::vector<Tie> ties_;       ///< by slave node (deck data: nothing to dump)
  std::vector<Index> masters_;  ///< every master corner with a weight, ascending
  std::vector<double> carried_;
};

}  // namespace

namespace contact {

std::unique_ptr<Block> make_tie_block(std::vector<Tie> ties) {
  return std::make_unique<TieBlock>(std::move(ties));
}

const std::vector<Tie>& ties_of(const State& s) {
  return owned_by(s, &TieBlock::ties);
}

}  // namespace contact

}  // namespace mcdyna::solver
