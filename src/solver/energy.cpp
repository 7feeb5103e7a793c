#include "solver/energy.hpp"

#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver {

namespace {
double rigid_kinetic(const RigidBody& b) {
  return 0.5 * b.mass * b.previous_velocity.dot(b.velocity) +
         0.5 * b.previous_omega.dot(b.inertia() * b.omega);
}
}  // namespace

EnergySummary energy_summary(const State& s, const Eigen::Matrix3Xd& previous) {
  EnergySummary e;
  const Eigen::Matrix3Xd& velocity = s.nodes.velocity;
  const Solids& so = s.solids;
  for (std::size_t i = 0; i < so.ids.size(); ++i) {
    (so.eroded[i] ? e.eroded_internal : e.internal) += so.internal_energy[i];
    (so.eroded[i] ? e.eroded_hourglass : e.hourglass) += so.hourglass_energy[i];
  }
  const Shells& sh = s.shells;
  for (std::size_t i = 0; i < sh.ids.size(); ++i) {
    (sh.eroded[i] ? e.eroded_internal : e.internal) += sh.internal_energy[i];
    (sh.eroded[i] ? e.eroded_hourglass : e.hourglass) += sh.hourglass_energy[i];
  }
  const Beams& bm = s.beams;
  for (std::size_t i = 0; i < bm.ids.size(); ++i)
    (bm.eroded[i] ? e.eroded_internal : e.internal) += bm.internal_energy[i];
  for (const RigidWallState& w : s.rigid_walls)
    e.stonewall += w.energy;
  for (const contact::Interface& c : s.contacts)
    e.sliding += c.energy;
  for (const JointState& j : s.joints)
    e.internal += j.energy;
  for (const JointStiffnessState& j : s.joint_stiffnesses)
    e.internal += j.work;
  for (const NodalMotion& m : s.nodal_motions)
    e.external_work += m.work();
  e.external_work += s.load_work;
  e.damping += s.damping_work;
  for (const RigidBody& b : s.rigid_bodies) {
    if (b.released) continue;  // a failed weld: its nodes count as nodes
    e.kinetic += rigid_kinetic(b);
    e.external_work += b.constraint_work;
    e.momentum += b.mass * 0.5 * (b.velocity + b.previous_velocity);
    e.mass += b.mass;
  }
  for (const spg::Domain& d : s.spg) {
    for (std::size_t i = 0; i < d.fields.internal_energy.size(); ++i)
      e.internal += d.fields.internal_energy[i];
    e.damping += d.fields.damping_energy;
    for (const double w : d.fields.mode_energy)
      e.hourglass += w;
    const spg::SmoothedKinetic k = spg::smoothed_kinetic(s, d);
    e.kinetic += k.kinetic;
    e.momentum += k.momentum;
    e.mass += k.mass;
  }
  const Nodes& nd = s.nodes;
  for (Index n = 0; n < nd.count(); ++n) {
    const auto i = static_cast<std::size_t>(n);
    // MC-SPG particles count with their unsmoothed velocity and mass (above).
    if (nd.rigid_body[i] >= 0 || nd.smoothed[i] == 1) continue;
    e.kinetic += 0.5 * nd.mass[i] * previous.col(n).dot(velocity.col(n));
    e.momentum += 0.5 * nd.mass[i] * (previous.col(n) + velocity.col(n));
    e.mass += nd.mass[i];
    if (!nd.rotary_inertia.empty() && nd.rotary_inertia[i] > 0.0)
      e.kinetic += 0.5 * nd.rotary_inertia[i] *
                   nd.previous_angular_velocity.col(n).dot(nd.angular_velocity.col(n));
  }
  e.added_mass = total_added_mass(s);
  e.total = e.kinetic + e.internal + e.hourglass + e.stonewall + e.sliding + e.damping +
            e.eroded_internal + e.eroded_hourglass;
  return e;
}

double total_added_mass(const State& s) {
  double added = 0.0;
  for (const double a : s.nodes.added_mass)
    added += a;
  for (const spg::Domain& d : s.spg)
    for (const double a : d.particles.added_mass)
      added += a;
  return added;
}

