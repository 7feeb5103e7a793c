// The rigid bodies as one block of the time loop: each body sums its nodes' forces, advances its
// velocities under constraints and prescribed motion and sets its nodes' velocities; after the
// other nodes have moved it advances its centre and orientation and places its nodes. Over
// several processes every process advances every body (a few numbers each) from the exact sum
// of its owned nodes' forces over the processes, and places all of the body's nodes.
#include "solver/block.hpp"
#include "solver/rigid/rigid_bodies.hpp"
#include "solver/rigid/rigid_dump.hpp"
#include "solver/rigid/welds.hpp"

namespace mcdyna::solver {

namespace {

double rigid_kinetic(const RigidBody& b) {
  return 0.5 * b.mass * b.previous_velocity.dot(b.velocity) +
         0.5 * b.previous_omega.dot(b.inertia() * b.omega);
}

// The rigid bodies are the State's (loads, joints, contact and walls act on them as on the
// nodes); the welds' failure state is the block's own.
class RigidBodiesBlock final : public DumpedBlock<RigidBodiesBlock> {
 public:
  explicit RigidBodiesBlock(std::vector<WeldState> welds) : welds_(std::move(welds)) {}
  [[nodiscard]] const std::vector<WeldState>& welds() const { return welds_; }
  [[nodiscard]] std::string dump_name() const override { return "rigid bodies"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kRigidDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& s) {
    ar(s.rigid_bodies, welds_);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::rigid; }
  Index advance_velocities(State& s, const NodalForces& f, const StepTimes& t) override {
    const Index bad = advance_rigid_bodies(s, f, t);
    if (!welds_.empty()) check_welds(s, welds_, f.force, t);
    return bad;
  }
  void advance_positions(State& s, double dt) override { place_rigid_nodes(s, dt); }

  void add_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    for (const RigidBody& b : s.rigid_bodies) {
      if (b.released) continue;  // a failed weld: its nodes count as nodes
      e.kinetic += rigid_kinetic(b);
      e.external_work += b.constraint_work;
      e.momentum += b.mass * 0.5 * (b.velocity + b.previous_velocity);
      e.mass += b.mass;
    }
  }

  // bndout: the constraint force, moment and work of each body whose motion is prescribed or
  // fixed.
  void add_history_records(const State& s, HistoryRecords& out) const override {
    for (const RigidBody& b : s.rigid_bodies) {
      if (b.motions.empty() && b.fixed_translation == std::array<bool, 3>{} &&
          b.fixed_rotation == std::array<bool, 3>{})
        continue;
      out.boundaries.push_back({BoundaryRecord::Kind::rigid_part, b.part_id, b.constraint_force,
                                b.constraint_moment, b.constraint_work});
    }
  }

  void add_part_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                         std::vector<PartSummary>& parts) const override {
    for (std::size_t p = 0; p < s.parts.size(); ++p) {
      const Index b = s.parts[p].rigid_body;
      if (b < 0) continue;
      const RigidBody& body = s.rigid_bodies[static_cast<std::size_t>(b)];
      const Vec3 v = 0.5 * (body.velocity + body.previous_velocity);
      parts[p].kinetic = rigid_kinetic(body);
      parts[p].momentum = body.mass * v;
      parts[p].mass = body.mass;
      parts[p].rigid_velocity = v;
    }
  }

  // The rigid parts' elements, drawn: solids, then shells, with no stress.
  void write_state(const State& s, StateSink& sink) const override {
    const DisplayCells& rc = s.rigid_cells;
    auto part = [&](Index p) { return s.parts[static_cast<std::size_t>(p)].id; };
    for (std::size_t k = 0; k < rc.solids.size(); ++k) {
      CellValues v;
      v.part = part(rc.solid_parts[k]);
      v.id = rc.solid_ids[k];
      sink.cell(CellShape::hexahedron, rc.solids[k].data(), v);
    }
    for (std::size_t k = 0; k < rc.shells.size(); ++k) {
      const auto& q = rc.shells[k];
      CellValues v;
      v.part = part(rc.shell_parts[k]);
      v.id = rc.shell_ids[k];
      sink.cell(q[3] == q[2] ? CellShape::triangle : CellShape::quadrilateral, q.data(), v);
    }
  }

 private:
  std::vector<WeldState> welds_;
};

}  // namespace

std::unique_ptr<Block> make_rigid_bodies_block(std::vector<WeldState> welds) {
  return std::make_unique<RigidBodiesBlock>(std::move(welds));
}

const std::vector<WeldState>& welds_of(const State& s) {
  return owned_by(s, &RigidBodiesBlock::welds);
}

}  // namespace mcdyna::solver
