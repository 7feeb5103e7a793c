#include "core/diagnostics.hpp"

#include <algorithm>
#include <ostream>

namespace mcdyna::core {

namespace {

// A message quotes the deck's text ("got \"...\"", an expression); a field of 70 kB or an
// expression of 300,000 operators must not become a message of that size. The head and the
// tail (where "at position N" or a hint stands) are kept.
constexpr std::size_t kMessageHead = 300, kMessageTail = 200;

std::string clipped(std::string message) {
  if (message.size() <= kMessageHead + kMessageTail + 40) return message;
  const std::size_t cut = message.size() - kMessageHead - kMessageTail;
  return message.substr(0, kMessageHead) + fmt::format(" [... {} characters ...] ", cut) +
         message.substr(message.size() - kMessageTail);
}

}  // namespace

std::string excerpt(std::string_view text, std::size_t max) {
  if (text.size() <= max) return std::string(text);
  return fmt::format("{}... ({} characters)", text.substr(0, max), text.size());
}

void Diagnostics::report(Severity severity, SourceLoc loc, std::string message) {
  if (severity == Severity::error) ++errors_;
  if (severity == Severity::warning) ++warnings_;
  items_.push_back(Diagnostic{severity, loc, clipped(std::move(message))});
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
    // At most kEcho characters of the line, starting a little before the marked columns when
    // they lie further right ("..." says the line starts earlier); the caret stays in the window.
    constexpr std::size_t kEcho = 240, kLeadIn = 40;
    const std::size_t begin = d.loc.col_begin == 0 ? 0 : d.loc.col_begin - 1;
    const std::size_t from = begin + 1 > kEcho ? begin - kLeadIn : 0;
    const std::string_view lead = from > 0 ? "..." : "";
    out +=
        fmt::format("  {}{}\n", lead, printable(line.substr(std::min(from, line.size()), kEcho)));
    if (d.loc.col_begin != 0) {
      const std::size_t end = std::max<std::size_t>(d.loc.col_end, d.loc.col_begin) - 1;
      const std::size_t last = std::min(end, from + kEcho - 1);
      out += fmt::format("  {}{}\n", std::string(lead.size() + begin - from, ' '),
                         std::string(last - begin + 1, '^'));
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
