#pragma once
/// Keyword reference text from the schemas: `mcdyna keywords [NAME]` and manual/keywords/*.md.
#include <filesystem>
#include <iosfwd>

#include "deck/registry.hpp"

namespace mcdyna::cli {

/// One line per keyword: name, aliases, group, summary.
void print_keyword_list(std::ostream& out, const deck::Registry& registry);

/// Card layout of one keyword as text (markdown = false) or a Markdown page.
void print_keyword_layout(std::ostream& out, const deck::KeywordSchema& schema, bool markdown);

/// Writes DIR/<keyword>.md for every schema, DIR/README.md as the index and
/// DIR/classification.md from the classification table. Returns false on an I/O error.
bool write_keyword_pages(const std::filesystem::path& dir, const deck::Registry& registry);

}  // namespace mcdyna::cli
