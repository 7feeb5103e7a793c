// The geometric rigid walls as one formulation: its compile pass makes one block that owns the
// walls (geometric_wall.hpp). In the constraint phase, after the planar walls, each tracked node
// the coming step would carry into a wall lands on it (loads.hpp land_on_wall: the planar
// walls' constraint method, with friction relative to the wall's own velocity).
#include <fmt/format.h>

#include <algorithm>

#include "core/exact_sum.hpp"
#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/loads/loads.hpp"
#include "solver/walls/geometric_wall.hpp"
#include "solver/walls/walls_block.hpp"

namespace mcdyna::solver {

namespace {

using walls::GeometricWall;

inline constexpr auto kWallDumpedSizes = core::sizes_of<GeometricWall>();
static_assert(!core::kSizesPinned || kWallDumpedSizes == decltype(kWallDumpedSizes){328},
              "walls::GeometricWall changed: list what changes in a run in dumped() below, or "
              "leave it out as deck data");

// The wall's displacement at the end of the step and its velocity over it (_MOTION; the curve
// is read at t - BIRTH, a velocity at the middle of the step).
std::pair<Vec3, Vec3> wall_motion(const State& s, const GeometricWall& w, const StepTimes& t) {
  if (w.motion_curve < 0 || t.time < w.birth) return {w.displacement, Vec3::Zero()};
  const LoadCurve& curve = s.curves[static_cast<std::size_t>(w.motion_curve)];
  const double tau = t.time - w.birth;
  if (w.motion_is_displacement) {
    const Vec3 next = curve(tau + t.step) * w.motion_direction;
    return {next, (next - w.displacement) / t.step};
  }
  const Vec3 velocity = curve(tau + 0.5 * t.step) * w.motion_direction;
  return {w.displacement + t.step * velocity, velocity};
}

// The wall's constraint over one step: the tracked nodes it lands, its force and work summed
// exactly over the processes (each node on its owner), as the planar walls do.
void apply_wall(State& s, GeometricWall& w, const StepTimes& t) {
  Nodes& nd = s.nodes;
  const parallel::Ownership& own = s.ownership;
  const auto [next, wall_velocity] = wall_motion(s, w, t);
  enum { kForceX, kForceY, kForceZ, kNormal, kWork, kSums };
  std::vector<core::ExactSum> sums(kSums);
  if (!w.switched_off && t.time >= w.birth && t.time <= w.death) {
    for (const Index n : w.nodes) {
      if (!own.moves_node(n)) continue;  // another process moves it
      const Vec3 predicted = nd.position.col(n) + t.step * Vec3(nd.velocity.col(n));
      const walls::Penetration p = walls::penetration(w, next, predicted);
      if (!p.inside) continue;
      const WallLanding l = land_on_wall(nd, n, t, p.gap, p.normal, wall_velocity, w.friction);
      if (!own.owns_node(n)) continue;  // a replicated node counts on its owner only
      const double m = nodal_mass(nd, n);
      const Vec3 f = -m * l.change / t.mean;
      for (int k = 0; k < 3; ++k)
        sums[static_cast<std::size_t>(kForceX + k)].add(f[k]);
      sums[kNormal].add(-f.dot(p.normal));
      sums[kWork].add(impulse_work(m * l.change, l.start, l.end));
    }
  }
  const std::vector<double> total = own.comm.sum(sums);
  w.force = Vec3(total[kForceX], total[kForceY], total[kForceZ]);
  w.normal_force = total[kNormal];
  w.energy -= total[kWork];
  w.displacement = next;
  w.velocity = wall_velocity;
}

class GeometricWallsBlock final : public walls::WallsBlock<GeometricWall, GeometricWallsBlock> {
 public:
  using WallsBlock::WallsBlock;
  void constrain(State& s, const StepTimes& t) override {
    for (GeometricWall& w : walls_)
      apply_wall(s, w, t);
  }
  void add_history_records(const State& /*s*/, HistoryRecords& out) const override {
    for (const GeometricWall& w : walls_)
      out.walls.push_back({w.id, w.normal_force, w.force, w.energy});
  }
  [[nodiscard]] std::string dump_name() const override { return "geometric rigid walls"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kWallDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    for (GeometricWall& w : walls_)
      ar(w.displacement, w.velocity, w.force, w.normal_force, w.energy, w.switched_off);
  }
};

walls::Shape shape_of(model::WallShape s) {
  switch (s) {
    case model::WallShape::prism:
      return walls::Shape::prism;
    case model::WallShape::cylinder:
      return walls::Shape::cylinder;
    case model::WallShape::sphere:
      return walls::Shape::sphere;
    default:
      return walls::Shape::flat;
  }
}

// The shape's axes: the normal, and for a flat or prism wall the edges l (the edge vector made
// normal to n) and m = n x l. Returns false (reported) when they are degenerate.
bool set_axes(const model::RigidWall& mw, GeometricWall& w, core::Diagnostics& d) {
  const Vec3 head(mw.head[0], mw.head[1], mw.head[2]);
  const Vec3 n = head - w.point;
  if (!(n.norm() > 0.0)) return w.shape == walls::Shape::sphere;  // the builder said so
  w.normal = n.normalized();
  if (w.shape != walls::Shape::flat && w.shape != walls::Shape::prism) return true;
  const Vec3 l = Vec3(mw.edge_head[0], mw.edge_head[1], mw.edge_head[2]) - w.point;
  const Vec3 lp = l - l.dot(w.normal) * w.normal;
  if (!(lp.norm() > 0.0)) {
    if (w.shape == walls::Shape::flat && !mw.finite) return true;  // an infinite plane
    d.error(mw.loc,
            "*RIGIDWALL_GEOMETRIC: the edge vector l (XHEV YHEV ZHEV from the tail) is "
            "zero or along the normal");
    return false;
  }
  w.edge_l = lp.normalized();
  w.edge_m = w.normal.cross(w.edge_l);
  return true;
}

}  // namespace

namespace detail {

void compile_geometric_walls(const model::ModelDatabase& m, State& s,
                             const CompiledBlocks& /*before*/, Blocks& own, core::Diagnostics& d) {
  std::vector<GeometricWall> out;
  // Unnumbered walls are numbered after the planar ones, in deck order.
  const auto planar = std::count_if(m.rigid_walls.begin(), m.rigid_walls.end(), [](const auto& w) {
    return w.shape == model::WallShape::planar;
  });
  for (const model::RigidWall& mw : m.rigid_walls) {
    if (mw.shape == model::WallShape::planar) continue;
    GeometricWall w;
    w.id = mw.id != 0 ? mw.id : static_cast<model::Id>(planar + static_cast<long>(out.size()) + 1);
    w.shape = shape_of(mw.shape);
    w.point = Vec3(mw.tail[0], mw.tail[1], mw.tail[2]);
    if (!set_axes(mw, w, d)) continue;
    w.length_l = mw.length_l;
    w.length_m = mw.length_m;
    w.length_p = mw.length_p;
    w.radius = mw.radius;
    w.cylinder_length = mw.cylinder_length;
    w.friction = mw.friction;
    w.birth = mw.birth;
    w.death = mw.death == 0.0 ? 1.0e20 : mw.death;
    if (mw.motion_curve != 0) {
      w.motion_curve = curve_index(m, mw.motion_curve);
      w.motion_is_displacement = mw.motion_is_displacement;
      const Vec3 v(mw.motion_direction[0], mw.motion_direction[1], mw.motion_direction[2]);
      if (v.norm() > 0.0) w.motion_direction = v.normalized();
    }
    w.nodes = wall_nodes(m, s, mw, w.point, w.normal);
    out.push_back(std::move(w));
  }
  if (!out.empty()) own.push_back(std::make_unique<GeometricWallsBlock>(std::move(out)));
}

}  // namespace detail

}  // namespace mcdyna::solver
