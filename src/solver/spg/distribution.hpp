#pragma once
/// An SPG part over several processes (issue 25, manual/architecture.md "Many processes").
/// parallel::ParticleShare says what a process computes:
///   - the stress of its `stressed` rows: those of its own particles and every row that holds one
///     of them (the transpose), since f_I = -sum_J (w sigma F^-T)_J grad phi_I(X_J) runs over
///     the rows J holding I. Rows on a border are computed by each process that needs them,
///     from the same values, so every particle's force is gathered in the order of one process;
///   - the velocities of its own particles (Eqs. 29-30 and 13), after the accelerations of the
///     particles in their rows (`row_ghosts`) and then the u-hat of the particles whose rows hold
///     them (`column_ghosts`) arrived from their owners.
/// A process keeps the kernel rows (lists, shape functions) of its stressed rows only; the other
/// rows are empty there, and the transposes are complete for its own particles only. The
/// per-particle values (masses, smoothed masses, pinned, supports, bonds) are the same on every
/// process. The x and v of the nodes the stressed rows read come with the hexahedra's ghost
/// nodes (parallel::Halo). At a kernel check every process first receives what the check reads
/// of every particle (`synchronise`, Scope::check: positions, F-hat, pressure, ...); each decides
/// the renewal of its own rows; the free particles are bisected again by their current positions
/// (`reown_particles`); each process builds an equal share of the renewed rows and sends each to
/// the processes that read it under the new owners, which also receive the unchanged rows they
/// read from now on from the rows' previous owners (`redistribute_rows`); each process then
/// receives everything the particles it now reads carry (`migrate`).
#include <chrono>
#include <cstddef>

#include "solver/spg/spg_parts.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver::spg {

/// Whether a part can be split: MC-SPG or plain nodal integration (PDAMP included: its pairs
/// read the previous u-hat of the row partners, which then come with the column ghosts), with
/// either step estimate (the eigenvalue step's power iteration forms its products on each
/// process's rows, frequency.cpp). ITB 1's stabilisation reads second derivatives across the
/// whole part; such a part is still computed whole on every process (its nodes replicated,
/// SpgBlock::mark_replicated).
bool splittable(const Domain& d);

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
/// `previous_owner`, who held them whole, with their nodes' forces summed so far in `force`.
/// Collective.
void migrate(State& s, std::size_t domain, const std::vector<int>& previous_owner,
             Eigen::Matrix3Xd& force);

/// `width` values per particle, stored one particle after the other from `values`: every
/// process receives those of each particle from its owner. Collective.
void share_columns(const State& s, std::size_t domain, double* values, int width);

/// Columns of a 3 x count field from the particles' owners into the ghosts of `plan` (one of
/// `share`'s), timed as exchange.
void exchange_columns(parallel::ParticleShare& share, parallel::ExchangePlan& plan,
                      Eigen::Matrix3Xd& field);

/// The process that builds each of a renewal's flagged rows (-1: not flagged): the flagged
/// rows in particle order, in equal consecutive shares.
std::vector<int> row_builders(const std::vector<std::uint8_t>& flagged, int processes);

/// The degenerate rows (shape_functions) of every process, ascending. Collective.
std::vector<Index> share_degenerate(const State& s, const std::vector<Index>& mine);

/// The rows this process reads after a renewal (s.ownership.owner is already the new owners'),
/// into `incoming` with `take` set for each row the renewal's merge takes from it: the flagged
/// rows (builder >= 0) it reads, from their builders (`fresh` holds the rows built here); the
/// unchanged rows it reads from now on, from their previous owners (the share, not yet
/// rebuilt, still has them), with their per-row values
/// (kernel length, renewal volume, mode residual); and empty rows where it no longer reads a
/// row. Rows it read before and still reads, unchanged, are left to the current lists
/// (take 0). Collective.
void redistribute_rows(State& s, std::size_t domain, const std::vector<int>& builder,
                       const NeighbourList& fresh, const ShapeFunctions& fresh_shape,
                       NeighbourList& incoming, ShapeFunctions& incoming_shape,
                       std::vector<std::uint8_t>& take);

/// After the share was first built (or rebuilt on a restart): drops the rows this process does
/// not read and rebuilds the transposes, complete for its own particles (renewal.cpp).
/// Collective.
void keep_read_rows(State& s, Domain& d);

/// The rows of every process's own particles, on process 0 (empty rows elsewhere), for the
/// run's summary (neighbour pairs and separate pieces). Collective.
NeighbourList rows_on_root(const State& s, std::size_t domain);

/// At a renewal (after Scope::check: every process holds every position): the particles whose
/// node no hexa, SPC or prescribed motion shares are bisected again by their current positions
/// over the processes; their nodes' owners change in s.ownership.owner. The renewal then
/// redistributes the rows and rebuilds the share; the caller migrates the particle values and
/// moves s.ownership.generation on, after which the time loop rebuilds the halo.
void reown_particles(State& s, std::size_t domain);

}  // namespace mcdyna::solver::spg
