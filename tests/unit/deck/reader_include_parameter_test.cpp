// *INCLUDE (search paths, continuation, cycles, depth) and *PARAMETER (types, expressions, scopes).
#include <doctest/doctest.h>

#include <fmt/format.h>

#include "deck/parameters.hpp"
#include "test_support.hpp"

using mcdyna::test::load_file;
using mcdyna::test::load_text;
using mcdyna::test::TempDir;

TEST_CASE("*INCLUDE: relative to the including file, continuation lines, backslashes") {
  TempDir d;
  d.write("sub/nodes.k", "*NODE\n       1             1.0\n*INCLUDE\nmore\\extra_nodes.k\n");
  d.write("sub/more/extra_nodes.k", "*NODE\n       2             2.0\n");
  d.write("a_rather_long_directory_name/mesh_part_two.k", "*NODE\n       3             3.0\n");
  const auto main = d.write("main.k",
                            "*KEYWORD\n*INCLUDE\nsub/nodes.k\n*INCLUDE\na_rather_long_directory_"
                            "name/ +\nmesh_part_two.k\n*END\n");
  auto l = load_file(main);
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().nodes.size() == 3);
  CHECK(l->model().nodes[1].position[0] == 2.0);
  CHECK(l->model().nodes[2].id == 3);
  CHECK(l->deck.files.size() == 5);  // index 0 is the command line
}

TEST_CASE("*INCLUDE_PATH and *INCLUDE_PATH_RELATIVE are searched") {
  TempDir d;
  d.write("lib/mat.k", "*MAT_ELASTIC\n         4    7.8E-9  210000.0       0.3\n");
  d.write("abs_lib/curve.k", "*DEFINE_CURVE\n         9\n0.0,0.0\n1.0,1.0\n");
  const auto main =
      d.write("deck/main.k", "*INCLUDE_PATH_RELATIVE\n../lib\n*INCLUDE_PATH\n" +
                                 (d.path() / "abs_lib").string() + "\n*INCLUDE\nmat.k\ncurve.k\n");
  auto l = load_file(main);
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  CHECK(l->model().materials.size() == 1);
  CHECK(l->model().curves.size() == 1);
}

TEST_CASE("missing include, include cycle and runaway chain are reported, not fatal") {
  TempDir d;
  d.write("a.k", "*INCLUDE\nb.k\n");
  d.write("b.k", "*INCLUDE\na.k\n*NODE\n       1\n");
  auto cycle = load_file(d.write("main.k", "*INCLUDE\na.k\nnot_there.k\n"));
  CHECK(cycle->has_message("include cycle: main.k -> a.k -> b.k -> a.k"));
  CHECK(cycle->has_message("include file \"not_there.k\" not found"));
  CHECK(cycle->model().nodes.size() == 1);  // the rest of b.k is still read
  for (int i = 0; i < 70; ++i) {
    d.write("chain" + std::to_string(i) + ".k", "*INCLUDE\nchain" + std::to_string(i + 1) + ".k\n");
  }
  auto chain = load_file(d.write("deep.k", "*INCLUDE\nchain0.k\n"));
  CHECK(chain->has_message("include depth exceeds 64"));
}

