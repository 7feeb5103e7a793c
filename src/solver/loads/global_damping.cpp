// *DAMPING_GLOBAL as one block of the time loop: a force -D m v on every deformable node (and a
// moment -D I w on the rotations of shell nodes), and -D M v, -D J w on every rigid body, scaled
// per direction (STX..SRZ), D the constant VALDMP or its curve at t. The force takes the
// velocities v^{n-1/2} the cycle starts from (explicit; stable while D dt < 2). Its work, taken
// out of the structure, is glstat's damping energy.
#include "core/exact_sum.hpp"
#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"
#include "solver/loads/load_state.hpp"

namespace mcdyna::solver {

namespace {

// Returns the work the damping took out over the step just taken.
double apply_global_damping(State& s, const GlobalDampingState& g, NodalForces& forces) {
  const double d = g.curve >= 0 ? s.curves[static_cast<std::size_t>(g.curve)](s.time) : g.value;
  if (d == 0.0) return 0.0;
  const Nodes& nd = s.nodes;
  const bool rotations = nd.rotates();
  core::ExactSum taken;
  const std::size_t count = s.ownership.moved_count(nd.count());
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = s.ownership.moved_node(k);
    const auto i = static_cast<std::size_t>(n);
    if (nd.rigid_body[i] >= 0) continue;
    double power = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double f = -g.scale[static_cast<std::size_t>(a)] * d * nd.mass[i] * nd.velocity(a, n);
      forces.force(a, n) += f;
      power += f * nd.velocity(a, n);
      if (rotations && nd.rotary_inertia[i] > 0.0) {
        const double m = -g.scale[static_cast<std::size_t>(3 + a)] * d * nd.rotary_inertia[i] *
                         nd.angular_velocity(a, n);
        forces.moment(a, n) += m;
        power += m * nd.angular_velocity(a, n);
      }
    }
    if (s.ownership.owns_node(n)) taken.add(-power * s.step);
  }
  for (RigidBody& b : s.rigid_bodies) {
    if (b.released) continue;
    const Vec3 w = b.inertia() * b.omega;
    for (int a = 0; a < 3; ++a) {
      const double f = -g.scale[static_cast<std::size_t>(a)] * d * b.mass * b.velocity[a];
      const double m = -g.scale[static_cast<std::size_t>(3 + a)] * d * w[a];
      b.load_force[a] += f;
      b.load_moment[a] += m;
      if (s.ownership.comm.rank() == 0) taken.add(-(f * b.velocity[a] + m * b.omega[a]) * s.step);
    }
  }
  return s.ownership.comm.sum(std::vector<core::ExactSum>{taken})[0];
}

// Owns the compiled *DAMPING_GLOBAL and the work it has taken (glstat's damping energy).
class GlobalDampingBlock final : public DumpedBlock<GlobalDampingBlock> {
 public:
  explicit GlobalDampingBlock(GlobalDampingState damping) : damping_(damping) {}
  [[nodiscard]] std::string dump_name() const override { return "global damping"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(std::array<std::size_t, 0>{});
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(work_);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::boundary; }
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    e.damping += work_;
  }
  void forces(State& s, NodalForces& f, ForceReport& /*report*/) override {
    work_ += apply_global_damping(s, damping_, f);
  }

 private:
  GlobalDampingState damping_;
  double work_ = 0.0;  ///< taken so far
};

}  // namespace

std::unique_ptr<Block> make_global_damping_block(GlobalDampingState damping) {
  return std::make_unique<GlobalDampingBlock>(damping);
}

}  // namespace mcdyna::solver
