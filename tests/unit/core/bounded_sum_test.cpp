// core::BoundedSum: the same bits for any order of the terms and any split of them into partial
// sums merged by their digits, within a double's rounding of the exact sum (core::ExactSum).
#include "core/bounded_sum.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "core/exact_sum.hpp"
#include "same_bits.hpp"

namespace mcdyna::core {

namespace {

using test::same_bits;

double bound_of(const std::vector<double>& terms) {
  double m = 0.0;
  for (const double x : terms)
    m = std::max(m, std::abs(x));
  return m;
}

double bounded_sum(const std::vector<double>& terms, double bound) {
  BoundedSum s(bound);
  for (const double x : terms)
    s.add(x);
  return s.value();
}

// Squared norms of a power iteration's vector (non-negative, six decades), and signed terms
// with cancellation (a weighted dot product).
std::vector<double> terms(bool signed_terms, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> t(n);
  for (double& x : t) {
    x = std::pow(10.0, -6.0 * unit(rng)) * 3.7e4;
    if (signed_terms && unit(rng) < 0.5) x = -x;
  }
  return t;
}

}  // namespace

TEST_CASE("BoundedSum: any order and any split give the same bits") {
  for (const bool signed_terms : {false, true}) {
    std::vector<double> t = terms(signed_terms, 5000, 25);
    const double bound = bound_of(t);
    const double reference = bounded_sum(t, bound);
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 5; ++trial) {
      std::shuffle(t.begin(), t.end(), rng);
      CHECK(same_bits(bounded_sum(t, bound), reference));
      // Split into 3 partial sums merged by their digits, as over 3 processes.
      BoundedSum parts[3] = {BoundedSum(bound), BoundedSum(bound), BoundedSum(bound)};
      for (std::size_t i = 0; i < t.size(); ++i)
        parts[(i * 7 + static_cast<std::size_t>(trial)) % 3].add(t[i]);
      BoundedSum::Digits total{};
      for (const BoundedSum& p : parts)
        for (int k = 0; k < 2; ++k)
          total[static_cast<std::size_t>(k)] += p.digits()[static_cast<std::size_t>(k)];
      CHECK(same_bits(BoundedSum::from_digits(bound, total).value(), reference));
    }
  }
}

TEST_CASE("BoundedSum: within a double's rounding of the exact sum") {
  for (const bool signed_terms : {false, true}) {
    const std::vector<double> t = terms(signed_terms, 20000, 3);
    ExactSum exact;
    for (const double x : t)
      exact.add(x);
    const double sum = bounded_sum(t, bound_of(t));
    // Each term loses under 2^-80 of the bound's power of two; the value's two roundings
    // (high digit, then the low one added) stay within 2 ulp of the exact sum here, whose
    // magnitude is 10^3 x the bound's at least.
    const double e = std::abs(exact.value());
    CHECK(std::abs(sum - exact.value()) <= 2.0 * (std::nextafter(e, 2.0 * e) - e));
    MESSAGE("relative difference to the exact sum ",
            std::abs(sum - exact.value()) / std::abs(exact.value()));
  }
}

TEST_CASE("BoundedSum: tiny and huge bounds, zeros, carries over many terms") {
  CHECK(bounded_sum({0.0, 0.0}, 0.0) == 0.0);
  CHECK(bounded_sum({1e-300, 2e-300}, 2e-300) == doctest::Approx(3e-300).epsilon(1e-15));
  CHECK(bounded_sum({1e300, -1e300, 5e299}, 1e300) == doctest::Approx(5e299).epsilon(1e-15));
  // 5 million terms of 1 (more than the carry interval of 2^22): exactly 5e6.
  BoundedSum s(1.0);
  for (int i = 0; i < 5000000; ++i)
    s.add(1.0);
  CHECK(s.value() == 5.0e6);
}

}  // namespace mcdyna::core
