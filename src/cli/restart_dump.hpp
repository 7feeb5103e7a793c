#pragma once
/// Restart dumps (*DATABASE_BINARY_D3DUMP, *DATABASE_BINARY_RUNRSF, and the running restart file
/// an interrupted run leaves) and reading one back for `mcdyna run DECK --restart FILE`. A dump
/// holds the solver state's changing part (solver/run/restart.hpp), the time loop's resume point
/// and where the outputs stood; the deck's constant data comes from compiling the same deck again,
/// which the dump's fingerprint checks. mcdyna's own format, not LS-DYNA's d3dump.
#include <filesystem>
#include <string>
#include <vector>

#include "core/source.hpp"
#include "io/outputs.hpp"
#include "model/controls.hpp"
#include "solver/run/driver.hpp"
#include "solver/state.hpp"

namespace mcdyna::cli {

/// Identifies the deck and the command-line options that change the physics: every file's text
/// (includes too) and `options`, hashed (FNV-1a, 64 bit).
std::string deck_fingerprint(const core::SourceFiles& files, const std::string& options);

/// Writes the dump to `path` (through path.part and a rename: a dump on disk is always whole).
void write_dump(const std::filesystem::path& path, const std::string& fingerprint,
                const solver::State& state, const solver::ResumePoint& point,
                const io::OutputsResume& outputs);

struct LoadedDump {
  solver::ResumePoint point;
  io::OutputsResume outputs;
};

/// Reads a dump over a state compiled from the same deck. Throws std::runtime_error with a
/// message naming the file (not a dump, another deck or options, truncated).
LoadedDump read_dump(const std::filesystem::path& path, const std::string& fingerprint,
                     solver::State& state);

}  // namespace mcdyna::cli

namespace mcdyna::cli {

/// When and where dumps are written: every CYCL cycles of *DATABASE_BINARY_D3DUMP (a family
/// d3dump01, d3dump02, ...; a restarted run continues the numbers) and of
/// *DATABASE_BINARY_RUNRSF (runrsf, or runrsf01 ... runrsfNR in turn for NR > 1), and a running
/// restart file when a stop signal ends the run, with or without those keywords.
class DumpSchedule {
 public:
  DumpSchedule(const model::OutputRequests& requests, std::filesystem::path dir);
  /// Is a dump due at this cycle? Remembers which files, for take(). `interrupted` (a signal)
  /// writes the running restart file; `requested` (sense switch sw1 or sw3) the next d3dumpNN,
  /// as LS-DYNA does.
  bool due(long cycle, bool interrupted, bool requested = false);
  /// The files due at the last due() that returned true.
  std::vector<std::filesystem::path> take();

 private:
  std::filesystem::path dir_;
  long d3dump_cycles_ = 0, runrsf_cycles_ = 0;
  int runrsf_files_ = 1;
  int next_d3dump_ = 1, runrsf_written_ = 0;
  std::vector<std::filesystem::path> pending_;
};

}  // namespace mcdyna::cli
