// An SPG part split over processes: shares, the synchronisation at kernel checks, re-owning
// after renewals (distribution.hpp).
#include "solver/spg/distribution.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/parallel/bisection.hpp"
#include "solver/parallel/owned_gather.hpp"

namespace mcdyna::solver::spg {

namespace {

// The values of particle j that a synchronisation carries (distribution.hpp, Scope), as
// (first value, count); one list serves packing and unpacking. A byte flag travels as a double.
// `force`: the cycle's nodal forces, carried with `everything` where given (a migration in the
// force pass; a dump takes them from the time loop).
template <class Visit>
void particle_values(State& s, Domain& d, Index j, Scope scope, Visit&& visit,
                     Eigen::Matrix3Xd* force = nullptr) {
  const auto jj = static_cast<std::size_t>(j);
  ParticleSet& p = d.particles;
  ParticleFields& f = d.fields;
  auto flags = [&](std::initializer_list<std::vector<std::uint8_t>*> list) {
    for (std::vector<std::uint8_t>* v : list) {
      double flag = (*v)[jj];
      visit(&flag, 1);
      (*v)[jj] = static_cast<std::uint8_t>(flag);
    }
  };
  const Index node = p.nodes[jj];
  if (scope == Scope::masses) {
    for (std::vector<double>* v : {&p.mass, &p.base_mass, &p.added_mass})
      visit(&(*v)[jj], 1);
    return;
  }
  if (scope == Scope::histories) {  // energy.cpp and the ASCII histories
    for (std::vector<double>* v : {&p.mass, &p.added_mass, &f.internal_energy, &f.mode_energy})
      if (!v->empty()) visit(&(*v)[jj], 1);
    visit(f.unsmoothed.col(j).data(), 3);
    visit(f.unsmoothed_previous.col(j).data(), 3);
    return;
  }
  if (scope == Scope::check) {  // what bond failure and the renewal read (renewal.cpp)
    visit(s.nodes.position.col(node).data(), 3);
    visit(f.deformation.col(j).data(), 9);
    visit(&f.pressure[jj], 1);
    visit(&f.volume[jj], 1);
    if (!f.points.plastic_strain.empty()) visit(&f.points.plastic_strain[jj], 1);
    flags({&f.debris});
    return;
  }
  for (std::vector<double>* v : {&p.mass, &p.base_mass, &p.added_mass})
    visit(&(*v)[jj], 1);
  visit(s.nodes.position.col(node).data(), 3);
  visit(s.nodes.velocity.col(node).data(), 3);
  // The force summed so far in this force pass, and the acceleration of the last cycle.
  if (force) visit(force->col(node).data(), 3);
  visit(s.nodes.acceleration.col(node).data(), 3);
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
  flags({&f.failed, &f.debris});
  // The eigenvalue step's power iterate, kept on the particles' owners (frequency.cpp).
  if (d.kernel.step_bound.mode.cols() > 0) visit(d.kernel.step_bound.mode.col(j).data(), 3);
}

parallel::ParticleShare& share_of(State& s, std::size_t domain) {
  const std::size_t parts = domains_of(s).size();
  if (s.ownership.particles.size() != parts) s.ownership.particles.resize(parts);
  return s.ownership.particles[domain];
}

}  // namespace

bool splittable(const Domain& d) {
  const Stabilization mode = d.settings.stabilization;
  return mode == Stabilization::momentum_consistent || mode == Stabilization::none;
}

void share_particles(State& s, std::size_t domain) {
  const Domain& d = domain_of(s, domain);
  parallel::ParticleShare& share = share_of(s, domain);
  const core::Communicator& comm = s.ownership.comm;
  const int me = comm.rank();
  const auto n = static_cast<std::size_t>(d.count());
  share.split = true;
  share.owner.resize(n);
  share.owned.flag.assign(n, 0);
  share.stressed.flag.assign(n, 0);
  share.owned.index.clear();
  share.stressed.index.clear();
  for (std::size_t j = 0; j < n; ++j) {
    share.owner[j] = s.ownership.owner[static_cast<std::size_t>(d.particles.nodes[j])];
    if (share.owner[j] == me) {
      share.owned.flag[j] = 1;
      share.stressed.flag[j] = 1;
      share.owned.index.push_back(static_cast<Index>(j));
    }
  }
  // The rows holding an owned particle (its transpose), and the two ghost layers.
  std::vector<std::uint8_t> row_ghost(n, 0), column_ghost(n, 0);
  for (const Index i : share.owned.index) {
    const auto ii = static_cast<std::size_t>(i);
    for (Index t = d.kernel.transpose.offsets[ii]; t < d.kernel.transpose.offsets[ii + 1]; ++t) {
      const auto j = static_cast<std::size_t>(d.kernel.transpose.rows[static_cast<std::size_t>(t)]);
      share.stressed.flag[j] = 1;
      if (!share.owned.flag[j]) column_ghost[j] = 1;
    }
    for (Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
      const auto j =
          static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
      if (!share.owned.flag[j]) row_ghost[j] = 1;
    }
  }
  // PDAMP's pairs read the previous u-hat of the row partners as well.
  if (d.settings.damping > 0.0)
    for (std::size_t j = 0; j < n; ++j)
      column_ghost[j] = column_ghost[j] | row_ghost[j];
  for (std::size_t j = 0; j < n; ++j)
    if (share.stressed.flag[j]) share.stressed.index.push_back(static_cast<Index>(j));
  share.current.flag.assign(n, 0);
  share.current.index.clear();
  for (std::size_t j = 0; j < n; ++j)
    if (share.owned.flag[j] || column_ghost[j]) {
      share.current.flag[j] = 1;
      share.current.index.push_back(static_cast<Index>(j));
    }
  share.row_ghosts = parallel::ExchangePlan(comm, share.owner, row_ghost, 3);
  share.column_ghosts = parallel::ExchangePlan(comm, share.owner, column_ghost, 3);
  // The eigenvalue step's power iteration (frequency.cpp) forms the stress of the stressed rows
  // from an iterate that lives on the owners: it reads the iterate of every particle in them.
  share.stress_ghosts = parallel::ExchangePlan();
  if (d.settings.step_estimate == StepEstimate::eigenvalue) {
    std::vector<std::uint8_t> stress_ghost(n, 0);
    for (const Index j : share.stressed.index) {
      const auto jj = static_cast<std::size_t>(j);
      if (!share.owned.flag[jj]) stress_ghost[jj] = 1;
      for (Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
        const auto k =
            static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
        if (!share.owned.flag[k]) stress_ghost[k] = 1;
      }
    }
    share.stress_ghosts = parallel::ExchangePlan(comm, share.owner, stress_ghost, 3);
  }
}

void synchronise(State& s, std::size_t domain, Scope scope) {
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  if (share == nullptr) return;
  Domain& d = domain_of(s, domain);
  parallel::gather_owned(
      s.ownership.comm, share->owner.size(), [&](std::size_t j) { return share->owner[j]; },
      [&](std::size_t j, std::vector<double>& out) {
        particle_values(s, d, static_cast<Index>(j), scope,
                        [&](const double* v, int count) { out.insert(out.end(), v, v + count); });
      },
      [&](std::size_t j, const double*& in) {
        particle_values(s, d, static_cast<Index>(j), scope, [&](double* v, int count) {
          std::copy(in, in + count, v);
          in += count;
        });
      },
      scope == Scope::to_root || scope == Scope::histories);
}

void migrate(State& s, std::size_t domain, const std::vector<int>& previous_owner,
             Eigen::Matrix3Xd& force) {
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  Domain& d = domain_of(s, domain);
  const int me = s.ownership.comm.rank();
  const auto n = static_cast<std::size_t>(d.count());
  // What this process reads from now on: its stressed rows and the particles in them (their
  // nodes' x and v, and for its own particles' rows the accelerations and u-hat).
  std::vector<std::uint8_t> wanted(share->stressed.flag);
  for (const Index i : share->stressed.index)
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(i)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(i) + 1]; ++p)
      wanted[static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)])] = 1;
  for (std::size_t j = 0; j < n; ++j)
    if (previous_owner[j] == me) wanted[j] = 0;  // held whole here until now
  int width = 0;
  particle_values(
      s, d, 0, Scope::everything, [&](const double*, int count) { width += count; }, &force);
  parallel::ExchangePlan plan(s.ownership.comm, previous_owner, wanted, width);
  plan.exchange(
      [&](Index j, double* out) {
        particle_values(
            s, d, j, Scope::everything,
            [&](const double* v, int count) { out = std::copy(v, v + count, out); }, &force);
      },
      [&](Index j, const double* in) {
        particle_values(
            s, d, j, Scope::everything,
            [&](double* v, int count) {
              std::copy(in, in + count, v);
              in += count;
            },
            &force);
      });
}

