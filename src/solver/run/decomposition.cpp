#include "solver/run/decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "solver/block.hpp"
#include "solver/parallel/bisection.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::solver::parallel {

namespace {

// Bisects the nodes flagged in `take` (by `weight`) over all ranks into d.owner.
void bisect_nodes(const State& s, const std::vector<std::uint8_t>& take,
                  const std::vector<double>& weight, int ranks, Decomposition& d) {
  std::vector<Index> nodes;
  for (Index n = 0; n < s.nodes.count(); ++n)
    if (take[static_cast<std::size_t>(n)]) nodes.push_back(n);
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(nodes.size()));
  std::vector<double> w(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    points.col(static_cast<Eigen::Index>(k)) = s.nodes.initial.col(nodes[k]);
    w[k] = weight[static_cast<std::size_t>(nodes[k])];
  }
  const std::vector<int> cell = bisect(points, w, ranks);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    d.owner[static_cast<std::size_t>(nodes[k])] = cell[k];
}

// The slave nodes the contact blocks visit each cycle, one entry per pass and node.
std::vector<Index> contact_nodes(const State& s) {
  std::vector<Index> nodes;
  for (const std::unique_ptr<Block>& b : s.blocks)
    b->add_contact_nodes(nodes);
  return nodes;
}

}  // namespace

Decomposition decompose(const State& s, int ranks, const EntityCosts& costs) {
  const auto n = static_cast<std::size_t>(s.nodes.count());
  Decomposition d;
  d.ranks = ranks;
  d.owner.assign(n, 0);
  // What sits on each node: its particles, an eighth of each solid, its contact passes.
  std::vector<double> weight(n, 0.0);
  std::vector<std::uint8_t> particle(n, 0), solid(n, 0), other(n, 1);
  for (const spg::Domain* dom : spg::domains_of(s))
    for (const Index node : dom->particles.nodes) {
      particle[static_cast<std::size_t>(node)] = 1;
      weight[static_cast<std::size_t>(node)] += costs.particle;
    }
  for (const auto& element : solids_of(s).nodes)
    for (const Index node : element) {
      solid[static_cast<std::size_t>(node)] = 1;
      weight[static_cast<std::size_t>(node)] += costs.hexahedron / 8.0;
    }
  const std::vector<Index> searched = contact_nodes(s);
  for (const Index node : searched)
    weight[static_cast<std::size_t>(node)] += costs.contact_node;
  for (std::size_t k = 0; k < n; ++k) {
    if (particle[k]) solid[k] = 0;  // a particle's node goes with the particles
    if (particle[k] || solid[k]) other[k] = 0;
  }
  bisect_nodes(s, particle, weight, ranks, d);
  bisect_nodes(s, solid, weight, ranks, d);
  // Rigid-body and free nodes: little work each, spread by count.
  std::vector<double> unit(n, 1.0);
  bisect_nodes(s, other, unit, ranks, d);
  return d;
}

std::vector<RankLoad> rank_loads(const State& s, const Decomposition& d, const EntityCosts& costs) {
  std::vector<RankLoad> load(static_cast<std::size_t>(d.ranks));
  for (const int r : d.owner)
    ++load[static_cast<std::size_t>(r)].owned_nodes;
  std::vector<std::pair<int, Index>> read;  // (rank, node) it reads
  std::vector<int> ranks;
  auto computed_by = [&](const auto& nodes_of_entity) {  // the ranks owning any of its nodes
    ranks.clear();
    for (const Index node : nodes_of_entity)
      ranks.push_back(d.owner[static_cast<std::size_t>(node)]);
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  };
  for (const auto& element : solids_of(s).nodes) {
    computed_by(element);
    for (const int r : ranks) {
      RankLoad& l = load[static_cast<std::size_t>(r)];
      ++l.elements;
      if (ranks.size() > 1) ++l.ghost_elements;
      l.cost += costs.hexahedron;
      for (const Index node : element)
        read.emplace_back(r, node);
    }
  }
  std::vector<Index> row_nodes;
  for (const spg::Domain* dp : spg::domains_of(s)) {
    const spg::Domain& dom = *dp;
    const spg::NeighbourList& list = dom.kernel.list;
    for (Index j = 0; j < dom.count(); ++j) {
      row_nodes.clear();
      for (Index q = list.offsets[static_cast<std::size_t>(j)];
           q < list.offsets[static_cast<std::size_t>(j) + 1]; ++q)
        row_nodes.push_back(
            dom.particles
                .nodes[static_cast<std::size_t>(list.neighbours[static_cast<std::size_t>(q)])]);
      const Index own_node = dom.particles.nodes[static_cast<std::size_t>(j)];
      row_nodes.push_back(own_node);
      computed_by(row_nodes);
      const int owner = d.owner[static_cast<std::size_t>(own_node)];
      ++load[static_cast<std::size_t>(owner)].particles;
      for (const int r : ranks) {
        RankLoad& l = load[static_cast<std::size_t>(r)];
        ++l.rows;
        if (r != owner) ++l.ghost_rows;
        l.cost += costs.particle;
        for (const Index node : row_nodes)
          read.emplace_back(r, node);
      }
    }
  }
  for (const Index node : contact_nodes(s))
    load[static_cast<std::size_t>(d.owner[static_cast<std::size_t>(node)])].cost +=
        costs.contact_node;
  std::sort(read.begin(), read.end());
  read.erase(std::unique(read.begin(), read.end()), read.end());
  std::vector<std::pair<int, int>> peers;  // (rank, rank owning a node it reads)
  for (const auto& [r, node] : read) {
    const int owner = d.owner[static_cast<std::size_t>(node)];
    if (owner == r) continue;
    ++load[static_cast<std::size_t>(r)].ghost_nodes;
    peers.emplace_back(r, owner);
  }
  std::sort(peers.begin(), peers.end());
  peers.erase(std::unique(peers.begin(), peers.end()), peers.end());
  for (const auto& [r, owner] : peers)
    ++load[static_cast<std::size_t>(r)].peers;
  return load;
}

}  // namespace mcdyna::solver::parallel
