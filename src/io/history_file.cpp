#include "io/history_file.hpp"

#include <chrono>
#include <ctime>
#include <stdexcept>

namespace mcdyna::io {

namespace {

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
    : name_(name) {
  const std::filesystem::path ascii_path = place.dir / name, csv_path = place.dir / (name + ".csv");
  if (const HistoryResume* r = find_resume(place, name)) {
    // A restarted run continues the files as they were at the dump: what a run stopped later
    // wrote past that point is cut off.
    ascii_ = RecordFile::continue_at(ascii_path, r->ascii_bytes);
    csv_ = RecordFile::continue_at(csv_path, r->csv_bytes);
    holding_ = true;
    return;
  }
  ascii_ = RecordFile::create(ascii_path);
  csv_ = RecordFile::create(csv_path);
  ascii(" {}\n", title.substr(0, 72));
  ascii("                         ls-dyna (version mcdyna 0.1)     date {}\n", today());
  csv("{}\n", csv_header);
  flush();
}

HistoryResume HistoryFile::resume_point() const {
  return {name_, ascii_.size(), csv_.size(), saved_values()};
}

void HistoryFile::continue_records(const HistoryResume& r) {
  holding_ = false;
  restore_values(r.values);
}

void HistoryFile::flush() {
  ascii_.commit();
  csv_.commit();
}

void HistoryFile::legend(const std::vector<std::pair<long long, std::string>>& entities) {
  ascii("\n{{BEGIN LEGEND}}\n Entity #        Title\n");
  for (const auto& [id, title] : entities)
    ascii("{:9d}     {}\n", id, title.substr(0, 70));
  ascii("{{END LEGEND}}\n");
}

}  // namespace mcdyna::io
