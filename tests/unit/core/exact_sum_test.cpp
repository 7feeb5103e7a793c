// core::ExactSum: the same bits for any order and any split of the terms, and the exact sum
// where a double holds it.
#include "core/exact_sum.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "same_bits.hpp"

namespace mcdyna::core {

namespace {

using test::same_bits;

double sum_of(const std::vector<double>& terms) {
  ExactSum s;
  for (const double x : terms)
    s.add(x);
  return s.value();
}

// Terms over many scales and both signs, as energies and forces of a model are.
std::vector<double> mixed_terms(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-60, 60);
  std::vector<double> t;
  for (int i = 0; i < n; ++i)
    t.push_back(std::ldexp(unit(rng), scale(rng)));
  return t;
}

}  // namespace

TEST_CASE("ExactSum: the same bits for any order and any split into merged partial sums") {
  std::mt19937_64 rng(25);
  const std::vector<double> terms = mixed_terms(rng, 5000);
  const double reference = sum_of(terms);
  double naive_spread = 0.0;  // what a plain double sum does under reordering, for scale
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> shuffled = terms;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    CHECK(same_bits(sum_of(shuffled), reference));
    double naive = 0.0;
    for (const double x : shuffled)
      naive += x;
    naive_spread = std::max(naive_spread, std::abs(naive - reference));
    // Split into 1-7 partial sums (threads, ranks), merged in a shuffled order.
    const auto parts = static_cast<std::size_t>(1 + trial % 7);
    std::vector<ExactSum> partial(parts);
    for (std::size_t i = 0; i < shuffled.size(); ++i)
      partial[(i * 7919) % parts].add(shuffled[i]);
    std::shuffle(partial.begin(), partial.end(), rng);
    ExactSum merged;
    for (const ExactSum& p : partial)
      merged.merge(p);
    CHECK(same_bits(merged.value(), reference));
  }
  MESSAGE("plain double sums of the same terms differ by up to ", naive_spread);
  CHECK(naive_spread > 0.0);  // the terms are ones reordering changes: the check above means it
}

TEST_CASE("ExactSum: exact where the sum is a double, cancellation included") {
  CHECK(sum_of({1.0e16, 1.0, -1.0e16}) == 1.0);  // a plain sum gives 0
  // The doubles nearest 0.1, 0.2 and 0.3 sum to exactly 2^-55 (a plain sum gives 2^-54).
  CHECK(sum_of({0.1, 0.2, -0.3}) == 0x1p-55);
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(sum_of({tiny, tiny, tiny}) == 3.0 * tiny);
  const double big = std::numeric_limits<double>::max();
  CHECK(sum_of({big, big, -big}) == big);  // the intermediate 2 max overflows a double
  CHECK(sum_of({-2.5, 1.25, -0.75}) == -2.0);
  CHECK(sum_of({}) == 0.0);
  // 2^53 + 1 is not a double: the result is one of its neighbours.
  const double two53 = 9007199254740992.0;
  const double r = sum_of({two53, 1.0});
  CHECK((r == two53 || r == two53 + 2.0));
}

TEST_CASE("ExactSum: the exact sum of 100,000 terms where a double holds it") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Integers times a power of two: their exact sum is an integer a double holds.
  std::vector<double> terms;
  std::int64_t exact = 0;
  for (int i = 0; i < 100000; ++i) {
    const auto k = static_cast<std::int64_t>(unit(rng) * 1.0e9) - 500000000;
    terms.push_back(std::ldexp(static_cast<double>(k), -20));
    exact += k;
  }
  CHECK(sum_of(terms) == std::ldexp(static_cast<double>(exact), -20));
}

TEST_CASE("ExactSum: NaN and infinities") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(sum_of({1.0, inf}) == inf);
  CHECK(sum_of({1.0, -inf}) == -inf);
  CHECK(std::isnan(sum_of({inf, -inf})));
  CHECK(std::isnan(sum_of({1.0, std::nan("")})));
}

}  // namespace mcdyna::core
