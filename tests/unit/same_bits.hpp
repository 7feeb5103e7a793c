#pragma once
/// Bitwise equality of two doubles (-0 and +0 differ, a NaN equals the same NaN).
#include <cstring>

namespace mcdyna::test {

inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

}  // namespace mcdyna::test
