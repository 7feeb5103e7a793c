// CSV histories (ours and other engineers') and the dispatch to the LS-DYNA ASCII readers.
#include "io/history_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/diagnostics.hpp"
#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::io {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// A history's lines, read one at a time. A line has at most kMaxLine characters, so /dev/zero or
// a binary file is refused at its first line instead of filling memory; a NUL byte is refused
// (it would cut every message that quotes the line); a UTF-8 byte-order mark before the first
// line and the '\r' of CRLF files are dropped.
constexpr std::size_t kMaxLine = 1 << 20;

class TextLines {
 public:
  TextLines(std::istream& in, const std::string& source) : in_(in), source_(source) {}
  /// The next line, or false at the end of the file.
  bool next(std::string& line) {
    line.clear();
    if (!in_) return false;
    int c = 0;
    while ((c = in_.get()) != std::char_traits<char>::eof() && c != '\n') {
      line.push_back(static_cast<char>(c));
      if (line.size() > kMaxLine)
        throw HistoryReadError(
            fmt::format("{}:{}:1: error: a line longer than {} characters: not a history file",
                        source_, number_ + 1, kMaxLine));
    }
    if (c == std::char_traits<char>::eof() && line.empty()) return false;
    ++number_;
    if (number_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (const auto nul = line.find('\0'); nul != std::string::npos)
      throw HistoryReadError(
          fmt::format("{}:{}:{}: error: a NUL byte: not a text file", source_, number_, nul + 1));
    return true;
  }
  /// Lines read so far (the number of the last one).
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::istream& in_;
  const std::string& source_;
  std::size_t number_ = 0;
};

// The separator of a CSV header: comma, else semicolon, else tab.
char csv_separator(const std::string& header) {
  for (const char c : {',', ';', '\t'})
    if (header.find(c) != std::string::npos) return c;
  return ',';
}

// Columns that name an entity rather than hold a value: rows with them are pivoted.
bool is_key_name(const std::string& name) {
  static const std::set<std::string> keys{"contact", "side", "part", "node",    "kind",
                                          "id",      "wall", "mat",  "element", "interface",
                                          "nid",     "pid",  "set",  "segment", "material"};
  std::string lower;
  for (const char c : name)
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return keys.count(lower) > 0;
}

std::string unquote(std::string_view s) {
  s = deck::trim(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return std::string(s);
}

std::optional<double> csv_value(std::string_view field) {
  const std::string s = unquote(field);
  if (s.empty()) return kMissing;
  const std::string u = deck::upper(s);
  if (u == "NAN" || u == "NA" || u == "N/A") return kMissing;
  return deck::parse_real(s);
}

// Column of the start of field `k` in a separated line (1-based, for messages).
std::size_t field_column(const std::string& line, char sep, std::size_t k) {
  std::size_t col = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t next = line.find(sep, col);
    if (next == std::string::npos) return line.size() + 1;
    col = next + 1;
  }
  return col + 1;
}

// A CSV history read row by row: the header row (or, when it is all numbers, column numbers),
// then each row into the table. Rows keyed by entity columns (contact, node, part ...) are
// pivoted into one column per quantity and entity.
class CsvReader {
 public:
  explicit CsvReader(const std::string& source) : source_(source) {}

  /// Takes line `number` of the file; blank lines are skipped.
  void line(const std::string& text, std::size_t number) {
    if (deck::trim(text).empty()) return;
    if (header_.empty()) {
      read_header(text, number);
      if (!numeric_header_) return;
    }
    read_row(text, number);
  }

  HistoryTable finish() {
    if (header_.empty())
      throw HistoryReadError(fmt::format("{}: error: the file is empty", source_));
    return builder_.finish(source_, "csv");
  }

 private:
  void read_header(const std::string& line, std::size_t number) {
    sep_ = csv_separator(line);
    for (const std::string_view h : deck::split(line, sep_))
      header_.push_back(unquote(h));
    std::set<std::string> seen;
    for (std::size_t k = 0; k < header_.size(); ++k) {
      if (header_[k].empty())
        throw HistoryReadError(detail::located_message(source_, number, line,
                                                       field_column(line, sep_, k),
                                                       "empty column name in the header row"));
      if (!seen.insert(header_[k]).second)
        throw HistoryReadError(
            detail::located_message(source_, number, line, field_column(line, sep_, k),
                                    fmt::format("column name '{}' appears twice in the header row",
                                                core::excerpt(header_[k], 40))));
    }
    // A header of numbers is data without a header: name the columns by their index.
    numeric_header_ = std::all_of(header_.begin(), header_.end(), [](const std::string& h) {
      return deck::parse_real(h).has_value();
    });
    key_.assign(header_.size(), false);
    for (std::size_t k = 0; k < header_.size(); ++k) {
      key_[k] = !numeric_header_ && is_key_name(header_[k]);
      keyed_ = keyed_ || key_[k];
    }
    if (numeric_header_)
      for (std::size_t k = 0; k < header_.size(); ++k)
        header_[k] = std::to_string(k + 1);
    const auto time_it = std::find(header_.begin(), header_.end(), "time");
    if (keyed_ && time_it == header_.end())
      throw HistoryReadError(detail::located_message(
          source_, number, line, 1,
          "rows keyed by entity (contact, node, part …) need a 'time' column to be grouped"));
    time_col_ = static_cast<std::size_t>(time_it - header_.begin());
    if (!keyed_)  // the columns are the header's, in its order: set by index, not by name
      for (const std::string& h : header_)
        columns_.push_back(builder_.add_column(h));
    values_.resize(header_.size());
  }

