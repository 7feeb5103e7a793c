// The point and pressure loads as one block of the time loop: *LOAD_NODE forces and moments on
// nodes, *LOAD_RIGID_BODY on bodies at their centres, *LOAD_SEGMENT pressure on segments (their
// current area and normal: a follower load), each SF x curve(t). Their work is the trapezoidal
// rule over each step, half the force at either end times x^{n+1} - x^n = dt v^{n+1/2}, charged
// when the next cycle's forces are known (as the contact's); it goes to glstat's external work.
//
// Every process applies every load; over several processes the loaded nodes are moved by every
// process (mark_replicated), and a rigid body sums its nodes on their owners.
#include "solver/block.hpp"
#include "solver/loads/loads_dump.hpp"

namespace mcdyna::solver {

namespace {

double value(const State& s, Index curve, double scale, double shift) {
  return scale * s.curves[static_cast<std::size_t>(curve)](s.time - shift);
}

// Adds to `work` what the loads did over the step just taken.
void apply_point_loads(State& s, std::vector<PointLoadState>& loads, NodalForces& f, double& work) {
  const Nodes& nd = s.nodes;
  for (PointLoadState& l : loads) {
    const double now = value(s, l.curve, l.scale, 0.0);
    // Work of last cycle's load and this one over the step just taken, at v^{n+1/2}.
    double speed = 0.0;
    if (l.body >= 0) {
      const RigidBody& b = s.rigid_bodies[static_cast<std::size_t>(l.body)];
      speed = l.moment ? b.omega[l.axis] : b.velocity[l.axis];
    }
    for (const Index n : l.nodes)
      speed += l.moment ? nd.angular_velocity(l.axis, n) : nd.velocity(l.axis, n);
    work += 0.5 * s.step * (l.last + now) * speed;
    l.last = now;
    if (l.body >= 0) {
      RigidBody& b = s.rigid_bodies[static_cast<std::size_t>(l.body)];
      (l.moment ? b.load_moment : b.load_force)[l.axis] += now;
    }
    for (const Index n : l.nodes)
      (l.moment ? f.moment : f.force)(l.axis, n) += now;
  }
}

void apply_pressure_loads(const State& s, std::vector<PressureLoadState>& loads,
                          Eigen::Matrix3Xd& force, double& work) {
  const Nodes& nd = s.nodes;
  for (PressureLoadState& l : loads) {
    const double p = s.time >= l.arrival ? value(s, l.curve, l.scale, l.arrival) : 0.0;
    for (std::size_t k = 0; k < l.segments.size(); ++k) {
      const std::array<Index, 4>& seg = l.segments[k];
      const bool triangle = seg[3] == seg[2];
      const int corners = triangle ? 3 : 4;
      auto x = [&](std::size_t c) { return Vec3(nd.position.col(seg[c])); };
      // Area times unit normal (right-hand rule over N1 N2 N3 N4).
      const Vec3 area = triangle ? Vec3(0.5 * (x(1) - x(0)).cross(x(2) - x(0)))
                                 : Vec3(0.5 * (x(2) - x(0)).cross(x(3) - x(1)));
      const Vec3 f = -p * area / corners;
      for (int c = 0; c < corners; ++c) {
        const Index n = seg[static_cast<std::size_t>(c)];
        const auto col = static_cast<Index>(4 * k + static_cast<std::size_t>(c));
        work += 0.5 * s.step * (Vec3(l.last.col(col)) + f).dot(nd.velocity.col(n));
        l.last.col(col) = f;
        force.col(n) += f;
      }
    }
  }
}

// Owns its loads and their work so far (glstat's external work).
class AppliedLoadsBlock final : public DumpedBlock<AppliedLoadsBlock> {
 public:
  AppliedLoadsBlock(std::vector<PointLoadState> points, std::vector<PressureLoadState> pressures)
      : points_(std::move(points)), pressures_(std::move(pressures)) {}
  [[nodiscard]] std::string dump_name() const override { return "applied loads"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kLoadDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(points_, pressures_, work_);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    for (const PointLoadState& l : points_)
      for (const Index n : l.nodes)
        nodes[static_cast<std::size_t>(n)] = 1;
    for (const PressureLoadState& l : pressures_)
      for (const auto& seg : l.segments)
        for (const Index n : seg)
          nodes[static_cast<std::size_t>(n)] = 1;
  }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    e.external_work += work_;
  }
  void forces(State& s, NodalForces& f, ForceReport& /*report*/) override {
    apply_point_loads(s, points_, f, work_);
    apply_pressure_loads(s, pressures_, f.force, work_);
  }

 private:
  std::vector<PointLoadState> points_;
  std::vector<PressureLoadState> pressures_;
  double work_ = 0.0;  ///< of the point and pressure loads so far
};

}  // namespace

std::unique_ptr<Block> make_applied_loads_block(std::vector<PointLoadState> points,
                                                std::vector<PressureLoadState> pressures) {
  return std::make_unique<AppliedLoadsBlock>(std::move(points), std::move(pressures));
}

}  // namespace mcdyna::solver
