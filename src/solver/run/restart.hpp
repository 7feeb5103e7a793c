#pragma once
/// Restart dumps of the solver state (*DATABASE_BINARY_D3DUMP / RUNRSF, `--restart`): what changes
/// during a run, bit for bit, so a run continued from a dump is identical to one that never
/// stopped. What only the deck defines (curves, materials, parts, time controls, body loads) is
/// not dumped: a restart compiles the same deck again and reads the dump over it (the dump
/// carries the deck's fingerprint, cli/restart_dump.cpp).
///
/// The dump is made of sections, each checksummed on its own so that a damaged dump says which
/// part is damaged: the nodes, then one per block that has something changing (Block::save, in
/// the blocks' order, named by the block), then the clock and the energies.
#include <string>
#include <vector>

#include "core/binary_archive.hpp"
#include "solver/run/driver.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// The names of the state's dump sections, in order.
std::vector<std::string> state_sections(const State& state);

/// Writes / reads section `section` (an index into state_sections()) of the state's changing
/// part.
void save_state_section(core::OutArchive& ar, const State& state, std::size_t section);
void load_state_section(core::InArchive& ar, State& state, std::size_t section);

/// The sizes of the dumped structs, as text: a dump written by a build whose structs differ
/// (a member added or removed) is refused instead of being misread.
std::string dump_layout(const State& state);

/// The time loop's own values at the top of a cycle (driver.hpp ResumePoint).
void save_resume_point(core::OutArchive& ar, const ResumePoint& point);
void load_resume_point(core::InArchive& ar, ResumePoint& point);

}  // namespace mcdyna::solver