void share_columns(const State& s, std::size_t domain, double* values, int width) {
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const auto w = static_cast<std::size_t>(width);
  parallel::gather_owned(
      s.ownership.comm, share->owner.size(), [&](std::size_t j) { return share->owner[j]; },
      [&](std::size_t j, std::vector<double>& out) {
        out.insert(out.end(), values + w * j, values + w * (j + 1));
      },
      [&](std::size_t j, const double*& in) {
        std::copy(in, in + w, values + w * j);
        in += w;
      });
}

void exchange_columns(parallel::ParticleShare& share, parallel::ExchangePlan& plan,
                      Eigen::Matrix3Xd& field) {
  const auto start = std::chrono::steady_clock::now();
  plan.exchange(
      [&](Index j, double* out) {
        for (int c = 0; c < 3; ++c)
          out[c] = field(c, j);
      },
      [&](Index j, const double* in) {
        for (int c = 0; c < 3; ++c)
          field(c, j) = in[c];
      });
  share.exchange_seconds += seconds_since(start);
}

std::vector<int> row_builders(const std::vector<std::uint8_t>& flagged, int processes) {
  const auto count = static_cast<std::size_t>(std::count(flagged.begin(), flagged.end(), 1));
  std::vector<int> builder(flagged.size(), -1);
  std::size_t k = 0;
  for (std::size_t i = 0; i < flagged.size(); ++i)
    if (flagged[i])
      builder[i] = static_cast<int>(k++ * static_cast<std::size_t>(processes) / count);
  return builder;
}

