#include "solver/run/halo.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "solver/solids/solids.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::solver::parallel {

namespace {

// Every per-node value an output reads that the process moving the node computes, as (first
// value, count) pairs; one list serves packing and unpacking.
template <class Visit>
void node_fields(State& s, Eigen::Matrix3Xd& previous, Index n, Visit&& visit) {
  Nodes& nd = s.nodes;
  visit(nd.position.col(n).data(), 3);
  visit(nd.velocity.col(n).data(), 3);
  visit(nd.acceleration.col(n).data(), 3);
  visit(&nd.added_mass[static_cast<std::size_t>(n)], 1);
  visit(previous.col(n).data(), 3);
}

// The same for a hexahedron: what the histories read (energy.cpp), and with `states` its other
// values and those of its integration points.
template <class Visit>
void element_fields(Solids& so, Index e, bool states, Visit&& visit) {
  const auto i = static_cast<std::size_t>(e);
  for (std::vector<double>* v : {&so.internal_energy, &so.hourglass_energy, &so.added_mass})
    visit(&(*v)[i], 1);
  if (!states) return;
  for (std::vector<double>* v :
       {&so.volume, &so.pressure, &so.eos_energy, &so.temperature, &so.viscosity, &so.time_step})
    visit(&(*v)[i], 1);
  visit(&so.hourglass_force[12 * i], 12);
  visit(&so.corner_force[24 * i], 24);
  const auto block = std::find_if(so.blocks.begin(), so.blocks.end(),
                                  [e](const SolidBlock& b) { return e >= b.begin && e < b.end; });
  const Index first = block->point_begin + (e - block->begin) * block->points_per_element;
  MaterialPoints& p = so.points;
  for (Index q = first; q < first + block->points_per_element; ++q) {
    visit(p.deviator.col(q).data(), 6);
    if (p.back_stress.cols() > 0) visit(p.back_stress.col(q).data(), 6);
    if (!p.plastic_strain.empty()) visit(&p.plastic_strain[static_cast<std::size_t>(q)], 1);
    if (!p.damage.empty()) visit(&p.damage[static_cast<std::size_t>(q)], 1);
  }
}

}  // namespace

Halo::Halo(State& s, const Decomposition& d, std::vector<std::uint8_t> replicated,
           core::Communicator comm)
    : comm_(comm) {
  s.ownership.comm = comm_;
  s.ownership.replicated = std::move(replicated);
  s.ownership.owner = d.owner;
  rebuild(s);
}

void Halo::rebuild(State& s) {
  const int me = comm_.rank();
  const Index n_nodes = s.nodes.count();
  const Solids& solids = solids_of(s);
  const Index n_elements = solids.count();
  Ownership& own = s.ownership;
  size_ = HaloSize{};
  output_.assign(static_cast<std::size_t>(comm_.size()), OutputShare{});
  own.moves.assign(static_cast<std::size_t>(n_nodes), 0);
  own.owns.assign(static_cast<std::size_t>(n_nodes), 0);
  own.computes.assign(static_cast<std::size_t>(n_elements), 0);
  auto owner = [&](Index n) { return own.owner[static_cast<std::size_t>(n)]; };
  own.moved_nodes.clear();
  for (Index n = 0; n < n_nodes; ++n) {
    const auto i = static_cast<std::size_t>(n);
    own.moves[i] = (owner(n) == me || own.replicated[i]) ? 1 : 0;
    if (own.moves[i]) own.moved_nodes.push_back(n);
    own.owns[i] = owner(n) == me ? 1 : 0;
    if (own.replicated[i])
      ++size_.replicated_nodes;
    else if (owner(n) == me)
      ++size_.owned_nodes;
  }
  // The hexahedra with a moved node, and the nodes they read that another process moves.
  std::vector<std::uint8_t> ghost(static_cast<std::size_t>(n_nodes), 0);
  for (Index e = 0; e < n_elements; ++e) {
    const auto& corners = solids.nodes[static_cast<std::size_t>(e)];
    if (std::none_of(corners.begin(), corners.end(), [&](Index n) { return own.moves_node(n); }))
      continue;
    own.computes[static_cast<std::size_t>(e)] = 1;
    ++size_.elements;
    if (owner(corners[0]) != me) ++size_.ghost_elements;
    for (const Index n : corners)
      if (!own.moves_node(n)) ghost[static_cast<std::size_t>(n)] = 1;
  }
  // The split SPG parts: the nodes of the rows a process computes (spg/distribution.cpp).
  for (std::size_t k = 0; k < own.particles.size(); ++k) {
    const ParticleShare* share = own.split_part(k);
    if (share == nullptr) continue;
    const spg::Domain& dom = spg::domain_of(s, k);
    size_.particles += static_cast<Index>(share->owned.index.size());
    size_.rows += static_cast<Index>(share->stressed.index.size());
    size_.particle_ghosts += share->row_ghosts.ghosts() + share->column_ghosts.ghosts();
    size_.particle_bytes +=
        share->row_ghosts.received_bytes() + share->column_ghosts.received_bytes();
    for (const Index j : share->stressed.index) {
      const auto jj = static_cast<std::size_t>(j);
      for (Index p = dom.kernel.list.offsets[jj]; p < dom.kernel.list.offsets[jj + 1]; ++p) {
        const Index node = dom.particles.nodes[static_cast<std::size_t>(
            dom.kernel.list.neighbours[static_cast<std::size_t>(p)])];
        if (!own.moves_node(node)) ghost[static_cast<std::size_t>(node)] = 1;
      }
      const Index node = dom.particles.nodes[jj];
      if (!own.moves_node(node)) ghost[static_cast<std::size_t>(node)] = 1;
    }
  }
  motion_ = ExchangePlan(comm_, own.owner, ghost, 6);
  size_.ghost_nodes = motion_.ghosts();
  size_.sent_nodes = motion_.sent();
  size_.peers = motion_.peers();
  // What each process other than 0 sends to 0 at an output: the values it alone computes.
  for (Index n = 0; n < n_nodes; ++n)
    if (const int r = own.output_owner(n); r != 0)
      output_[static_cast<std::size_t>(r)].nodes.push_back(n);
  for (Index e = 0; e < n_elements; ++e)
    if (const int r = owner(solids.nodes[static_cast<std::size_t>(e)][0]); r != 0)
      output_[static_cast<std::size_t>(r)].elements.push_back(e);
}

