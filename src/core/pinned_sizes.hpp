#pragma once
/// What each block's part of a restart dump is made of (solver/run/restart.hpp): the member lists
/// (binary_archive.hpp's fields()) live beside each formulation's code, and so do the pins
/// of the dumped structs' sizes. A member added to a dumped struct changes its size and stops
/// the build on the pinned platform until it is listed in fields() (or said to be deck data);
/// the sizes are also written into every dump, so a dump from a build whose structs differ is
/// refused instead of misread.
#include <array>
#include <cstddef>
#include <string>

#include "core/binary_archive.hpp"

namespace mcdyna::core {

/// The platform CI builds on (x86-64, libstdc++ without debug containers): where the sizes are
/// pinned. Elsewhere the pins are not checked (the dump still carries the sizes).
#if defined(__x86_64__) && defined(__GLIBCXX__) && !defined(_GLIBCXX_DEBUG)
inline constexpr bool kSizesPinned = true;
#else
inline constexpr bool kSizesPinned = false;
#endif

/// The sizes of the structs a block dumps, in the order it names them.
template <class... T>
constexpr std::array<std::size_t, sizeof...(T)> sizes_of() {
  return {sizeof(T)...};
}

/// The same sizes as text, for the dump's layout line.
template <std::size_t N>
std::string sizes_text(const std::array<std::size_t, N>& sizes) {
  std::string out;
  for (const std::size_t n : sizes)
    out += std::to_string(n) + " ";
  return out;
}

}  // namespace mcdyna::core
