#pragma once
/// Small string helpers shared by the schema loader, lexer and card reader.
#include <string>
#include <string_view>
#include <vector>

namespace mcdyna::deck {

[[nodiscard]] inline bool is_blank_char(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

[[nodiscard]] inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && is_blank_char(s.back()))
    s.remove_suffix(1);
  return s;
}

[[nodiscard]] inline std::string_view trim_right(std::string_view s) {
  while (!s.empty() && (is_blank_char(s.back()) || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

[[nodiscard]] std::string upper(std::string_view s);

/// Splits on a separator; keeps empty pieces ("a,,b" -> a, "", b).
[[nodiscard]] std::vector<std::string_view> split(std::string_view s, char sep);

/// Splits on runs of blanks. With max_tokens > 0, after that many tokens the untouched rest of the
/// line is one more piece.
[[nodiscard]] std::vector<std::string_view> split_whitespace(std::string_view s,
                                                             std::size_t max_tokens = 0);

/// Splits text into lines without their '\n' (a trailing '\r' is kept for the caller to trim).
[[nodiscard]] std::vector<std::string_view> split_lines(std::string_view text);

/// True if `a` equals `b` ignoring ASCII case.
[[nodiscard]] bool iequals(std::string_view a, std::string_view b);

}  // namespace mcdyna::deck
