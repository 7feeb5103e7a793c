#include "deck/numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

namespace mcdyna::deck {

namespace {

bool parse_whole(std::string_view text, double& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out, std::chars_format::general);
  return ec == std::errc() && ptr == end;
}

// Rewrites Fortran spellings into a form from_chars accepts: D exponent -> E, and an exponent
// sign without a letter ("1.5-3") gets an 'E' inserted before it.
bool normalise_fortran(std::string_view text, char* buf, std::size_t cap, std::size_t& len) {
  if (text.size() + 2 > cap) return false;
  len = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == 'd' || c == 'D') c = 'E';
    const bool sign = c == '+' || c == '-';
    if (sign && i > 0) {
      const char prev = text[i - 1];
      const bool prev_is_exp = prev == 'e' || prev == 'E' || prev == 'd' || prev == 'D';
      if (!prev_is_exp) {
        if (!((prev >= '0' && prev <= '9') || prev == '.')) return false;
        buf[len++] = 'E';
      }
    }
    buf[len++] = c;
  }
  return true;
}

}  // namespace

std::optional<double> parse_real(std::string_view text) {
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return std::nullopt;
  double v = 0.0;
  if (!parse_whole(text, v)) {
    char buf[64];
    std::size_t len = 0;
    if (!normalise_fortran(text, buf, sizeof buf, len)) return std::nullopt;
    if (!parse_whole(std::string_view(buf, len), v)) return std::nullopt;
  }
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  if (text.empty()) return std::nullopt;
  std::string_view digits = text;
  if (digits.front() == '+') digits.remove_prefix(1);
  std::int64_t v = 0;
  const char* end = digits.data() + digits.size();
  auto [ptr, ec] = std::from_chars(digits.data(), end, v);
  if (ec == std::errc() && ptr == end) return v;
  if (ec == std::errc::result_out_of_range) return std::nullopt;
  const auto r = parse_real(text);
  if (!r || *r != std::trunc(*r) || std::fabs(*r) > 9.0e18) return std::nullopt;
  return static_cast<std::int64_t>(*r);
}

}  // namespace mcdyna::deck