  void read_row(const std::string& line, std::size_t number) {
    const std::vector<std::string_view> fields = deck::split(line, sep_);
    if (fields.size() != header_.size())
      throw HistoryReadError(detail::located_message(
          source_, number, line, 1,
          fmt::format("{} fields where the header has {}", fields.size(), header_.size())));
    std::string suffix;
    for (std::size_t k = 0; k < fields.size(); ++k) {
      values_[k] = kMissing;
      if (key_[k]) {
        suffix += suffix.empty() ? '@' : '/';
        suffix += unquote(fields[k]);
        continue;
      }
      const auto v = csv_value(fields[k]);
      if (!v)
        throw HistoryReadError(
            detail::located_message(source_, number, line, field_column(line, sep_, k),
                                    fmt::format("'{}' in column '{}' is not a number",
                                                core::excerpt(unquote(fields[k])), header_[k])));
      values_[k] = *v;
    }
    if (!keyed_) {
      builder_.new_row();
      for (std::size_t k = 0; k < fields.size(); ++k)
        builder_.set_at(columns_[k], values_[k]);
      return;
    }
    builder_.row_at(values_[time_col_]);
    for (std::size_t k = 0; k < fields.size(); ++k)
      if (!key_[k]) builder_.set(k != time_col_ ? header_[k] + suffix : header_[k], values_[k]);
  }

  const std::string& source_;
  char sep_ = ',';
  std::vector<std::string> header_;
  std::vector<bool> key_;
  bool keyed_ = false, numeric_header_ = false;
  std::size_t time_col_ = 0;
  std::vector<std::size_t> columns_;
  std::vector<double> values_;
  detail::WideTableBuilder builder_;
};

// The LS-DYNA ASCII formats are recognised within their first lines; kDetectLines of them are
// held to decide. ASCII files are then read whole (their records span several lines); CSV is
// read row by row, so only the values are held (8 bytes each, against about 16 of text).
constexpr std::size_t kDetectLines = 400;

HistoryTable read_history_stream(std::istream& in, const std::string& source) {
  TextLines lines(in, source);
  std::vector<std::string> head;
  std::string line;
  while (head.size() < kDetectLines && lines.next(line))
    head.push_back(line);
  const std::string ascii = detail::detect_lsdyna_ascii(head);
  if (!ascii.empty()) {
    while (lines.next(line))
      head.push_back(line);
    while (!head.empty() && deck::trim(head.back()).empty())
      head.pop_back();
    return detail::read_lsdyna_ascii(ascii, head, source);
  }
  CsvReader csv(source);
  for (std::size_t n = 0; n < head.size(); ++n)
    csv.line(head[n], n + 1);
  head.clear();
  while (lines.next(line))
    csv.line(line, lines.number());
  return csv.finish();
}

}  // namespace

int HistoryTable::find(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

namespace detail {

void WideTableBuilder::row_at(double time) {
  if (have_time_ && time == last_time_ && rows_ > 0) return;
  new_row();
  last_time_ = time;
  have_time_ = true;
  set("time", time);
}

void WideTableBuilder::new_row() {
  ++rows_;
  for (std::vector<double>& c : columns_)
    c.push_back(kMissing);
}

std::size_t WideTableBuilder::column(const std::string& name) {
  const auto [it, added] = index_.emplace(name, names_.size());
  if (!added) return it->second;
  names_.push_back(name);
  columns_.emplace_back(rows_, kMissing);
  return names_.size() - 1;
}

void WideTableBuilder::set(const std::string& name, double value) {
  if (rows_ == 0) new_row();
  columns_[column(name)].back() = value;
}

std::size_t WideTableBuilder::add_column(const std::string& name) {
  return column(name);
}

void WideTableBuilder::set_at(std::size_t column, double value) {
  columns_[column].back() = value;
}

HistoryTable WideTableBuilder::finish(const std::string& source, const std::string& format) {
  HistoryTable t;
  t.source = source;
  t.format = format;
  t.names = std::move(names_);
  t.columns = std::move(columns_);
  index_.clear();
  return t;
}

std::string located_message(const std::string& source, std::size_t line_number,
                            const std::string& line, std::size_t column, const std::string& what) {
  return fmt::format("{}:{}:{}: error: {}\n  {}\n  {}^", source, line_number, column, what, line,
                     std::string(column > 0 ? column - 1 : 0, ' '));
}

}  // namespace detail

HistoryTable read_history_text(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  return read_history_stream(in, source);
}

HistoryTable read_history(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw HistoryReadError(fmt::format("{}: error: is a directory", path.string()));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HistoryReadError(fmt::format("{}: error: cannot open the file", path.string()));
  return read_history_stream(in, path.string());
}

}  // namespace mcdyna::io
