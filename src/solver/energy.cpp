// glstat's and matsum's sums: each block adds its own terms (Block::add_energies,
// add_part_energies) in the blocks' order, then the nodes that no block moves itself add their
// kinetic energy, momentum and mass.
#include "solver/energy.hpp"

#include "solver/block.hpp"

namespace mcdyna::solver {

EnergySummary energy_summary(const State& s, const Eigen::Matrix3Xd& previous) {
  EnergySummary e;
  for (const auto& b : s.blocks)
    b->add_energies(s, previous, e);
  const Eigen::Matrix3Xd& velocity = s.nodes.velocity;
  const Nodes& nd = s.nodes;
  for (Index n = 0; n < nd.count(); ++n) {
    const auto i = static_cast<std::size_t>(n);
    // Rigid-body nodes and MC-SPG particles are counted by their blocks.
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
  for (const auto& b : s.blocks)
    b->add_added_mass(s, added);
  return added;
}

std::vector<PartSummary> part_summaries(const State& s, const Eigen::Matrix3Xd& previous) {
  std::vector<PartSummary> out(s.parts.size());
  for (std::size_t p = 0; p < s.parts.size(); ++p)
    out[p].part = s.parts[p].id;
  for (const auto& b : s.blocks)
    b->add_part_energies(s, previous, out);
  return out;
}

}  // namespace mcdyna::solver
