// The planar rigid walls as one formulation: its compile pass makes one block that owns the walls
// (planar_wall.hpp). In the constraint phase, after the prescribed motions, each tracked node the
// coming step would carry through a wall lands on it (loads.hpp land_on_wall, shared with the
// geometric walls); a moving wall takes the opposite impulse.
#include <algorithm>

#include "core/exact_sum.hpp"
#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/loads/loads.hpp"
#include "solver/walls/planar_wall.hpp"
#include "solver/walls/walls_block.hpp"

namespace mcdyna::solver {

// The dump reads the member list by argument-dependent lookup.
namespace walls {
template <class Ar>
void fields(Ar& ar, PlanarWall& w) {
  ar(w.id, w.point, w.normal, w.finite, w.edge_l, w.edge_m, w.length_l, w.length_m, w.friction,
     w.birth, w.death, w.switched_off, w.moving, w.mass, w.velocity, w.displacement, w.nodes,
     w.force, w.energy);
}
}  // namespace walls

namespace {

using walls::PlanarWall;

inline constexpr auto kPlanarWallDumpedSizes = core::sizes_of<PlanarWall>();
static_assert(!core::kSizesPinned ||
                  kPlanarWallDumpedSizes == decltype(kPlanarWallDumpedSizes){240},
              "walls::PlanarWall changed: list the new member in fields() above");

// Stonewall (constraint method): nodes that would cross the wall during the coming step get the
// normal velocity that puts them on it; Coulomb friction limits the tangential impulse.
void apply_walls(State& state, std::vector<PlanarWall>& walls, const StepTimes& t) {
  Nodes& nd = state.nodes;
  const parallel::Ownership& own = state.ownership;
  for (PlanarWall& w : walls) {
    const bool on = !w.switched_off && t.time >= w.birth && t.time <= w.death;
    // Wall plane at the end of the step (a moving wall advances along its normal).
    const Vec3 point_next = w.point + (w.displacement + w.velocity * t.step) * w.normal;
    // The wall's force, the work it absorbs and the impulse it takes, summed exactly: each node
    // on the process that owns it, then over the processes (the same bits for any count).
    enum { kForceX, kForceY, kForceZ, kWork, kImpulse, kSums };
    std::vector<core::ExactSum> sums(kSums);
    for (const Index n : w.nodes) {
      if (!on) break;
      if (!own.moves_node(n)) continue;  // another process moves it
      const Vec3 x = nd.position.col(n);
      Vec3 v = nd.velocity.col(n);
      const double gap = (x + t.step * v - point_next).dot(w.normal);
      if (gap >= 0.0) continue;
      if (w.finite) {
        const Vec3 r = x - w.point - w.displacement * w.normal;
        const double a = r.dot(w.edge_l), b = r.dot(w.edge_m);
        if ((w.length_l > 0.0 && (a < 0.0 || a > w.length_l)) ||
            (w.length_m > 0.0 && (b < 0.0 || b > w.length_m)))
          continue;
      }
      const double m = nodal_mass(nd, n);
      // The wall moves along its normal only: no velocity of its own across it.
      const WallLanding l = land_on_wall(nd, n, t, gap, w.normal, Vec3::Zero(), w.friction);
      if (!own.owns_node(n)) continue;  // a replicated node counts on its owner only
      const Vec3 f = -m * l.change / t.mean;
      for (int k = 0; k < 3; ++k)
        sums[static_cast<std::size_t>(kForceX + k)].add(f[k]);
      sums[kImpulse].add(m * l.normal_change);
      sums[kWork].add(impulse_work(m * l.change, l.start, l.end));
    }
    const std::vector<double> total = own.comm.sum(sums);
    w.force = Vec3(total[kForceX], total[kForceY], total[kForceZ]);
    w.energy -= total[kWork];
    const double wall_impulse = total[kImpulse];
    if (w.moving) {
      // The wall takes the opposite normal impulse (momentum is exchanged, not created).
      w.velocity -= wall_impulse / w.mass;
      w.displacement += w.velocity * t.step;
    }
  }
}

class PlanarWallsBlock final : public walls::WallsBlock<PlanarWall, PlanarWallsBlock> {
 public:
  using WallsBlock::WallsBlock;
  void constrain(State& s, const StepTimes& t) override { apply_walls(s, walls_, t); }
  // The force on the wall along its normal is minus the structure's push: positive in contact.
  void add_history_records(const State& /*s*/, HistoryRecords& out) const override {
    for (const PlanarWall& w : walls_)
      out.walls.push_back({w.id, -w.force.dot(w.normal), w.force, w.energy});
  }
  [[nodiscard]] std::string dump_name() const override { return "rigid walls"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kPlanarWallDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(walls_);
  }
};

}  // namespace

const std::vector<walls::PlanarWall>& walls::planar_walls_of(const State& s) {
  return owned_by(s, &PlanarWallsBlock::walls);
}

namespace detail {

void compile_planar_walls(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                          Blocks& own, core::Diagnostics& d) {
  std::vector<PlanarWall> walls;
  for (const model::RigidWall& w : m.rigid_walls) {
    if (w.shape != model::WallShape::planar) continue;  // geometric walls: walls/
    PlanarWall rw;
    rw.id = w.id != 0 ? w.id : static_cast<model::Id>(walls.size() + 1);
    rw.point = Vec3(w.tail[0], w.tail[1], w.tail[2]);
    const Vec3 n = Vec3(w.head[0], w.head[1], w.head[2]) - rw.point;
    if (!(n.norm() > 0.0)) {
      d.error(w.loc, "*RIGIDWALL_PLANAR: the normal (head - tail) has zero length");
      continue;
    }
    rw.normal = n.normalized();
    if (w.friction >= 2.0) {
      d.error(w.loc, "*RIGIDWALL_PLANAR: FRIC = {} (welding) is not supported", w.friction);
    }
    rw.friction = w.friction;
    rw.birth = w.birth;
    rw.death = w.death == 0.0 ? 1.0e20 : w.death;
    if (w.finite) {
      rw.finite = true;
      const Vec3 l = Vec3(w.edge_head[0], w.edge_head[1], w.edge_head[2]) - rw.point;
      const Vec3 lp = l - l.dot(rw.normal) * rw.normal;
      if (!(lp.norm() > 0.0)) {
        d.error(w.loc, "*RIGIDWALL_PLANAR_FINITE: edge vector l is parallel to the normal");
        continue;
      }
      rw.edge_l = lp.normalized();
      rw.edge_m = rw.normal.cross(rw.edge_l);
      rw.length_l = w.length_l;
      rw.length_m = w.length_m;
    }
    if (w.moving) {
      rw.moving = true;
      rw.mass = w.mass;
      rw.velocity = w.initial_velocity;
      if (!(w.mass > 0.0)) d.error(w.loc, "*RIGIDWALL_PLANAR_MOVING: MASS must be > 0");
    }
    rw.nodes = wall_nodes(m, s, w, rw.point, rw.normal);
    walls.push_back(std::move(rw));
  }
  if (!walls.empty()) own.push_back(std::make_unique<PlanarWallsBlock>(std::move(walls)));
}

}  // namespace detail

}  // namespace mcdyna::solver
