#include <doctest/doctest.h>

#include "deck/numbers.hpp"

using mcdyna::deck::parse_integer;
using mcdyna::deck::parse_real;

TEST_CASE("reals: plain, Fortran D exponent, E-less exponent, signs") {
  CHECK(parse_real("1.5").value() == 1.5);
  CHECK(parse_real("+2.").value() == 2.0);
  CHECK(parse_real(".25").value() == 0.25);
  CHECK(parse_real("1.0E+4").value() == 1.0e4);
  CHECK(parse_real("1.0D+4").value() == 1.0e4);
  CHECK(parse_real("1.0d-2").value() == doctest::Approx(1.0e-2).epsilon(1e-15));
  CHECK(parse_real("8.90000-3").value() == doctest::Approx(8.9e-3).epsilon(1e-15));
  CHECK(parse_real("1.00000+4").value() == 1.0e4);
  CHECK(parse_real("-3.5-10").value() == doctest::Approx(-3.5e-10).epsilon(1e-15));
  CHECK(parse_real("2.1e11").value() == 2.1e11);
}

TEST_CASE("reals: garbage and out-of-range values are rejected") {
  CHECK_FALSE(parse_real("1.2.3"));
  CHECK_FALSE(parse_real("abc"));
  CHECK_FALSE(parse_real("1e999"));
  CHECK_FALSE(parse_real("inf"));
  CHECK_FALSE(parse_real("nan"));
  CHECK_FALSE(parse_real("1-"));
  CHECK_FALSE(parse_real("++1"));
  CHECK_FALSE(parse_real("0x10"));
}

TEST_CASE("integers: digits, integral reals, rejects fractions and overflow") {
  CHECK(parse_integer("42").value() == 42);
  CHECK(parse_integer("+7").value() == 7);
  CHECK(parse_integer("-3").value() == -3);
  CHECK(parse_integer("2.").value() == 2);
  CHECK(parse_integer("1.0E3").value() == 1000);
  CHECK(parse_integer("9999999999").value() == 9999999999LL);
  CHECK_FALSE(parse_integer("2.5"));
  CHECK_FALSE(parse_integer("99999999999999999999999"));
  CHECK_FALSE(parse_integer("x1"));
}
