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
/// (parallel::Halo). At a kernel check every process first receives every particle's values
/// from its owner (`synchronise`), so the bond failure, the renewal and the smoothed masses run
/// whole and alike on every process; after a renewal the free particles are bisected again by
/// their current positions (`reown_particles`): particles that flowed across a border change
/// process there, with everything they carry, because every process already holds it.
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

/// Every process receives every particle's values (node x and v, masses, velocities, material
/// point, kernel fields of the last pass) from the particle's owner. With `masses_only`, the
/// masses alone (after DT2MS added mass on owned rows). Collective.
void synchronise(State& s, std::size_t domain, bool masses_only = false);

/// After a renewal (with every process holding every value): the particles whose node no hexa,
/// SPC or prescribed motion shares are bisected again by their current positions over the
/// processes; their nodes' owners change in s.ownership.owner. The caller rebuilds the share
/// and moves s.ownership.generation on, after which the time loop rebuilds the halo.
void reown_particles(State& s, std::size_t domain);

}  // namespace mcdyna::solver::spg
