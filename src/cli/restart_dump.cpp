#include "cli/restart_dump.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <fstream>

#include "core/binary_archive.hpp"
#include "solver/restart.hpp"

namespace mcdyna::cli {

namespace {

// The file opens with these bytes (no length before them, so any other file fails here first).
constexpr std::array<char, 20> kMagic = {'m', 'c', 'd', 'y', 'n', 'a', ' ', 'r', 'e', 's',
                                         't', 'a', 'r', 't', ' ', 'd', 'u', 'm', 'p', '\n'};
constexpr std::uint32_t kVersion = 2;  // 2: the layout string after the version
constexpr const char* kEnd = "end of dump";

void fnv1a(std::uint64_t& h, std::string_view bytes) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
}

}  // namespace

std::string deck_fingerprint(const core::SourceFiles& files, const std::string& options) {
  std::uint64_t h = 14695981039346656037ULL;
  for (std::size_t i = 1; i < files.size(); ++i) {  // index 0: "no file"
    fnv1a(h, files.file(static_cast<std::uint32_t>(i)).text);
    fnv1a(h, std::string_view("\0", 1));
  }
  fnv1a(h, options);
  return fmt::format("{:016x}", h);
}

void write_dump(const std::filesystem::path& path, const std::string& fingerprint,
                const solver::State& state, const solver::ResumePoint& point,
                const io::OutputsResume& outputs) {
  const std::filesystem::path part = path.string() + ".part";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", part.string()));
    core::OutArchive ar(out);
    std::array<char, 20> magic = kMagic;
    std::string print = fingerprint, end = kEnd;
    std::uint32_t version = kVersion;
    double time = state.time;
    long cycle = state.cycle;
    std::string layout = solver::dump_layout();
    ar(magic, version, layout, print, time, cycle);
    solver::save_resume_point(ar, point);
    solver::save_state(ar, state);
    ar(const_cast<io::OutputsResume&>(outputs), end);  // one member list for both directions
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write {} (disk full?)", part.string()));
  }
  std::filesystem::rename(part, path);
}

LoadedDump read_dump(const std::filesystem::path& path, const std::string& fingerprint,
                     solver::State& state) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!in || ec)
    throw std::runtime_error(fmt::format("cannot read the restart dump {}", path.string()));
  core::InArchive ar(in, size);
  LoadedDump d;
  try {
    std::array<char, 20> magic{};
    std::uint32_t version = 0;
    if (size < magic.size()) throw core::ArchiveError("not an mcdyna restart dump");
    ar(magic);
    if (magic != kMagic) throw core::ArchiveError("not an mcdyna restart dump");
    ar(version);
    if (version != kVersion)
      throw core::ArchiveError(
          fmt::format("dump format {} (this mcdyna reads {})", version, kVersion));
    std::string layout, print;
    double time = 0.0;
    long cycle = 0;
    ar(layout);
    if (layout != solver::dump_layout())
      throw core::ArchiveError(
          "written by an mcdyna build whose solver state differs from this one's (restart with "
          "the binary that wrote it)");
    ar(print, time, cycle);
    if (print != fingerprint)
      throw core::ArchiveError(
          "written from another deck or with other --spg-* options (a restart needs the deck and "
          "options of the run that wrote the dump, unchanged)");
    solver::load_resume_point(ar, d.point);
    solver::load_state(ar, state);
    std::string end;
    ar(d.outputs, end);
    if (end != kEnd) throw core::ArchiveError("corrupt dump (no end marker)");
  } catch (const core::ArchiveError& e) {
    throw std::runtime_error(fmt::format("restart dump {}: {}", path.string(), e.what()));
  }
  return d;
}

DumpSchedule::DumpSchedule(const model::OutputRequests& requests, std::filesystem::path dir)
    : dir_(std::move(dir)) {
  if (requests.d3dump) d3dump_cycles_ = requests.d3dump->cycles;
  if (requests.runrsf) {
    runrsf_cycles_ = requests.runrsf->cycles;
    runrsf_files_ = requests.runrsf->files;
  }
  // A restarted run continues the d3dump family after the highest number present.
  for (int k = 1; k < 100; ++k)
    if (std::filesystem::exists(dir_ / fmt::format("d3dump{:02d}", k))) next_d3dump_ = k + 1;
}

bool DumpSchedule::due(long cycle, bool interrupted) {
  pending_.clear();
  if (d3dump_cycles_ > 0 && cycle % d3dump_cycles_ == 0)
    pending_.push_back(dir_ / fmt::format("d3dump{:02d}", next_d3dump_++));
  if ((runrsf_cycles_ > 0 && cycle % runrsf_cycles_ == 0) || interrupted) {
    const int k = runrsf_written_++ % runrsf_files_ + 1;
    pending_.push_back(
        dir_ / (runrsf_files_ == 1 ? std::string("runrsf") : fmt::format("runrsf{:02d}", k)));
  }
  return !pending_.empty();
}

std::vector<std::filesystem::path> DumpSchedule::take() {
  return std::move(pending_);
}

}  // namespace mcdyna::cli
