// CSV histories (ours and other engineers') and the dispatch to the LS-DYNA ASCII readers.
#include "io/history_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::io {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  while (!lines.empty() && deck::trim(lines.back()).empty())
    lines.pop_back();
  return lines;
}

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

HistoryTable read_csv(const std::vector<std::string>& lines, const std::string& source) {
  std::size_t first = 0;
  while (first < lines.size() && deck::trim(lines[first]).empty())
    ++first;
  if (first == lines.size())
    throw HistoryReadError(fmt::format("{}: error: the file is empty", source));
  const std::string& header_line = lines[first];
  const char sep = csv_separator(header_line);
  std::vector<std::string> header;
  for (const std::string_view h : deck::split(header_line, sep))
    header.push_back(unquote(h));
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k].empty())
      throw HistoryReadError(detail::located_message(source, first + 1, header_line,
                                                     field_column(header_line, sep, k),
                                                     "empty column name in the header row"));
  // A header of numbers is data without a header: name the columns by their index.
  const bool numeric_header = std::all_of(header.begin(), header.end(), [](const std::string& h) {
    return deck::parse_real(h).has_value();
  });
  std::vector<bool> key(header.size(), false);
  bool keyed = false;
  for (std::size_t k = 0; k < header.size(); ++k) {
    key[k] = !numeric_header && is_key_name(header[k]);
    keyed = keyed || key[k];
  }
  if (numeric_header)
    for (std::size_t k = 0; k < header.size(); ++k)
      header[k] = std::to_string(k + 1);
  const auto time_it = std::find(header.begin(), header.end(), "time");
  if (keyed && time_it == header.end())
    throw HistoryReadError(detail::located_message(
        source, first + 1, header_line, 1,
        "rows keyed by entity (contact, node, part …) need a 'time' column to be grouped"));
  const auto time_col = static_cast<std::size_t>(time_it - header.begin());

  detail::WideTableBuilder b;
  for (std::size_t n = numeric_header ? first : first + 1; n < lines.size(); ++n) {
    const std::string& line = lines[n];
    if (deck::trim(line).empty()) continue;
    const std::vector<std::string_view> fields = deck::split(line, sep);
    if (fields.size() != header.size())
      throw HistoryReadError(detail::located_message(
          source, n + 1, line, 1,
          fmt::format("{} fields where the header has {}", fields.size(), header.size())));
    std::string suffix;
    for (std::size_t k = 0; k < fields.size(); ++k)
      if (key[k]) {
        suffix += suffix.empty() ? '@' : '/';
        suffix += unquote(fields[k]);
      }
    std::vector<double> values(fields.size(), kMissing);
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (key[k]) continue;
      const auto v = csv_value(fields[k]);
      if (!v)
        throw HistoryReadError(detail::located_message(
            source, n + 1, line, field_column(line, sep, k),
            fmt::format("'{}' in column '{}' is not a number", unquote(fields[k]), header[k])));
      values[k] = *v;
    }
    if (keyed)
      b.row_at(values[time_col]);
    else
      b.new_row();
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (key[k]) continue;
      b.set(keyed && k != time_col ? header[k] + suffix : header[k], values[k]);
    }
  }
  return b.finish(source, "csv");
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
  const std::vector<std::string> lines = split_lines(text);
  const std::string ascii = detail::detect_lsdyna_ascii(lines);
  if (!ascii.empty()) return detail::read_lsdyna_ascii(ascii, lines, source);
  return read_csv(lines, source);
}

HistoryTable read_history(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HistoryReadError(fmt::format("{}: error: cannot open the file", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return read_history_text(text.str(), path.string());
}

}  // namespace mcdyna::io