namespace {

// The processes that read row `row` of `list` under `owner`: the owner of the row and of every
// particle in it, ascending, once each.
void readers_of(const NeighbourList& list, Index row, const std::vector<int>& owner,
                std::vector<int>& readers) {
  readers.assign(1, owner[static_cast<std::size_t>(row)]);
  for (Index p = list.offsets[static_cast<std::size_t>(row)];
       p < list.offsets[static_cast<std::size_t>(row) + 1]; ++p)
    readers.push_back(
        owner[static_cast<std::size_t>(list.neighbours[static_cast<std::size_t>(p)])]);
  std::sort(readers.begin(), readers.end());
  readers.erase(std::unique(readers.begin(), readers.end()), readers.end());
}

bool reads(const std::vector<int>& readers, int process) {
  return std::binary_search(readers.begin(), readers.end(), process);
}

// A row in a message: its particle, its pair count, its per-row values, then per pair the
// neighbour, phi and grad phi.
constexpr std::size_t kRowHeader = 7, kPairValues = 5;

void pack_row(const Domain& d, const NeighbourList& list, const ShapeFunctions& shape, Index row,
              std::vector<double>& out) {
  const auto r = static_cast<std::size_t>(row);
  out.insert(out.end(),
             {static_cast<double>(row), static_cast<double>(list.count(row)), d.kernel.length[r],
              d.kernel.renewal_volume[r], d.fields.mode_residual(0, row),
              d.fields.mode_residual(1, row), d.fields.mode_residual(2, row)});
  for (Index p = list.offsets[r]; p < list.offsets[r + 1]; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    out.insert(out.end(), {static_cast<double>(list.neighbours[pp]), shape.value[pp],
                           shape.gradient(0, p), shape.gradient(1, p), shape.gradient(2, p)});
  }
}

}  // namespace

