#include "core/source.hpp"

#include <algorithm>

namespace mcdyna::core {

SourceLoc SourceLoc::with_columns(int begin, int end) const {
  SourceLoc loc = *this;
  loc.col_begin = static_cast<std::uint16_t>(std::clamp(begin, 0, 65535));
  loc.col_end = static_cast<std::uint16_t>(std::clamp(end, 0, 65535));
  return loc;
}

SourceFiles::SourceFiles() {
  files_.push_back(std::make_unique<SourceFile>(SourceFile{"<command line>", "", {}}));
}

std::uint32_t SourceFiles::add(std::filesystem::path path, std::string text) {
  auto f = std::make_unique<SourceFile>(SourceFile{std::move(path), std::move(text), {}});
  f->line_starts.reserve(f->text.size() / 40 + 1);
  f->line_starts.push_back(0);
  const std::string& t = f->text;
  for (std::size_t i = t.find('\n'); i != std::string::npos; i = t.find('\n', i + 1)) {
    if (i + 1 < t.size()) f->line_starts.push_back(static_cast<std::uint32_t>(i + 1));
  }
  files_.push_back(std::move(f));
  return static_cast<std::uint32_t>(files_.size() - 1);
}

std::string_view SourceFiles::line_text(std::uint32_t file, std::uint32_t line) const {
  if (file >= files_.size() || line == 0) return {};
  const SourceFile& f = *files_[file];
  if (line > f.line_starts.size()) return {};
  const std::size_t begin = f.line_starts[line - 1];
  std::size_t end = f.text.find('\n', begin);
  if (end == std::string::npos) end = f.text.size();
  if (end > begin && f.text[end - 1] == '\r') --end;
  return std::string_view(f.text).substr(begin, end - begin);
}

}  // namespace mcdyna::core
