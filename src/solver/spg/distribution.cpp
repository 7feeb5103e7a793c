// An SPG part split over processes: shares, the synchronisation at kernel checks, re-owning
// after renewals (distribution.hpp).
#include "solver/spg/distribution.hpp"

#include <stdexcept>

#include "solver/parallel/decomposition.hpp"

namespace mcdyna::solver::spg {

namespace {

// Every value of particle j that one process computes for the others between kernel checks,
// as (first value, count); one list serves packing and unpacking. A byte flag travels as a
// double.
template <class Visit>
void particle_values(State& s, Domain& d, Index j, bool masses_only, Visit&& visit) {
  const auto jj = static_cast<std::size_t>(j);
  ParticleSet& p = d.particles;
  visit(&p.mass[jj], 1);
  visit(&p.base_mass[jj], 1);
  visit(&p.added_mass[jj], 1);
  if (masses_only) return;
  const Index node = p.nodes[jj];
  visit(s.nodes.position.col(node).data(), 3);
  visit(s.nodes.velocity.col(node).data(), 3);
  ParticleFields& f = d.fields;
  for (std::vector<double>* v : {&f.volume, &f.step, &f.pressure, &f.eos_energy, &f.temperature,
                                 &f.viscosity, &f.internal_energy, &f.mode_stiffness,
                                 &f.mode_energy, &f.points.plastic_strain, &f.points.damage})
    if (!v->empty()) visit(&(*v)[jj], 1);
  for (Eigen::Matrix3Xd* m :
       {&f.unsmoothed, &f.unsmoothed_previous, &f.smoothed, &f.mode_residual, &f.mode_force})
    if (m->cols() > 0) visit(m->col(j).data(), 3);
  visit(f.points.deviator.col(j).data(), 6);
  if (f.points.back_stress.cols() > 0) visit(f.points.back_stress.col(j).data(), 6);
  visit(f.deformation.col(j).data(), 9);
  visit(f.stress_gradient.col(j).data(), 9);
  for (std::vector<std::uint8_t>* flags : {&f.failed, &f.debris}) {
    double flag = (*flags)[jj];
    visit(&flag, 1);
    (*flags)[jj] = static_cast<std::uint8_t>(flag);
  }
}

parallel::ParticleShare& share_of(State& s, std::size_t domain) {
  if (s.ownership.particles.size() != s.spg.size()) s.ownership.particles.resize(s.spg.size());
  return s.ownership.particles[domain];
}

}  // namespace

bool splittable(const Domain& d) {
  const Stabilization mode = d.settings.stabilization;
  return (mode == Stabilization::momentum_consistent || mode == Stabilization::none) &&
         d.settings.step_estimate == StepEstimate::nearest_neighbour;
}

std::size_t domain_index(const State& s, const Domain& d) {
  return static_cast<std::size_t>(&d - s.spg.data());
}

void share_particles(State& s, std::size_t domain) {
  const Domain& d = s.spg[domain];
  parallel::ParticleShare& share = share_of(s, domain);
  const core::Communicator& comm = s.ownership.comm;
  const int me = comm.rank();
  const auto n = static_cast<std::size_t>(d.count());
  share.split = true;
  share.owner.resize(n);
  share.owns.assign(n, 0);
  share.stresses.assign(n, 0);
  share.owned.clear();
  share.stressed.clear();
  for (std::size_t j = 0; j < n; ++j) {
    share.owner[j] = s.ownership.owner[static_cast<std::size_t>(d.particles.nodes[j])];
    if (share.owner[j] == me) {
      share.owns[j] = 1;
      share.stresses[j] = 1;
      share.owned.push_back(static_cast<Index>(j));
    }
  }
  // The rows holding an owned particle (its transpose), and the two ghost layers.
  std::vector<std::uint8_t> row_ghost(n, 0), column_ghost(n, 0);
  for (const Index i : share.owned) {
    const auto ii = static_cast<std::size_t>(i);
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto j = static_cast<std::size_t>(d.kernel.transpose.rows[static_cast<std::size_t>(t)]);
      share.stresses[j] = 1;
      if (!share.owns[j]) column_ghost[j] = 1;
    }
    for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
      const auto j =
          static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
      if (!share.owns[j]) row_ghost[j] = 1;
    }
  }
  // PDAMP's pairs read the previous u-hat of the row partners as well.
  if (d.settings.damping > 0.0)
    for (std::size_t j = 0; j < n; ++j)
      column_ghost[j] = column_ghost[j] | row_ghost[j];
  for (std::size_t j = 0; j < n; ++j)
    if (share.stresses[j]) share.stressed.push_back(static_cast<Index>(j));
  share.row_ghosts = parallel::ExchangePlan(comm, share.owner, row_ghost, 3);
  share.column_ghosts = parallel::ExchangePlan(comm, share.owner, column_ghost, 3);
}

void synchronise(State& s, std::size_t domain, bool masses_only) {
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  if (share == nullptr) return;
  Domain& d = s.spg[domain];
  std::vector<double> mine;
  for (const Index j : share->owned)
    particle_values(s, d, j, masses_only,
                    [&](const double* v, int count) { mine.insert(mine.end(), v, v + count); });
  const std::vector<double> all = s.ownership.comm.all_gather_varying(mine);
  // Unpacked in the order they were packed: process by process, each one's particles ascending.
  const double* in = all.data();
  for (int r = 0; r < s.ownership.comm.size(); ++r)
    for (Index j = 0; j < d.count(); ++j) {
      if (share->owner[static_cast<std::size_t>(j)] != r) continue;
      particle_values(s, d, j, masses_only, [&](double* v, int count) {
        std::copy(in, in + count, v);
        in += count;
      });
    }
  if (in != all.data() + all.size())
    throw std::logic_error("spg::synchronise: the processes' shares do not match");
}

void reown_particles(State& s, std::size_t domain) {
  const Domain& d = s.spg[domain];
  std::vector<Index> free;
  for (Index j = 0; j < d.count(); ++j)
    if (!d.particles.shared[static_cast<std::size_t>(j)]) free.push_back(j);
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k)
    points.col(static_cast<Eigen::Index>(k)) =
        s.nodes.position.col(d.particles.nodes[static_cast<std::size_t>(free[k])]);
  const std::vector<int> cell =
      parallel::bisect(points, std::vector<double>(free.size(), 1.0), s.ownership.comm.size());
  for (std::size_t k = 0; k < free.size(); ++k)
    s.ownership
        .owner[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(free[k])])] =
        cell[k];
}

}  // namespace mcdyna::solver::spg