void Halo::exchange_motion(State& s) {
  Nodes& nd = s.nodes;
  motion_.exchange(
      [&](Index n, double* out) {
        for (int c = 0; c < 3; ++c) {
          out[c] = nd.position(c, n);
          out[3 + c] = nd.velocity(c, n);
        }
      },
      [&](Index n, const double* in) {
        for (int c = 0; c < 3; ++c) {
          nd.position(c, n) = in[c];
          nd.velocity(c, n) = in[3 + c];
        }
      });
}

void Halo::gather_for_output(State& s, Eigen::Matrix3Xd& previous, bool states) const {
  // Packing and unpacking walk the same lists in the same order.
  Solids* solids = solids_in(s);  // elements are in the shares only when there are hexahedra
  auto walk = [&](const OutputShare& share, auto&& visit) {
    for (const Index n : share.nodes)
      node_fields(s, previous, n, visit);
    for (const Index e : share.elements) {
      // The erosion flag travels as a double beside the element's values.
      double eroded = solids->eroded[static_cast<std::size_t>(e)];
      visit(&eroded, 1);
      solids->eroded[static_cast<std::size_t>(e)] = static_cast<std::uint8_t>(eroded);
      element_fields(*solids, e, states, visit);
    }
  };
  std::vector<double> mine;
  if (comm_.rank() != 0)
    walk(output_[static_cast<std::size_t>(comm_.rank())],
         [&](const double* v, int count) { mine.insert(mine.end(), v, v + count); });
  std::vector<int> counts;
  const std::vector<double> all = comm_.gather_to_root(mine, counts);
  if (comm_.rank() != 0) return;
  const double* in = all.data();
  for (int r = 1; r < comm_.size(); ++r)
    walk(output_[static_cast<std::size_t>(r)], [&](double* v, int count) {
      std::copy(in, in + count, v);
      in += count;
    });
  if (in != all.data() + all.size())
    throw std::logic_error("Halo::gather_for_output: the processes' shares do not match");
}

std::size_t Halo::received_bytes() const {
  return motion_.received_bytes() + size_.particle_bytes;
}

std::string Halo::summary() const {
  const std::vector<double> mine = {
      static_cast<double>(size_.owned_nodes),    static_cast<double>(size_.replicated_nodes),
      static_cast<double>(size_.ghost_nodes),    static_cast<double>(size_.sent_nodes),
      static_cast<double>(size_.peers),          static_cast<double>(size_.elements),
      static_cast<double>(size_.ghost_elements), static_cast<double>(received_bytes()),
      static_cast<double>(size_.particles),      static_cast<double>(size_.rows),
      static_cast<double>(size_.particle_ghosts)};
  const std::vector<double> all = comm_.all_gather(mine);
  if (comm_.rank() != 0) return {};
  std::string out = fmt::format(
      "Decomposition over {} processes (recursive coordinate bisection, issue 25)\n"
      "  rank  owned nodes  replicated  ghost nodes  sent nodes  peers  hexahedra  ghost hexa  "
      "halo bytes/cycle  particles  SPG rows  particle ghosts\n",
      comm_.size());
  for (int r = 0; r < comm_.size(); ++r) {
    const double* v = &all[static_cast<std::size_t>(r) * mine.size()];
    out += fmt::format(
        "  {:4d} {:12.0f} {:11.0f} {:12.0f} {:11.0f} {:6.0f} {:10.0f} {:11.0f} {:17.0f} {:10.0f} "
        "{:9.0f} {:16.0f}\n",
        r, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10]);
  }
  out +=
      "  replicated: nodes of the blocks every process computes whole (contact, SPG parts with\n"
      "  options not split yet); each process moves them itself. SPG rows: the rows a process\n"
      "  computes (its particles' and those holding them); particle ghosts: accelerations and\n"
      "  unsmoothed velocities received per cycle, counted in the halo bytes.\n";
  return out;
}

}  // namespace mcdyna::solver::parallel
