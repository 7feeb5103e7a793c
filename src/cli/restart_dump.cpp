#include "cli/restart_dump.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <fstream>

#include "core/binary_archive.hpp"
#include "core/diagnostics.hpp"
#include "io/checked_file.hpp"
#include "solver/run/restart.hpp"

namespace mcdyna::cli {

namespace {

// The file opens with these bytes (no length before them, so any other file fails here first),
// then the format version, then checksummed sections: each its name, its size, the checksum of
// its bytes (core::checksum) and the bytes. A flipped byte anywhere is a refusal naming the
// section, never a run from a damaged state.
constexpr std::array<char, 20> kMagic = {'m', 'c', 'd', 'y', 'n', 'a', ' ', 'r', 'e', 's',
                                         't', 'a', 'r', 't', ' ', 'd', 'u', 'm', 'p', '\n'};
constexpr std::uint32_t kVersion = 9;  // 2: the layout string; 3: checksummed sections;
                                       // 4: the node owners of a run over several processes;
                                       // 5: shells and nodal rotations; 6: joints; 7: beams, welds;
                                       // 8: force transducers, SOFT 2, C0 triangles;
                                       // 9: the d3plot family's position
constexpr std::string_view kHeader = "header", kResume = "resume point", kOutputs = "outputs",
                           kEnd = "end of dump";

void fnv1a(std::uint64_t& h, std::string_view bytes) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
}

// Appends one section: name, size, checksum, bytes.
template <class Write>
void put_section(std::string& file, std::string_view name, Write&& write) {
  std::string bytes;
  core::OutArchive ar(bytes);
  write(ar);
  std::string label(name);
  std::uint64_t size = bytes.size(), sum = core::checksum(bytes);
  core::OutArchive head(file);
  head(label, size, sum);
  file += bytes;
}

// Reads the next section, which must be `name`, checks its sum and hands its bytes to `read`,
// which must use them all.
template <class Read>
void get_section(core::InArchive& file, std::string_view whole, std::string_view name,
                 Read&& read) {
  std::string label;
  std::uint64_t size = 0, sum = 0;
  file(label, size, sum);
  if (label != name)
    throw core::ArchiveError(fmt::format("corrupt dump: section '{}' expected, found '{}'", name,
                                         core::excerpt(label, 40)));
  if (size > file.left()) throw core::ArchiveError("the dump ends early (truncated file?)");
  const std::string_view bytes = whole.substr(whole.size() - file.left(), size);
  if (core::checksum(bytes) != sum)
    throw core::ArchiveError(fmt::format(
        "section '{}' is damaged (its checksum does not match: the file changed after it was "
        "written)",
        name));
  file.skip(size);
  core::InArchive ar(bytes);
  read(ar);
  if (ar.left() != 0)
    throw core::ArchiveError(fmt::format(
        "section '{}' does not match this mcdyna's layout ({} bytes left over)", name, ar.left()));
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
  std::string file(kMagic.begin(), kMagic.end());
  std::uint32_t version = kVersion;
  core::OutArchive prologue(file);
  prologue(version);
  put_section(file, kHeader, [&](core::OutArchive& ar) {
    std::string layout = solver::dump_layout(state), print = fingerprint;
    double time = state.time;
    long cycle = state.cycle;
    ar(layout, print, time, cycle);
  });
  put_section(file, kResume, [&](core::OutArchive& ar) { solver::save_resume_point(ar, point); });
  const std::vector<std::string> sections = solver::state_sections(state);
  for (std::size_t k = 0; k < sections.size(); ++k)
    put_section(file, sections[k],
                [&](core::OutArchive& ar) { solver::save_state_section(ar, state, k); });
  put_section(file, kOutputs, [&](core::OutArchive& ar) {
    ar(const_cast<io::OutputsResume&>(outputs));  // one member list for both directions
  });
  put_section(file, kEnd, [](core::OutArchive&) {});
  io::write_file_atomically(path, file);  // through path.part and a rename: always whole
}

LoadedDump read_dump(const std::filesystem::path& path, const std::string& fingerprint,
                     solver::State& state) {
  // A FIFO or device would block the read (or never end); a dump is a regular file.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error(
        fmt::format("cannot read the restart dump {}: {}", path.string(),
                    std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::string whole(ec ? 0 : size, '\0');
  if (!in || ec || !in.read(whole.data(), static_cast<std::streamsize>(whole.size())))
    throw std::runtime_error(fmt::format("cannot read the restart dump {}", path.string()));
  core::InArchive ar(whole);
  LoadedDump d;
  try {
    std::array<char, 20> magic{};
    std::uint32_t version = 0;
    if (whole.size() < magic.size()) throw core::ArchiveError("not an mcdyna restart dump");
    ar(magic);
    if (magic != kMagic) throw core::ArchiveError("not an mcdyna restart dump");
    ar(version);
    if (version != kVersion)
      throw core::ArchiveError(
          fmt::format("dump format {} (this mcdyna reads {})", version, kVersion));
    get_section(ar, whole, kHeader, [&](core::InArchive& h) {
      std::string layout, print;
      double time = 0.0;
      long cycle = 0;
      h(layout);
      if (layout != solver::dump_layout(state))
        throw core::ArchiveError(
            "written by an mcdyna build whose solver state differs from this one's (restart "
            "with the binary that wrote it)");
      h(print, time, cycle);
      if (print != fingerprint)
        throw core::ArchiveError(
            "written from another deck or with other --spg-* options (a restart needs the deck "
            "and options of the run that wrote the dump, unchanged)");
    });
    get_section(ar, whole, kResume,
                [&](core::InArchive& r) { solver::load_resume_point(r, d.point); });
    const std::vector<std::string> sections = solver::state_sections(state);
    for (std::size_t k = 0; k < sections.size(); ++k)
      get_section(ar, whole, sections[k],
                  [&](core::InArchive& r) { solver::load_state_section(r, state, k); });
    get_section(ar, whole, kOutputs, [&](core::InArchive& r) { r(d.outputs); });
    get_section(ar, whole, kEnd, [](core::InArchive&) {});
    if (ar.left() != 0)
      throw core::ArchiveError(fmt::format("corrupt dump ({} bytes after its end)", ar.left()));
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
  // A restarted run continues the d3dump family after the highest number present (over
  // several processes, process 0's file d3dumpNN.0000 stands for the family member).
  for (int k = 1; k < 100; ++k)
    if (std::filesystem::exists(dir_ / fmt::format("d3dump{:02d}", k)) ||
        std::filesystem::exists(dir_ / fmt::format("d3dump{:02d}.0000", k)))
      next_d3dump_ = k + 1;
}

bool DumpSchedule::due(long cycle, bool interrupted, bool requested) {
  pending_.clear();
  if ((d3dump_cycles_ > 0 && cycle % d3dump_cycles_ == 0) || requested)
    pending_.push_back(dir_ / fmt::format("d3dump{:02d}", next_d3dump_++));
  if ((runrsf_cycles_ > 0 && cycle % runrsf_cycles_ == 0) || (interrupted && !requested)) {
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