std::vector<PartSummary> part_summaries(const State& s, const Eigen::Matrix3Xd& previous) {
  const Eigen::Matrix3Xd& velocity = s.nodes.velocity;
  std::vector<PartSummary> out(s.parts.size());
  for (std::size_t p = 0; p < s.parts.size(); ++p)
    out[p].part = s.parts[p].id;
  const Solids& so = s.solids;
  for (std::size_t e = 0; e < so.ids.size(); ++e) {
    PartSummary& ps = out[static_cast<std::size_t>(so.part[e])];
    (so.eroded[e] ? ps.eroded_internal : ps.internal) += so.internal_energy[e];
    ps.hourglass += so.hourglass_energy[e];
    ps.added_mass += so.added_mass[e];
    const double m = so.mass[e] / 8.0;
    for (const Index n : so.nodes[e]) {
      ps.kinetic += 0.5 * m * previous.col(n).dot(velocity.col(n));
      ps.momentum += 0.5 * m * (previous.col(n) + velocity.col(n));
    }
  }
  const Shells& sh = s.shells;
  const Nodes& nd = s.nodes;
  for (std::size_t e = 0; e < sh.ids.size(); ++e) {
    PartSummary& ps = out[static_cast<std::size_t>(sh.part[e])];
    (sh.eroded[e] ? ps.eroded_internal : ps.internal) += sh.internal_energy[e];
    ps.hourglass += sh.hourglass_energy[e];
    ps.added_mass += sh.added_mass[e];
    const bool triangle = sh.nodes[e][3] == sh.nodes[e][2];
    const double m = sh.mass[e] / (triangle ? 3.0 : 4.0);
    const double inertia = sh.corner_inertia[e];
    for (int c = 0; c < (triangle ? 3 : 4); ++c) {
      const Index n = sh.nodes[e][static_cast<std::size_t>(c)];
      ps.kinetic +=
          0.5 * m * previous.col(n).dot(velocity.col(n)) +
          0.5 * inertia * nd.previous_angular_velocity.col(n).dot(nd.angular_velocity.col(n));
      ps.momentum += 0.5 * m * (previous.col(n) + velocity.col(n));
    }
  }
  const Beams& bm = s.beams;
  for (std::size_t e = 0; e < bm.ids.size(); ++e) {
    PartSummary& ps = out[static_cast<std::size_t>(bm.part[e])];
    (bm.eroded[e] ? ps.eroded_internal : ps.internal) += bm.internal_energy[e];
    ps.added_mass += bm.added_mass[e];
    const double m = 0.5 * bm.mass[e], inertia = bm.end_inertia[e];
    for (const Index n : bm.nodes[e]) {
      ps.kinetic +=
          0.5 * m * previous.col(n).dot(velocity.col(n)) +
          0.5 * inertia * nd.previous_angular_velocity.col(n).dot(nd.angular_velocity.col(n));
      ps.momentum += 0.5 * m * (previous.col(n) + velocity.col(n));
    }
  }
  for (const spg::Domain& d : s.spg) {
    PartSummary& ps = out[static_cast<std::size_t>(d.part)];
    for (Index i = 0; i < d.count(); ++i) {
      const auto ii = static_cast<std::size_t>(i);
      ps.internal += d.fields.internal_energy[ii];
      ps.added_mass += d.particles.added_mass[ii];
      const Index n = d.particles.nodes[ii];
      const bool mc = s.nodes.smoothed[static_cast<std::size_t>(n)] == 1;
      const Vec3 before = mc ? Vec3(d.fields.unsmoothed_previous.col(i)) : Vec3(previous.col(n));
      const Vec3 after = mc ? Vec3(d.fields.unsmoothed.col(i)) : Vec3(velocity.col(n));
      ps.kinetic += 0.5 * d.particles.mass[ii] * before.dot(after);
      ps.momentum += 0.5 * d.particles.mass[ii] * (before + after);
    }
    ps.internal += d.fields.damping_energy;
    for (const double w : d.fields.mode_energy)
      ps.hourglass += w;
  }
  for (std::size_t p = 0; p < s.parts.size(); ++p) {
    const Index b = s.parts[p].rigid_body;
    if (b < 0) continue;
    const RigidBody& body = s.rigid_bodies[static_cast<std::size_t>(b)];
    const Vec3 v = 0.5 * (body.velocity + body.previous_velocity);
    out[p].kinetic = rigid_kinetic(body);
    out[p].momentum = body.mass * v;
    out[p].rigid_velocity = v;
  }
  return out;
}

}  // namespace mcdyna::solver