std::vector<Index> share_degenerate(const State& s, const std::vector<Index>& mine) {
  const std::vector<double> all =
      s.ownership.comm.all_gather_varying(std::vector<double>(mine.begin(), mine.end()));
  std::vector<Index> degenerate(all.begin(), all.end());
  std::sort(degenerate.begin(), degenerate.end());
  return degenerate;
}

void redistribute_rows(State& s, std::size_t domain, const std::vector<int>& builder,
                       const NeighbourList& fresh, const ShapeFunctions& fresh_shape,
                       NeighbourList& incoming, ShapeFunctions& incoming_shape,
                       std::vector<std::uint8_t>& take) {
  Domain& d = domain_of(s, domain);
  const core::Communicator& comm = s.ownership.comm;
  const int me = comm.rank();
  const auto n = static_cast<std::size_t>(d.count());
  std::vector<int> owner(n);
  for (std::size_t j = 0; j < n; ++j)
    owner[j] = s.ownership.owner[static_cast<std::size_t>(d.particles.nodes[j])];
  // Rows out: a built row to every other process that reads it; an unchanged row, from its
  // previous owner, to the processes that read it now and did not before.
  // The share is still the one before the renewal: its owners and the rows read under them.
  const parallel::ParticleShare& before_renewal = *s.ownership.split_part(domain);
  const std::vector<int>& previous_owner = before_renewal.owner;
  const parallel::ParticleSubset& was_read = before_renewal.stressed;
  std::vector<std::vector<double>> to(static_cast<std::size_t>(comm.size()));
  std::vector<int> readers, before;
  std::vector<std::uint8_t> keep(n, 0);  // read here before and now, unchanged
  for (std::size_t j = 0; j < n; ++j) {
    const auto row = static_cast<Index>(j);
    if (builder[j] >= 0) {
      if (builder[j] != me) continue;
      readers_of(fresh, row, owner, readers);
      for (const int r : readers)
        if (r != me) pack_row(d, fresh, fresh_shape, row, to[static_cast<std::size_t>(r)]);
      continue;
    }
    if (!was_read.flag[j]) continue;
    readers_of(d.kernel.list, row, owner, readers);
    keep[j] = reads(readers, me) ? 1 : 0;
    if (previous_owner[j] != me) continue;
    readers_of(d.kernel.list, row, previous_owner, before);
    for (const int r : readers)
      if (!reads(before, r))
        pack_row(d, d.kernel.list, d.kernel.shape, row, to[static_cast<std::size_t>(r)]);
  }
  const std::vector<std::vector<double>> from = comm.all_to_all(to);
  std::vector<const double*> arrived(n, nullptr);
  for (const std::vector<double>& message : from)
    for (std::size_t at = 0; at < message.size();) {
      arrived[static_cast<std::size_t>(message[at])] = &message[at];
      at += kRowHeader + kPairValues * static_cast<std::size_t>(message[at + 1]);
    }
  // Rows in: the merge takes every row from `incoming` but the kept ones.
  std::vector<std::uint8_t> built_here(n, 0);
  take.assign(n, 1);
  incoming.offsets.assign(n + 1, 0);
  for (std::size_t j = 0; j < n; ++j) {
    const auto row = static_cast<Index>(j);
    Index count = 0;
    if (arrived[j] != nullptr) {
      count = static_cast<Index>(arrived[j][1]);
    } else if (builder[j] == me) {
      readers_of(fresh, row, owner, readers);
      built_here[j] = reads(readers, me) ? 1 : 0;
      if (built_here[j]) count = fresh.count(row);
    } else if (keep[j]) {
      take[j] = 0;
    }
    incoming.offsets[j + 1] = incoming.offsets[j] + count;
  }
  const auto pairs = static_cast<std::size_t>(incoming.offsets.back());
  incoming.neighbours.resize(pairs);
  incoming_shape.value.resize(pairs);
  incoming_shape.gradient.resize(3, static_cast<Eigen::Index>(pairs));
  incoming_shape.hessian.resize(6, 0);  // a split part has no second derivatives (splittable)
  for (std::size_t j = 0; j < n; ++j) {
    Index q = incoming.offsets[j];
    if (const double* in = arrived[j]) {
      if (builder[j] < 0) {  // an unchanged row keeps the values of its renewal
        d.kernel.length[j] = in[2];
        d.kernel.renewal_volume[j] = in[3];
        d.fields.mode_residual.col(static_cast<Eigen::Index>(j)) = Vec3(in[4], in[5], in[6]);
      }
      in += kRowHeader;
      for (; q < incoming.offsets[j + 1]; ++q, in += kPairValues) {
        incoming.neighbours[static_cast<std::size_t>(q)] = static_cast<Index>(in[0]);
        incoming_shape.value[static_cast<std::size_t>(q)] = in[1];
        incoming_shape.gradient.col(q) = Vec3(in[2], in[3], in[4]);
      }
    } else if (built_here[j]) {
      for (Index p = fresh.offsets[j]; p < fresh.offsets[j + 1]; ++p, ++q) {
        incoming.neighbours[static_cast<std::size_t>(q)] =
            fresh.neighbours[static_cast<std::size_t>(p)];
        incoming_shape.value[static_cast<std::size_t>(q)] =
            fresh_shape.value[static_cast<std::size_t>(p)];
        incoming_shape.gradient.col(q) = fresh_shape.gradient.col(p);
      }
    }
  }
}

