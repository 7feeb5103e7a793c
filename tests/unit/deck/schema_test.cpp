// keywords/ and the builders agree; every schema parses; every builder reads only fields its
// schema declares (run on a deck that exercises every supported keyword with all its options).
#include <doctest/doctest.h>

#include <set>

#include "deck/builders/builders.hpp"
#include "deck/registry.hpp"
#include "test_support.hpp"

using namespace mcdyna;

TEST_CASE("every builder-handled schema has a builder and every builder a schema") {
  const auto& reg = test::registry();
  std::set<std::string> builders;
  for (const auto& b : deck::builder_table())
    builders.emplace(b.keyword);
  std::set<std::string> schemas;
  for (const auto& s : reg.schemas()) {
    if (s.handler == "builder") {
      schemas.insert(s.name);
      CHECK_MESSAGE(builders.count(s.name) == 1, "no builder for *", s.name);
    }
  }
  for (const auto& b : builders)
    CHECK_MESSAGE(schemas.count(b) == 1, "no schema for builder ", b);
  CHECK(reg.schemas().size() >= 60);
}

TEST_CASE("the keyword list of issue 2 is supported, with aliases and options") {
  const auto& reg = test::registry();
  for (const char* k : {"NODE",
                        "ELEMENT_SOLID",
                        "ELEMENT_SHELL",
                        "PART",
                        "SECTION_SOLID",
                        "SECTION_SOLID_SPG",
                        "SECTION_SPG",
                        "SECTION_SHELL",
                        "MAT_ELASTIC",
                        "MAT_001",
                        "MAT_PLASTIC_KINEMATIC",
                        "MAT_003",
                        "MAT_JOHNSON_COOK",
                        "MAT_015",
                        "MAT_RIGID",
                        "MAT_020",
                        "MAT_PIECEWISE_LINEAR_PLASTICITY",
                        "MAT_024",
                        "MAT_ADD_EROSION",
                        "EOS_LINEAR_POLYNOMIAL",
                        "EOS_GRUNEISEN",
                        "HOURGLASS",
                        "CONTROL_HOURGLASS",
                        "CONTROL_TERMINATION",
                        "CONTROL_TIMESTEP",
                        "CONTROL_CONTACT",
                        "CONTROL_SOLID",
                        "CONTROL_ENERGY",
                        "CONTROL_BULK_VISCOSITY",
                        "CONTROL_ACCURACY",
                        "CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID",
                        "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TITLE",
                        "CONTACT_AUTOMATIC_SINGLE_SURFACE_ID_MPP",
                        "CONTACT_NODES_TO_SURFACE",
                        "CONTACT_SURFACE_TO_SURFACE",
                        "BOUNDARY_SPC_NODE",
                        "BOUNDARY_SPC_SET_ID",
                        "BOUNDARY_PRESCRIBED_MOTION_NODE",
                        "BOUNDARY_PRESCRIBED_MOTION_SET",
                        "BOUNDARY_PRESCRIBED_MOTION_RIGID_ID",
                        "DEFINE_CURVE_TITLE",
                        "DEFINE_VECTOR",
                        "DEFINE_BOX",
                        "SET_NODE_LIST",
                        "SET_NODE_LIST_TITLE",
                        "SET_NODE_LIST_GENERATE",
                        "SET_PART_LIST",
                        "SET_SEGMENT",
                        "INITIAL_VELOCITY",
                        "INITIAL_VELOCITY_NODE",
                        "INITIAL_VELOCITY_GENERATION",
                        "RIGIDWALL_PLANAR",
                        "RIGIDWALL_PLANAR_FINITE",
                        "RIGIDWALL_PLANAR_MOVING_ID",
                        "RIGIDWALL_PLANAR_ID",
                        "DATABASE_BINARY_D3PLOT",
                        "DATABASE_BINARY_D3DUMP",
                        "DATABASE_BINARY_RUNRSF",
                        "DATABASE_GLSTAT",
                        "DATABASE_MATSUM",
                        "DATABASE_RCFORC",
                        "DATABASE_NODOUT",
                        "DATABASE_SPCFORC",
                        "DATABASE_BNDOUT",
                        "DATABASE_RWFORC",
                        "DATABASE_HISTORY_NODE",
                        "DATABASE_HISTORY_NODE_SET",
                        "DATABASE_HISTORY_NODE_ID",
                        "DATABASE_EXTENT_BINARY",
                        "KEYWORD",
                        "TITLE",
                        "END",
                        "COMMENT",
                        "INCLUDE",
                        "INCLUDE_PATH",
                        "INCLUDE_PATH_RELATIVE",
                        "PARAMETER",
                        "PARAMETER_LOCAL",
                        "PARAMETER_EXPRESSION",
                        "PARAMETER_EXPRESSION_LOCAL"}) {
    CHECK_MESSAGE(reg.classify(k).support == deck::Support::supported, k);
  }
}

