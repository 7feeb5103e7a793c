#include "io/history_file.hpp"

#include <chrono>
#include <ctime>
#include <stdexcept>

namespace mcdyna::io {

namespace {
std::FILE* open_or_throw(const std::filesystem::path& p, const char* mode) {
  std::FILE* f = std::fopen(p.string().c_str(), mode);
  if (f == nullptr) throw std::runtime_error(fmt::format("cannot open {} for writing", p.string()));
  return f;
}

// A restarted run continues the file as it was at the dump: what a run killed later wrote past
// that point is cut off. A file shorter than at the dump is not the one the dump continues.
std::FILE* continue_file(const std::filesystem::path& p, std::uint64_t bytes) {
  std::error_code ec;
  const std::uintmax_t have = std::filesystem::file_size(p, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot continue {}: it is missing", p.string()));
  if (have < bytes)
    throw std::runtime_error(
        fmt::format("cannot continue {}: it is shorter ({} bytes) than when the restart dump was "
                    "written ({} bytes)",
                    p.string(), have, bytes));
  std::filesystem::resize_file(p, bytes);
  return open_or_throw(p, "a");
}

const HistoryResume* find_resume(const HistoryPlace& place, const std::string& name) {
  if (!place.resume) return nullptr;
  for (const HistoryResume& r : *place.resume)
    if (r.name == name) return &r;
  throw std::runtime_error(
      fmt::format("the restart dump has no {} (was it written from this deck?)", name));
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%m/%d/%Y", std::localtime(&now));
  return buf;
}
}  // namespace

HistoryFile::HistoryFile(const HistoryPlace& place, const std::string& name,
                         const std::string& title, const std::string& csv_header)
    : name_(name), ascii_path_(place.dir / name), csv_path_(place.dir / (name + ".csv")) {
  if (const HistoryResume* r = find_resume(place, name)) {
    ascii_.reset(continue_file(ascii_path_, r->ascii_bytes));
    csv_.reset(continue_file(csv_path_, r->csv_bytes));
    holding_ = true;
    return;
  }
  ascii_.reset(open_or_throw(ascii_path_, "w"));
  csv_.reset(open_or_throw(csv_path_, "w"));
  ascii(" {}\n", title.substr(0, 72));
  ascii("                         ls-dyna (version mcdyna 0.1)     date {}\n", today());
  csv("{}\n", csv_header);
  flush();
}

HistoryResume HistoryFile::resume_point() const {
  std::fflush(ascii_.get());
  std::fflush(csv_.get());
  return {name_, std::filesystem::file_size(ascii_path_), std::filesystem::file_size(csv_path_),
          saved_values()};
}

void HistoryFile::continue_records(const HistoryResume& r) {
  holding_ = false;
  restore_values(r.values);
}

void HistoryFile::flush() {
  std::fflush(ascii_.get());
  std::fflush(csv_.get());
}

void HistoryFile::legend(const std::vector<std::pair<long long, std::string>>& entities) {
  ascii("\n{{BEGIN LEGEND}}\n Entity #        Title\n");
  for (const auto& [id, title] : entities)
    ascii("{:9d}     {}\n", id, title.substr(0, 70));
  ascii("{{END LEGEND}}\n");
}

}  // namespace mcdyna::io