NeighbourList rows_on_root(const State& s, std::size_t domain) {
  const Domain& d = domain_of(s, domain);
  const parallel::ParticleShare* share = s.ownership.split_part(domain);
  const auto n = static_cast<std::size_t>(d.count());
  std::vector<double> mine;  // per own row: the row, its count, its neighbours
  for (const Index i : share->owned.index) {
    mine.push_back(i);
    mine.push_back(d.kernel.list.count(i));
    for (Index p = d.kernel.list.offsets[static_cast<std::size_t>(i)];
         p < d.kernel.list.offsets[static_cast<std::size_t>(i) + 1]; ++p)
      mine.push_back(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
  }
  std::vector<int> counts;
  const std::vector<double> all = s.ownership.comm.gather_to_root(mine, counts);
  std::vector<const double*> start(n, nullptr);
  for (std::size_t at = 0; at < all.size(); at += 2 + static_cast<std::size_t>(all[at + 1]))
    start[static_cast<std::size_t>(all[at])] = &all[at];
  NeighbourList list;
  list.offsets.assign(n + 1, 0);
  for (std::size_t j = 0; j < n; ++j)
    list.offsets[j + 1] = list.offsets[j] + (start[j] ? static_cast<Index>(start[j][1]) : 0);
  list.neighbours.reserve(static_cast<std::size_t>(list.offsets.back()));
  for (std::size_t j = 0; j < n; ++j)
    if (start[j])
      list.neighbours.insert(list.neighbours.end(), start[j] + 2,
                             start[j] + 2 + static_cast<std::size_t>(start[j][1]));
  return list;
}

void reown_particles(State& s, std::size_t domain) {
  const Domain& d = domain_of(s, domain);
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