TEST_CASE("classification: no-effect, output-only and unsupported with reasons") {
  const auto& reg = test::registry();
  auto c = reg.classify("CONTROL_MPP_IO_NODUMP");
  CHECK(c.support == deck::Support::no_effect);
  CHECK(c.reason.find("MPP") != std::string::npos);
  CHECK(reg.classify("CONTROL_OUTPUT").support == deck::Support::no_effect);
  CHECK(reg.classify("DATABASE_ELOUT").support == deck::Support::output_only);
  c = reg.classify("PART_AVERAGED");
  CHECK(c.support == deck::Support::unsupported);
  CHECK(c.reason == "option _AVERAGED of *PART is not supported");
  c = reg.classify("CONTACT_AUTOMATIC_SINGLE_SURFACE_MORTAR_ID");
  CHECK(c.support == deck::Support::unsupported);
  CHECK(c.reason.find("_MORTAR") != std::string::npos);
  CHECK(reg.classify("AIRBAG_SIMPLE_AIRBAG_MODEL").support == deck::Support::unsupported);
  CHECK(reg.classify("INCLUDE_TRANSFORM").support == deck::Support::unsupported);
}

TEST_CASE("malformed schemas are rejected with file:line") {
  CHECK_THROWS_WITH_AS(deck::parse_schema("x.kw",
                                          "keyword X\nsummary s\ncard 1\n  A real 10 0 - "
                                          "furlongs text\n"),
                       "keywords/x.kw:4: unknown dimension 'furlongs'", deck::SchemaError);
  CHECK_THROWS_AS(deck::parse_schema("x.kw", "keyword X\nsummary s\ncard 1 if A ~ 3\n"),
                  deck::SchemaError);
  CHECK_THROWS_AS(deck::parse_schema("x.kw", "keyword X\ncard 1\n  A real 10 0 - - d\n"),
                  deck::SchemaError);
}

// One instance of every builder keyword with every declared option, so that each builder's field
// lookups run against its schema (a mismatch raises "internal error").
TEST_CASE("all builders run on a deck using every supported keyword without internal errors") {
  const std::filesystem::path deck_path =
      std::filesystem::path(MCDYNA_SOURCE_DIR) / "tests/data/all_keywords.k";
  auto l = test::load_file(deck_path, true);
  CHECK_MESSAGE(!l->has_message("internal error"), l->messages());
  CHECK_MESSAGE(!l->diags.has_errors(), l->messages());
  std::set<std::string> used;
  for (const auto& u : l->built.keywords) {
    const auto c = test::registry().classify(u.name);
    if (c.schema != nullptr) used.insert(c.schema->name);
  }
  for (const auto& s : test::registry().schemas()) {
    if (s.handler == "builder") CHECK_MESSAGE(used.count(s.name) == 1, "not exercised: *", s.name);
  }
  const auto& m = l->model();
  CHECK(m.nodes.size() == 12);
  CHECK(m.solids.size() == 1);
  CHECK(m.shells.size() == 1);
  CHECK(m.contacts.size() == 8);
  CHECK(m.outputs.ascii.size() == 7);
}
