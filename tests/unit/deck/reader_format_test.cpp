// Card reading: fixed columns, free format, long and I10 formats, defaults, options.
#include <doctest/doctest.h>

#include "test_support.hpp"

using mcdyna::test::load_text;

TEST_CASE("*NODE fixed columns 8/16/16/16/8/8 and case-insensitive keyword names") {
  auto l = load_text(
      "*KEYWORD\n"
      "*node\n"
      "$ comment line\n"
      "       1             0.5            -1.0       1.25E+01       7       3\n"
      "      22       1.00000+4          1.0D-2                         \n"
      "*END\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  const auto& n = l->model().nodes;
  REQUIRE(n.size() == 2);
  CHECK(n[0].id == 1);
  CHECK(n[0].position[0] == 0.5);
  CHECK(n[0].position[1] == -1.0);
  CHECK(n[0].position[2] == 12.5);
  CHECK(n[0].translation_constraint == 7);
  CHECK(n[0].rotation_constraint == 3);
  CHECK(n[1].id == 22);
  CHECK(n[1].position[0] == 1.0e4);
  CHECK(n[1].position[1] == doctest::Approx(0.01).epsilon(1e-15));
  CHECK(n[1].position[2] == 0.0);
  CHECK(n[1].loc.line == 5);
}

TEST_CASE("*ELEMENT_SOLID: legacy one-line and current two-line layouts") {
  auto one = load_text(
      "*ELEMENT_SOLID\n"
      "       1       2      11      12      13      14      15      16      17      18\n");
  auto two = load_text(
      "*ELEMENT_SOLID (ten nodes format)\n"
      "       1       2\n"
      "      11      12      13      14      15      16      17      18       0       0\n"
      "       5       2\n"
      "      21      22      23      24      24      24      24      24\n");
  CHECK(!one->diags.has_errors());
  CHECK_MESSAGE(!two->diags.has_errors(), two->messages());
  REQUIRE(one->model().solids.size() == 1);
  REQUIRE(two->model().solids.size() == 2);
  const std::array<mcdyna::model::Id, 8> expected{11, 12, 13, 14, 15, 16, 17, 18};
  CHECK(one->model().solids[0].nodes == expected);
  CHECK(two->model().solids[0].nodes == expected);
  CHECK(two->model().solids[0].part == 2);
  CHECK(two->model().solids[1].id == 5);
  CHECK(two->model().solids[1].nodes[7] == 24);
}

TEST_CASE("*DEFINE_CURVE: title option, 20-wide points, zero scale factors mean 1") {
  auto l = load_text(
      "*DEFINE_CURVE_TITLE\n"
      "plunge speed\n"
      "         7         0       0.0       2.5      0.01\n"
      "                 0.0                 1.0\n"
      "              1.0E-3               -3.25\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().curves.size() == 1);
  const auto& c = l->model().curves[0];
  CHECK(c.id == 7);
  CHECK(c.title == "plunge speed");
  CHECK(c.abscissa_scale == 1.0);  // SFA 0 -> 1 ("EQ.0: default")
  CHECK(c.ordinate_scale == 2.5);
  CHECK(c.abscissa_offset == 0.01);
  REQUIRE(c.points.size() == 2);
  CHECK(c.points[1].first == 1.0e-3);
  CHECK(c.points[1].second == -3.25);
}

TEST_CASE("free format with commas, empty slots take defaults") {
  auto l = load_text(
      "*SECTION_SOLID_SPG_TITLE\n"
      "plate, with a comma in the title\n"
      "1,47,0\n"
      "1.5,,1.7,0,1,,,\n"
      "1,0.4,1.15,3,,,,-0.002\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().sections.size() == 1);
  const auto& s = l->model().sections[0];
  CHECK(s.title == "plate, with a comma in the title");
  CHECK(s.element_formulation == 47);
  CHECK(s.spg.support_scale[0] == 1.5);
  CHECK(s.spg.support_scale[1] == 1.5);  // blank DY -> DX
  CHECK(s.spg.support_scale[2] == 1.7);
  CHECK(s.spg.kernel_update == 1);
  CHECK(s.spg.smoothing_interval == 5);  // KERNEL 1 default
  CHECK(s.spg.damage_criterion == 1);
  CHECK(s.spg.failure_strain == 0.4);
  CHECK(s.spg.failure_stretch == 1.15);
  CHECK(s.spg.stabilization == 3);
  CHECK(s.spg.surface_quadrature_factor == 1.0);
  CHECK(s.spg.particle_damping == -0.002);
}

TEST_CASE("*SECTION_SPG alias and KERNEL-dependent defaults with card 3 omitted") {
  auto l = load_text(
      "*SECTION_SPG\n"
      "         3        47\n"
      "                                                 0\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  const auto& s = l->model().sections.at(0);
  CHECK(s.spg.support_scale[0] == 1.6);
  CHECK(s.spg.smoothing_interval == 15);
  CHECK(s.spg.stabilization == 1);  // LS-DYNA's blank ITB for KERNEL 0
  CHECK(s.spg.failure_strain == 1.0e11);
}

TEST_CASE("LONG=Y widens fields to 20 columns, '-' suffix restores standard format") {
  auto l = load_text(
      "*KEYWORD LONG=Y\n"
      "*NODE\n"
      "                   5                 1.5                 2.5                 3.5            "
      "       0                   0\n"
      "*MAT_ELASTIC -\n"
      "         1    7.8E-9  210000.0       0.3\n"
      "*END\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().nodes.size() == 1);
  CHECK(l->model().nodes[0].id == 5);
  CHECK(l->model().nodes[0].position[2] == 3.5);
  REQUIRE(l->model().materials.size() == 1);
  CHECK(l->model().materials[0].elastic.youngs_modulus == 210000.0);
}

TEST_CASE("per-keyword '+' long format and I10=Y") {
  auto plus = load_text(
      "*NODE +\n"
      "         12345678901                 1.0                 2.0                 3.0\n");
  CHECK_MESSAGE(!plus->diags.has_errors(), plus->messages());
  CHECK(plus->model().nodes.at(0).id == 12345678901LL);
  auto i10 = load_text(
      "*KEYWORD I10=Y\n"
      "*ELEMENT_SOLID\n"
      "1234567890         2\n"
      "         1         2         3         4         5         6         7         8\n");
  CHECK_MESSAGE(!i10->diags.has_errors(), i10->messages());
  REQUIRE(i10->model().solids.size() == 1);
  CHECK(i10->model().solids[0].id == 1234567890);
  CHECK(i10->model().solids[0].nodes[7] == 8);
}

TEST_CASE("_ID card before card 1 for contacts, optional cards A-D may be omitted") {
  auto l = load_text(
      "*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID\n"
      "        17screw on plate\n"
      "         1         2         2         3\n"
      "       0.3       0.2\n"
      "\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().contacts.size() == 1);
  const auto& c = l->model().contacts[0];
  CHECK(c.id == 17);
  CHECK(c.heading == "screw on plate");
  CHECK(c.a.id == 1);
  CHECK(c.a.type == 2);
  CHECK(c.b.type == 3);
  CHECK(c.static_friction == 0.3);
  CHECK(c.dynamic_friction == 0.2);
  CHECK(c.death == 1.0e20);
  CHECK(c.penalty_scale_a == 1.0);
}

TEST_CASE("a blank line is a card: *INITIAL_VELOCITY_GENERATION card 2 all defaults") {
  auto l = load_text(
      "*INITIAL_VELOCITY_GENERATION\n"
      "         1         2               -10.0\n"
      "\n"
      "*END\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  REQUIRE(l->model().initial_velocities.size() == 1);
  CHECK(l->model().initial_velocities[0].velocity[0] == -10.0);
  CHECK(l->model().initial_velocities[0].target_type == 2);
}

TEST_CASE("*COMMENT lines, text after *END and CRLF line ends are ignored") {
  auto l = load_text(
      "*KEYWORD\r\n*COMMENT\r\nthis is not a card, 1,2,3\r\n*TITLE\r\nmy job\r\n"
      "*END\r\n*NODE\r\n garbage after end\r\n");
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  CHECK(l->model().title == "my job");
  CHECK(l->model().nodes.empty());
}

TEST_CASE("bad field: error names file, line, columns, keyword, card and field, echoes the line") {
  auto l = load_text(
      "*MAT_JOHNSON_COOK\n"
      "         1    2.7E-9   26000.0\n"
      "     324.0     114.0      0.42     0.002      1.34   1.2.3       293.0       1.0\n");
  REQUIRE(l->diags.has_errors());
  const std::string text = l->messages();
  CHECK(text.find("main.k:3:51-60: error: *MAT_JOHNSON_COOK card 2 field TM: expected a real "
                  "number, got \"1.2.3\"") != std::string::npos);
  CHECK(text.find("     324.0     114.0") != std::string::npos);
}

TEST_CASE("required fields, constraints and tabs are reported, values still read") {
  auto l = load_text(
      "*MAT_ELASTIC\n"
      "         1      -7.8     200.0\n"
      "*NODE\n"
      "\t1\t0.0\n");
  CHECK(l->has_message("*MAT_ELASTIC card 1 field RO: value -7.8 is not allowed (must be > 0)"));
  CHECK(l->has_message("tab character in a fixed-column card"));
}

TEST_CASE("a 70 kB free-format field: the message and the echoed line stay short") {
  const std::string field(70000, '7');
  auto l = load_text("*NODE\n1,0.0," + field + "x,0.0\n");
  REQUIRE(l->diags.has_errors());
  const std::string m = l->messages();
  CAPTURE(m.substr(0, 1500));
  CHECK(m.find("main.k:2:7-") != std::string::npos);
  CHECK(m.find("(70001 characters)") != std::string::npos);  // the quoted field is cut
  CHECK(m.size() < 1000);  // was 140,000+ bytes (the field, then 65,000 carets)
  CHECK(m.find(std::string(241, '^')) == std::string::npos);
  CHECK(m.find(std::string(200, '^')) != std::string::npos);
  // A bad field further right than the echo's width: the echo starts shortly before it.
  auto r = load_text("*NODE\n1,0.0,0." + std::string(400, '0') + ",1.2.3\n");
  const std::string mr = r->messages();
  CAPTURE(mr);
  CHECK(mr.find("got \"1.2.3\"") != std::string::npos);
  CHECK(mr.find("\n  ...") != std::string::npos);
  CHECK(mr.size() < 800);
}
