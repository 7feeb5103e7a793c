#pragma once
/// An SPG part over several processes (issue 25, manual/architecture.md "Many processes"). Every
/// process holds the whole part; parallel::ParticleShare says what it computes:
///   - the stress of its `stressed` rows: those of its own particles and every row that holds one
///     of them (the transpose), since f_I = -sum_J (w sigma F^-T)_J grad phi_I(X_J) runs over
///     the rows J holding I. Rows on a border are computed by each process that needs them,
///     from the same values, so every particle's force is gathered in the order of one process;
///   - the velocities of its own particles (Eqs. 29-30 and 13), after the accelerations of the
///     particles in their rows (`row_ghosts`) and then the u-hat of the particles whose rows hold
///     them (`column_ghosts`) arrived from their owners.
/// The x and v of the nodes the stressed rows read come with the hexahedra's ghost nodes
/// (parallel::Halo). At a kernel check every process first receives what the check reads of
/// every particle (`synchronise`, Scope::check: positions, F-hat, pressure, ...), so bond
/// failure, the choice of rows and the smoothed masses run whole and alike on every process;
/// each process builds an equal share of the renewed rows and all share them (`share_rows`).
/// After a renewal the free particles are bisected again by their current positions
/// (`reown_particles`): particles that flowed across a border change process there, and each
/// process receives everything the particles it now reads carry (`migrate`).
#include <chrono>
#include <cstddef>

#include "solver/state.hpp"

namespace mcdyna::solver::spg {

/// Whether a part can be split: MC-SPG or plain nodal integration, with the nearest-neighbour
/// step (PDAMP included: its pairs read the previous u-hat of the row partners, which then come
/// with the column ghosts). ITB 1's stabilisation and the eigenvalue step (power iteration)
/// read products across the whole part; such a part is still computed whole on every process
/// (its nodes replicated, SpgBlock::mark_replicated).
bool splittable(const Domain& d);

/// The index of `d` in s.spg.
std::size_t domain_index(const State& s, const Domain& d);

/// The share of part `domain` from the node owners (s.ownership.owner), with its exchange plans.
/// Collective.
void share_particles(State& s, std::size_t domain);

/// Runs `exchange` and charges its wall time to the part's exchange seconds (when split).
template <class Exchange>
void timed_exchange(State& s, std::size_t domain, Exchange&& exchange) {
  const auto start = std::chrono::steady_clock::now();
  exchange();
  if (parallel::ParticleShare* share = s.ownership.split_part(domain))
    share->exchange_seconds += seconds_since(start);
}

/// What a synchronisation carries, from each particle's owner.
enum class Scope {
  masses,      ///< to every process: the masses (after DT2MS added mass on owned rows)
  check,       ///< to every process: what a kernel check and renewal read (x, F-hat, p, V, ...)
  everything,  ///< to every process: every value (before a restart dump)
  to_root,     ///< every value, to process 0 only (before a d3plot state)
  histories    ///< to process 0 only, what the histories read: masses, energies, u-hat
};

/// Every process (process 0 for `to_root`) receives the values of `scope` of every particle
/// from its owner. Collective.
void synchronise(State& s, std::size_t domain, Scope scope);

/// After the share was rebuilt with new owners or rows: each process receives every value of
/// the particles it now reads (its stressed rows and the particles in them) from their
/// `previous_owner`, who held them whole. Collective.
void migrate(State& s, std::size_t domain, const std::vector<int>& previous_owner);

/// `width` values per particle, stored one particle after the other from `values`: every
/// process receives those of each particle from its owner. Collective.
void share_columns(const State& s, std::size_t domain, double* values, int width);

/// The process that builds each of a renewal's flagged rows (-1: not flagged): the flagged
/// rows in particle order, in equal consecutive shares.
std::vector<int> row_builders(const std::vector<std::uint8_t>& flagged, int processes);

/// A renewal's fresh rows (renewal.cpp): `fresh`, `shape` and `degenerate` hold the rows this
/// process built (`builder`, from row_builders); on return they hold every flagged row, in
/// particle order, as one process builds them (the other rows empty). Collective.
void share_rows(const State& s, const std::vector<int>& builder, NeighbourList& fresh,
                ShapeFunctions& shape, std::vector<Index>& degenerate);

/// After a renewal (with every process holding every value): the particles whose node no hexa,
/// SPC or prescribed motion shares are bisected again by their current positions over the
/// processes; their nodes' owners change in s.ownership.owner. The caller rebuilds the share
/// and moves s.ownership.generation on, after which the time loop rebuilds the halo.
void reown_particles(State& s, std::size_t domain);

}  // namespace mcdyna::solver::spg
