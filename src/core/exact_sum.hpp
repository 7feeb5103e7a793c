#pragma once
/// A sum of doubles that does not depend on the order of its terms: every term is added exactly
/// into a fixed-point integer that spans the whole range of finite doubles (2^-1074 to 2^1024),
/// so any order of the terms, and any split of them into partial sums merged later (threads,
/// MPI ranks: the partials merge by integer addition, exact and associative), holds the same
/// integer, and value() turns that integer into one double by one fixed procedure.
///
/// Why: a reduction over entities that live on different processes (the energies, a rigid
/// body's force and moment, the power iteration's norms) must give the same bits for any number
/// of processes. A serial sum in a fixed order would need every term on one process; this needs
/// only the 74 integers of each partial (issue 25, "the same bits for any process count").
///
/// The integer is held as base-2^32 digits in signed 64-bit limbs: a term touches three limbs
/// and adds less than 2^32 to each, so 2^30 terms can be added before the carries are
/// propagated (done every kCarryInterval terms, and before value()). NaN and infinities are
/// counted beside the integer: value() returns NaN for any NaN or for +inf and -inf together,
/// else the infinity. Cost: 6.4 ns a term against 0.57 ns for a plain double sum (10 million
/// terms over 80 binary orders of magnitude, one core of this machine, -O2).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mcdyna::core {

class ExactSum {
 public:
  /// Limbs of 32 bits from 2^-1152 to 2^1216. A term is m 2^p with m < 2^53 an integer and
  /// -1074 <= p <= 971, and the largest finite double is below 2^1024, which leaves room for
  /// 2^190 terms of it.
  static constexpr int kLimbs = 74;
  static constexpr int kLowestExponent = -1152;  ///< weight of limb 0's lowest bit

  void add(double x) {
    if (!std::isfinite(x)) {
      if (std::isnan(x))
        ++nan_;
      else if (x > 0.0)
        ++plus_infinity_;
      else
        ++minus_infinity_;
      return;
    }
    if (x == 0.0) return;
    // x = (-1)^sign magnitude 2^power with magnitude < 2^53 an integer, from the bits: the
    // stored fraction with the hidden bit (normal numbers) or without it (subnormals).
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto field = static_cast<int>((bits >> 52) & 0x7FF);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
    const std::uint64_t magnitude = field == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
    const int power = field == 0 ? -1074 : field - 1075;
    const bool negative = (bits >> 63) != 0;
    const int shift = power - kLowestExponent;  // bit position of the magnitude's bit 0, >= 78
    const int limb = shift / 32;
    const int bit = shift % 32;
    // Split magnitude << bit (at most 84 bits) into three 32-bit digits.
    const std::uint64_t low = (magnitude << bit) & 0xFFFFFFFFu;
    const std::uint64_t middle =
        bit == 0 ? (magnitude >> 32) & 0xFFFFFFFFu : ((magnitude >> (32 - bit)) & 0xFFFFFFFFu);
    const std::uint64_t high = bit == 0 ? 0 : magnitude >> (64 - bit);
    const std::int64_t sign = negative ? -1 : 1;
    limbs_[static_cast<std::size_t>(limb)] += sign * static_cast<std::int64_t>(low);
    limbs_[static_cast<std::size_t>(limb + 1)] += sign * static_cast<std::int64_t>(middle);
    limbs_[static_cast<std::size_t>(limb + 2)] += sign * static_cast<std::int64_t>(high);
    if (++pending_ >= kCarryInterval) normalise();
  }

  /// Adds another partial sum (of other terms): exact, in any order.
  void merge(const ExactSum& other) {
    ExactSum o = other;
    o.normalise();
    normalise();
    for (int k = 0; k < kLimbs; ++k)
      limbs_[static_cast<std::size_t>(k)] += o.limbs_[static_cast<std::size_t>(k)];
    nan_ += o.nan_;
    plus_infinity_ += o.plus_infinity_;
    minus_infinity_ += o.minus_infinity_;
    normalise();
  }

  /// The sum as a double: the limbs from the most significant down, each added once (within
  /// an ulp or so of the exact sum; the same bits for the same exact sum, whatever the terms'
  /// order).
  [[nodiscard]] double value() const {
    if (nan_ > 0 || (plus_infinity_ > 0 && minus_infinity_ > 0))
      return std::numeric_limits<double>::quiet_NaN();
    if (plus_infinity_ > 0) return std::numeric_limits<double>::infinity();
    if (minus_infinity_ > 0) return -std::numeric_limits<double>::infinity();
    ExactSum n = *this;
    n.normalise();
    // Canonical two's complement: limbs 0..kLimbs-2 in [0, 2^32), the top limb signed. A
    // negative sum is turned positive first so every digit below adds with the same sign.
    const bool negative = n.limbs_[kLimbs - 1] < 0;
    if (negative) n.negate();
    double sum = 0.0;
    for (int k = kLimbs - 1; k >= 0; --k) {
      const std::int64_t digit = n.limbs_[static_cast<std::size_t>(k)];
      if (digit != 0) sum += std::ldexp(static_cast<double>(digit), kLowestExponent + 32 * k);
    }
    return negative ? -sum : sum;
  }

  /// The limbs (after carrying) and the NaN, +inf and -inf counts, as integers whose
  /// element-wise sum over partial sums is the parts of their total: a merge over processes by
  /// one integer all-reduce (core::Communicator).
  using Parts = std::array<std::int64_t, kLimbs + 3>;
  [[nodiscard]] Parts parts() const {
    ExactSum n = *this;
    n.normalise();
    Parts p{};
    std::copy(n.limbs_.begin(), n.limbs_.end(), p.begin());
    p[kLimbs] = nan_;
    p[kLimbs + 1] = plus_infinity_;
    p[kLimbs + 2] = minus_infinity_;
    return p;
  }
  /// The sum whose parts (summed over partials) are `p`.
  static ExactSum from_parts(const Parts& p) {
    ExactSum s;
    std::copy(p.begin(), p.begin() + kLimbs, s.limbs_.begin());
    s.nan_ = p[kLimbs];
    s.plus_infinity_ = p[kLimbs + 1];
    s.minus_infinity_ = p[kLimbs + 2];
    s.normalise();
    return s;
  }

 private:
  static constexpr int kCarryInterval = 1 << 29;

  // Carries so that every limb but the top one is in [0, 2^32).
  void normalise() {
    for (int k = 0; k < kLimbs - 1; ++k) {
      const std::int64_t v = limbs_[static_cast<std::size_t>(k)];
      const std::int64_t carry = v >> 32;  // floor division by 2^32 (arithmetic shift)
      limbs_[static_cast<std::size_t>(k)] = v - carry * (std::int64_t{1} << 32);
      limbs_[static_cast<std::size_t>(k + 1)] += carry;
    }
    pending_ = 0;
  }

  // -x in the normalised form.
  void negate() {
    for (std::int64_t& l : limbs_)
      l = -l;
    normalise();
  }

  std::array<std::int64_t, kLimbs> limbs_{};
  long pending_ = 0;
  long nan_ = 0, plus_infinity_ = 0, minus_infinity_ = 0;
};

}  // namespace mcdyna::core