TEST_CASE("*PARAMETER R/I/C, &name and -&name in fields, case-insensitive names") {
  auto l = load_text(
      "*PARAMETER\n"
      "R  density    7.8E-9I     mid1         5C    title     steel\n"
      "R modulus   210000.0\n"
      "*MAT_ELASTIC\n"
      "     &MID1  &density  &Modulus       0.3\n"
      "*NODE\n"
      "       1    -&modulus\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  const auto& m = l->model().materials.at(0);
  CHECK(m.id == 5);
  CHECK(m.density == 7.8e-9);
  CHECK(m.elastic.youngs_modulus == 210000.0);
  CHECK(l->model().nodes.at(0).position[0] == -210000.0);
  const auto* t = l->deck.parameters.lookup("TITLE", 0);
  REQUIRE(t != nullptr);
  CHECK(t->type == 'C');
  CHECK(t->text == "steel");
}

TEST_CASE("*PARAMETER_EXPRESSION: operators, functions, pi, dependency order, integer truncation") {
  auto l = load_text(
      "*PARAMETER_EXPRESSION\n"
      "R area     &w*&h\n"
      "R w        2.0*(1.5+0.5)**2/4\n"
      "I n        7/2\n"
      "R trig     sin(pi/2)+max(1,3,2)-sqrt(16)+atan2(0,1)+mod(7,4)+abs(-1)+sign(3,-2)\n"
      "R logs     log(exp(2))+log10(1000)+nint(2.6)+int(-2.6)\n"
      "*PARAMETER\n"
      "R h             3.0\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  auto value = [&](const char* n) { return l->deck.parameters.lookup(n, 0)->number; };
  CHECK(value("W") == 2.0);
  CHECK(value("AREA") == 6.0);
  CHECK(value("N") == 3.0);
  CHECK(value("TRIG") == doctest::Approx(1.0 + 3.0 - 4.0 + 0.0 + 3.0 + 1.0 - 3.0));
  CHECK(value("LOGS") == doctest::Approx(2.0 + 3.0 + 3.0 - 2.0));
}

TEST_CASE("*PARAMETER_EXPRESSION errors: unknown names, self reference, division by zero") {
  auto l = load_text(
      "*PARAMETER_EXPRESSION\n"
      "R a        &b+1\n"
      "R b        a*2\n"
      "R c        1/0\n"
      "R d        foo(2)\n"
      "R e        &nothere\n");
  CHECK(l->has_message("depends on itself"));
  CHECK(l->has_message("division by zero"));
  CHECK(l->has_message("unknown function 'FOO'"));
  CHECK(l->has_message("unknown parameter 'NOTHERE'"));
}

TEST_CASE("*PARAMETER_LOCAL is visible in its file and its includes, not in parent or siblings") {
  TempDir d;
  d.write("child.k", "*SECTION_SOLID\n        20  &loc\n");
  d.write("with_local.k",
          "*PARAMETER_LOCAL\nRloc               2.0\n*INCLUDE\nchild.k\n"
          "*SECTION_SOLID\n        21  &loc\n");
  d.write("sibling.k", "*SECTION_SOLID\n        30  &loc\n");
  auto l = load_file(d.write("main.k",
                             "*INCLUDE\nwith_local.k\nsibling.k\n"
                             "*SECTION_SOLID\n        40  &loc\n"));
  const auto& s = l->model().sections;
  REQUIRE(s.size() == 4);
  CHECK(s[0].element_formulation == 2);
  CHECK(s[1].element_formulation == 2);
  const std::string text = l->messages();
  CHECK(text.find("sibling.k:2:11-20: error: *SECTION_SOLID card 1 field ELFORM: parameter &loc "
                  "is not defined") != std::string::npos);
  CHECK(text.find("main.k:5:11-20: error") != std::string::npos);
}

TEST_CASE("global parameters defined in a later include are visible (pydyna level tests)") {
  const std::filesystem::path dir = std::filesystem::path(MCDYNA_SOURCE_DIR) /
                                    "tests/data/public-decks/ansys/pydyna/tests/testfiles/keywords";
  auto l = load_file(dir / "00_minimal_parameter_test_main.k");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().sections.size() == 18);
  for (const auto& s : l->model().sections) {
    CHECK(s.element_formulation == (s.id % 2 == 0 ? 100 : 200));
  }
}

TEST_CASE("duplicate parameters follow *PARAMETER_DUPLICATION (default: warn, keep first)") {
  auto keep = load_text("*PARAMETER\nR x              1.0\nR x              2.0\n");
  CHECK(keep->deck.parameters.lookup("x", 0)->number == 1.0);
  CHECK(keep->diags.warning_count() == 1);
  auto take = load_text(
      "*PARAMETER_DUPLICATION\n         4\n*PARAMETER\nR x              1.0\n"
      "R x              2.0\n");
  CHECK(take->deck.parameters.lookup("x", 0)->number == 2.0);
  CHECK(take->diags.warning_count() == 0);
  auto error = load_text(
      "*PARAMETER_DUPLICATION\n3\n*PARAMETER\nR x              1.0\nR x              2.0\n");
  CHECK(error->has_message("parameter X is defined twice"));
}

TEST_CASE("parameter of the wrong kind for a field") {
  auto l = load_text(
      "*PARAMETER\nR half           0.5C name        abc\n"
      "*SECTION_SOLID\n     &half\n*NODE\n       1   &name\n");
  CHECK(l->has_message("parameter &half = 0.5 is not an integer"));
  CHECK(l->has_message("parameter &name is text (\"abc\"), expected a real number"));
}

TEST_CASE("*PARAMETER_EXPRESSION: a deep chain written in reverse order is evaluated") {
  // Q10000 = Q9999 + 1, ..., Q1 = Q0 + 1, Q0 = 1: every definition uses one defined after it,
  // 10,000 deep (this overflowed the stack when dependencies were evaluated recursively).
  std::string text = "*PARAMETER_EXPRESSION\n";
  for (int i = 10000; i > 0; --i)
    text += fmt::format("R Q{},Q{}+1\n", i, i - 1);
  text += "R Q0,1\n";
  auto l = load_text(text);
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  CHECK(l->deck.parameters.lookup("Q10000", 0)->number == 10001.0);
  CHECK(l->deck.parameters.lookup("Q5000", 0)->number == 5001.0);
}

TEST_CASE("*PARAMETER_EXPRESSION: cycles and their users are errors at their lines") {
  auto l = load_text(
      "*PARAMETER_EXPRESSION\n"
      "R a,&b+1\n"
      "R b,&c*2\n"
      "R c,a-1\n"
      "R d,c+1\n"
      "R e,e\n");
  CHECK_MESSAGE(l->has_message("parameter A depends on itself: A -> B -> C -> A"), l->messages());
  CHECK_MESSAGE(l->has_message("parameter E depends on itself: E -> E"), l->messages());
  // The users of a parameter with an error say which one (not "unknown parameter").
  CHECK_MESSAGE(l->has_message("parameter D: cannot evaluate 'c+1': C (line 4) has an error"),
                l->messages());
  CHECK_FALSE(l->has_message("unknown parameter"));
  CHECK(l->messages().find("main.k:2:") != std::string::npos);
  CHECK(l->messages().find("main.k:6:") != std::string::npos);
  // A long cycle is named by its ends.
  std::string text = "*PARAMETER_EXPRESSION\n";
  for (int i = 0; i < 1000; ++i)
    text += fmt::format("R P{},P{}+1\n", i, (i + 1) % 1000);
  auto c = load_text(text);
  CHECK_MESSAGE(c->has_message("P0 -> P1 -> P2 -> P3 -> P4 -> P5 -> ... -> P995 -> P996 -> P997 -> "
                               "P998 -> P999 -> P0"),
                c->messages());
}

TEST_CASE("*PARAMETER_EXPRESSION: 300,000 powers or signs in a row are an error, not a crash") {
  for (const std::string& op : {std::string("1**"), std::string("-"), std::string("+"),
                                std::string("("), std::string("sqrt(")}) {
    CAPTURE(op);
    std::string expr;
    for (int i = 0; i < 300000; ++i)
      expr += op;
    auto l = load_text("*PARAMETER_EXPRESSION\nR x," + expr + "1\n");
    CHECK_MESSAGE(l->has_message("expression nested too deeply"), l->messages().substr(0, 2000));
    // The message quotes the expression's head and tail only; the echoed line is a window.
    const std::string m = l->messages();
    CHECK(m.find("main.k:2:") != std::string::npos);
    CHECK(m.size() < 2000);
  }
  // 256 levels are fine.
  auto ok = load_text("*PARAMETER_EXPRESSION\nR x," + std::string(200, '(') + "2" +
                      std::string(200, ')') + "**2\n");
  CHECK_MESSAGE(!ok->diags.has_errors(), ok->messages());
  CHECK(ok->deck.parameters.lookup("X", 0)->number == 4.0);
}
