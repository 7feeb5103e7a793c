#pragma once
/// Number parsing for keyword cards, Fortran style included (keywords.md §1.3):
/// 1.0E+4, 1.0D+4, 1.00000+4 (E-less exponent), 3.5-10, leading '+', trailing '.'.
#include <cstdint>
#include <optional>
#include <string_view>

namespace mcdyna::deck {

/// Parses a trimmed, non-empty real; nullopt if it is not a number or not finite.
std::optional<double> parse_real(std::string_view text);

/// Parses a trimmed, non-empty integer. A real with an integral value ("2.", "1.0E3") is accepted
/// as LS-DYNA readers do; nullopt otherwise or if it does not fit in 64 bits.
std::optional<std::int64_t> parse_integer(std::string_view text);

}  // namespace mcdyna::deck
