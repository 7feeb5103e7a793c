#pragma once
/// Source files of a deck and locations inside them, for diagnostics that echo the offending line.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mcdyna::core {

/// A place in a deck: file index into SourceFiles, 1-based line, 1-based inclusive column range
/// (0 when the whole line is meant). Kept small because every node and element carries one.
struct SourceLoc {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint16_t col_begin = 0;
  std::uint16_t col_end = 0;

  [[nodiscard]] bool valid() const { return line != 0; }
  [[nodiscard]] SourceLoc with_columns(int begin, int end) const;
};

/// One file's text, kept for the whole run so diagnostics can echo lines.
struct SourceFile {
  std::filesystem::path path;              ///< as given or resolved; printed in diagnostics
  std::string text;                        ///< whole file content
  std::vector<std::uint32_t> line_starts;  ///< byte offset of each line's first character
};

/// All files read for one deck. Index 0 is reserved for "no file" (command-line problems).
class SourceFiles {
 public:
  SourceFiles();
  /// Adds a file whose content is already read; returns its index.
  std::uint32_t add(std::filesystem::path path, std::string text);
  [[nodiscard]] const SourceFile& file(std::uint32_t index) const { return *files_[index]; }
  [[nodiscard]] std::size_t size() const { return files_.size(); }
  /// Text of a 1-based line without its end-of-line characters; empty if out of range.
  [[nodiscard]] std::string_view line_text(std::uint32_t file, std::uint32_t line) const;

 private:
  // unique_ptr: string_views into a file's text stay valid while more files are added.
  std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace mcdyna::core
