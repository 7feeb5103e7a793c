#include "core/diagnostics.hpp"

#include <algorithm>
#include <ostream>

namespace mcdyna::core {

void Diagnostics::report(Severity severity, SourceLoc loc, std::string message) {
  if (severity == Severity::error) ++errors_;
  if (severity == Severity::warning) ++warnings_;
  items_.push_back(Diagnostic{severity, loc, std::move(message)});
}

namespace {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::note:
      return "note";
    case Severity::warning:
      return "warning";
    case Severity::error:
      return "error";
  }
  return "error";
}

// Replaces control characters and non-ASCII bytes so a garbage line cannot corrupt a terminal.
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text)
    out.push_back(c >= 0x20 && c < 0x7f ? static_cast<char>(c) : '?');
  return out;
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d, const SourceFiles& files) {
  std::string head;
  if (d.loc.file != 0 && d.loc.file < files.size()) {
    head = files.file(d.loc.file).path.string();
    if (d.loc.line != 0) head += fmt::format(":{}", d.loc.line);
    if (d.loc.col_begin != 0) {
      head += fmt::format(":{}", d.loc.col_begin);
      if (d.loc.col_end > d.loc.col_begin) head += fmt::format("-{}", d.loc.col_end);
    }
    head += ": ";
  } else {
    head = "mcdyna: ";
  }
  std::string out = fmt::format("{}{}: {}\n", head, severity_name(d.severity), d.message);
  const std::string_view line = files.line_text(d.loc.file, d.loc.line);
  if (d.loc.file != 0 && d.loc.line != 0) {
    out += fmt::format("  {}\n", printable(line.substr(0, 240)));
    if (d.loc.col_begin != 0) {
      const int begin = d.loc.col_begin;
      const int end = std::max<int>(d.loc.col_end, begin);
      out +=
          fmt::format("  {}{}\n", std::string(begin - 1, ' '), std::string(end - begin + 1, '^'));
    }
  }
  return out;
}

void print_diagnostics(std::ostream& out, const Diagnostics& diags, const SourceFiles& files,
                       std::size_t limit) {
  std::size_t shown = 0;
  for (const Diagnostic& d : diags.all()) {
    if (limit != 0 && shown == limit) break;
    out << format_diagnostic(d, files);
    ++shown;
  }
  if (shown < diags.all().size()) {
    out << fmt::format("mcdyna: {} more diagnostics not shown (use --max-messages 0 to see all)\n",
                       diags.all().size() - shown);
  }
}

}  // namespace mcdyna::core
