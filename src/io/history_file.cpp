#include "io/history_file.hpp"

#include <chrono>
#include <ctime>
#include <stdexcept>

namespace mcdyna::io {

namespace {
std::FILE* open_or_throw(const std::filesystem::path& p) {
  std::FILE* f = std::fopen(p.string().c_str(), "w");
  if (f == nullptr) throw std::runtime_error(fmt::format("cannot open {} for writing", p.string()));
  return f;
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%m/%d/%Y", std::localtime(&now));
  return buf;
}
}  // namespace

HistoryFile::HistoryFile(const std::filesystem::path& dir, const std::string& name,
                         const std::string& title, const std::string& csv_header)
    : name_(name), ascii_(open_or_throw(dir / name)), csv_(open_or_throw(dir / (name + ".csv"))) {
  ascii(" {}\n", title.substr(0, 72));
  ascii("                         ls-dyna (version mcdyna 0.1)     date {}\n", today());
  csv("{}\n", csv_header);
  flush();
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
