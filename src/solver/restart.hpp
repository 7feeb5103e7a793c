#pragma once
/// Restart dumps of the solver state (*DATABASE_BINARY_D3DUMP / RUNRSF, `--restart`): what changes
/// during a run, bit for bit, so a run continued from a dump is identical to one that never
/// stopped. What only the deck defines (curves, materials, parts, time controls, body loads) is
/// not dumped: a restart compiles the same deck again and reads the dump over it (the dump
/// carries the deck's fingerprint, cli/restart_dump.cpp).
#include <array>
#include <string>
#include <string_view>

#include "core/binary_archive.hpp"
#include "solver/driver.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// The sections the state's changing part is dumped in, in order (each checksummed on its own,
/// so a damaged dump says which part is damaged).
inline constexpr std::array<std::string_view, 8> kStateSections = {
    "nodes",       "solids",   "SPG domains",      "rigid bodies", "constraints and motions",
    "rigid walls", "contacts", "time and energies"};

/// Writes / reads section `section` (an index into kStateSections) of the state's changing part.
void save_state_section(core::OutArchive& ar, const State& state, std::size_t section);
void load_state_section(core::InArchive& ar, State& state, std::size_t section);

/// The sizes of the dumped structs, as text: a dump written by a build whose structs differ
/// (a member added or removed) is refused instead of being misread.
std::string dump_layout();

/// The time loop's own values at the top of a cycle (driver.hpp ResumePoint).
void save_resume_point(core::OutArchive& ar, const ResumePoint& point);
void load_resume_point(core::InArchive& ar, ResumePoint& point);

}  // namespace mcdyna::solver
