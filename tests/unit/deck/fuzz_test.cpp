// Mutation tests: corrupted decks give diagnostics, never a crash or an internal error. The same
// tests run under AddressSanitizer and UndefinedBehaviorSanitizer in CI (see .ci/run).
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <fstream>
#include <random>
#include <sstream>

#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace mcdyna;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const fs::path kData = fs::path(MCDYNA_SOURCE_DIR) / "tests/data";

void expect_clean_failure(const std::string& text, const char* what) {
  CAPTURE(what);
  auto l = test::load_text(text, true);
  CHECK_MESSAGE(!l->has_message("internal error"), l->messages());
  for (const auto& d : l->diags.all()) {  // every diagnostic formats without throwing
    CHECK_FALSE(core::format_diagnostic(d, l->deck.files).empty());
  }
}

}  // namespace

TEST_CASE("mutations of a valid deck: truncation, garbage bytes, huge numbers, deleted lines") {
  const std::string base = read_all(kData / "all_keywords.k");
  std::mt19937 rng(20261122);  // fixed seed: reproducible
  for (int trial = 0; trial < 300; ++trial) {
    std::string text = base;
    std::uniform_int_distribution<std::size_t> pos(0, text.size() - 1);
    switch (trial % 6) {
      case 0:
        text.resize(pos(rng));
        break;  // truncated anywhere, mid-line included
      case 1:
        for (int k = 0; k < 20; ++k)
          text[pos(rng)] = static_cast<char>(rng() & 0xff);
        break;
      case 2:
        text.insert(pos(rng), "1.0E+999999999999999999999999999999");
        break;
      case 3: {
        const std::size_t a = pos(rng);
        const std::size_t b = text.find('\n', a);
        if (b != std::string::npos) text.erase(a, b - a + 1);
        break;
      }
      case 4:
        text.insert(pos(rng), std::string(5000, 'x'));
        break;
      case 5:
        text.insert(pos(rng), "\n&undefined_parameter,-&x,&,--&y\n*\n*UNKNOWN_KEYWORD_Z\n");
        break;
    }
    expect_clean_failure(text, "mutation");
  }
}

TEST_CASE("hostile inputs: empty, binary, NUL bytes, one huge line, keyword-only, odd formats") {
  expect_clean_failure("", "empty");
  expect_clean_failure(std::string("\0\0\0*NODE\n\0\0", 11), "NUL bytes");
  std::string binary(4096, '\0');
  std::mt19937 rng(7);
  for (char& c : binary)
    c = static_cast<char>(rng() & 0xff);
  expect_clean_failure(binary, "binary");
  expect_clean_failure("*NODE\n" + std::string(200000, '9') + "\n", "huge line");
  expect_clean_failure("*\n*+\n*-\n*%\n*KEYWORD LONG=Q I10=Z\n", "bare keywords");
  expect_clean_failure("*ELEMENT_SOLID\n1\n", "element without its node line");
  expect_clean_failure("*PART\nonly a heading\n", "part without card 1");
  expect_clean_failure("*PARAMETER_EXPRESSION\nR x " + std::string(500, '(') + "\n",
                       "deep nesting");
  expect_clean_failure("*PARAMETER\nQ bad 1\n*PARAMETER_DUPLICATION\nxx\n", "bad parameter");
  expect_clean_failure("*SET_NODE_LIST_GENERATE\n1\n1,999999999999\n", "huge generate range");
  expect_clean_failure("*INCLUDE\n/dev/null\n/\n.\n\n +\n", "odd include names");
  // Found by libFuzzer (tools/fuzz_reader.sh): a code outside its allowed set reached a builder
  // that indexes a table by it (KERNEL 5: kSmstepDefault[5], an out-of-bounds read under ASan).
  auto kernel = test::load_text("*SECTION_SOLID_SPG\n1,47\n1.5,1.5,1.5,0,5\n");
  CHECK(kernel->has_message("field KERNEL: value 5 is not allowed (must be one of {0, 1, 2, 3})"));
}

TEST_CASE("include trouble: missing, cycles, self include, deep chains, directories") {
  test::TempDir d;
  d.write("self.k", "*INCLUDE\nself.k\n");
  for (int i = 0; i < 100; ++i) {
    d.write(fmt::format("c{}.k", i), fmt::format("*INCLUDE\nc{}.k\n", i + 1));
  }
  fs::create_directories(d.path() / "adir");
  auto l = test::load_file(d.write("main.k", "*INCLUDE\nself.k\nc0.k\nadir\nnope.k\n"), true);
  CHECK(l->has_message("include cycle"));
  CHECK(l->has_message("include depth exceeds 64"));
  CHECK(l->has_message("include file \"nope.k\" not found"));
  CHECK(l->has_message("include file \"adir\" not found"));
  CHECK_FALSE(l->has_message("internal error"));
}
