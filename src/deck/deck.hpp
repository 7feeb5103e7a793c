#pragma once
/// A lexed keyword deck: every file read, every keyword block with its data lines, parameters.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/source.hpp"
#include "deck/parameters.hpp"

namespace mcdyna::deck {

/// Card layout family: standard 80 columns, LONG=Y (fields widened to 20), I10=Y (fields widened
/// to 10). Chosen by *KEYWORD for the file or by a '+', '-' or '%' suffix on one keyword.
enum class CardFormat : std::uint8_t { standard, long_format, i10 };

/// Width of a field of `standard` columns in the given format (keywords.md §1.5).
[[nodiscard]] inline int field_width(CardFormat format, int standard) {
  if (format == CardFormat::long_format) return standard > 20 ? standard : 20;
  if (format == CardFormat::i10) return standard > 10 ? standard : 10;
  return standard;
}

/// One non-comment data line of a keyword block.
struct DataLine {
  std::string_view text;  ///< without end-of-line characters
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  [[nodiscard]] core::SourceLoc loc() const { return core::SourceLoc{file, line, 0, 0}; }
};

/// One keyword occurrence: "*NAME ..." and the data lines up to the next keyword.
struct KeywordBlock {
  std::string name;     ///< upper case, without '*' and without a format suffix
  core::SourceLoc loc;  ///< the keyword line
  CardFormat format = CardFormat::standard;
  std::uint32_t scope = 0;       ///< parameter scope of the file it is in
  std::uint32_t first_line = 0;  ///< index into Deck::lines
  std::uint32_t end_line = 0;
  /// The *CASE subcases it belongs to: the *CASE_BEGIN_n blocks around it and a "CID=n" on its
  /// keyword line (empty: the main model, read by every case). deck/cases.hpp selects.
  std::vector<long> subcases;
  [[nodiscard]] std::uint32_t line_count() const { return end_line - first_line; }
};

struct Deck {
  core::SourceFiles files;
  std::vector<DataLine> lines;
  std::vector<KeywordBlock> blocks;
  Parameters parameters;
  std::size_t bytes_read = 0;
};

/// Options of the deck reader.
struct ReadOptions {
  int max_include_depth = 64;
};

/// Reads a deck and everything it includes, collecting parameters and evaluating them. Problems
/// (missing files, include cycles, malformed *KEYWORD arguments …) go to `diags`; never throws
/// for bad input.
/// Why `path` cannot be read as a deck or include ("no such file", "is a directory", "is not a
/// regular file": a FIFO or device would block), or "" when it can be opened as a file.
std::string file_problem(const std::filesystem::path& path);

Deck read_deck(const std::filesystem::path& path, core::Diagnostics& diags,
               const ReadOptions& options = {});

/// Same, for deck text held in memory (tests); `virtual_path` names it in diagnostics and is the
/// base for relative includes.
Deck read_deck_text(std::string text, const std::filesystem::path& virtual_path,
                    core::Diagnostics& diags, const ReadOptions& options = {});

}  // namespace mcdyna::deck
