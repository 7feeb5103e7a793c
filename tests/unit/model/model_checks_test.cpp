// Cross-checks: duplicates, dangling references, physical and geometric sanity, all at once.
#include <doctest/doctest.h>

#include "test_support.hpp"

using mcdyna::test::load_text;

namespace {
const char* kCube =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*CONTROL_TERMINATION\n1.0\n";
}

TEST_CASE("duplicates and dangling references are all reported at their deck location") {
  auto l = load_text(std::string(kCube) +
                         "*NODE\n3,5,5,5\n"
                         "*PART\np\n1,10,20,30,40\n"
                         "*ELEMENT_SOLID\n1,1\n1,2,3,4,5,6,7,99\n"
                         "*ELEMENT_SOLID\n2,7\n1,2,3,4,5,6,7,8\n"
                         "*SET_NODE_LIST\n4\n1,77\n"
                         "*BOUNDARY_SPC_SET\n5,0,1\n"
                         "*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,1,0,66\n",
                     true);
  CHECK(l->has_message("node 3 is defined twice (first at line 4)"));
  CHECK(l->has_message("part 1 refers to section 10, which is not defined"));
  CHECK(l->has_message("part 1 refers to material 20, which is not defined"));
  CHECK(l->has_message("part 1 refers to equation of state 30, which is not defined"));
  CHECK(l->has_message("part 1 refers to *HOURGLASS 40, which is not defined"));
  CHECK(l->has_message("solid element 1 refers to node 99, which is not defined"));
  CHECK(l->has_message("solid element 2 refers to part 7, which is not defined"));
  CHECK(l->has_message("node set 4 contains node 77, which is not defined"));
  CHECK(l->has_message("*BOUNDARY_SPC refers to node set 5, which is not defined"));
  CHECK(l->has_message("*BOUNDARY_PRESCRIBED_MOTION refers to curve 66, which is not defined"));
  const std::string text = l->messages();
  CHECK(text.find("main.k:16:3-4: error: part 1 refers to section 10") != std::string::npos);
  CHECK(l->diags.error_count() == 10);
}

TEST_CASE("physical sanity: density, moduli, TM > TR, EPSO with C, DX >= 1, EOS for JC solids") {
  auto l = load_text(std::string(kCube) +
                         "*MAT_ELASTIC\n1,0.0,-5.0,0.7\n"
                         "*MAT_JOHNSON_COOK\n2,2.7e-9,26000\n324,114,0.42,0.01,1.34,250,293\n"
                         "*SECTION_SOLID_SPG\n1,47\n0.8\n"
                         "*SECTION_SOLID\n2,1\n"
                         "*PART\np\n1,2,2\n"
                         "*ELEMENT_SOLID\n1,1\n1,2,3,4,5,6,7,8\n",
                     true);
  CHECK(l->has_message("*MAT_ELASTIC card 1 field RO: value 0.0 is not allowed (must be > 0)"));
  CHECK(l->has_message("*MAT_ELASTIC 1: E < 0 (modulus from a curve) is not supported"));
  CHECK(l->has_message("Poisson's ratio PR = 0.7 must lie in (-1, 0.5)"));
  CHECK(l->has_message("melt temperature TM = 250 must exceed room temperature TR = 293"));
  CHECK(l->has_message("C = 0.01 needs a reference strain rate EPSO > 0"));
  CHECK(l->has_message("DX = 0.8 is below 1"));
  CHECK(l->has_message("*MAT_JOHNSON_COOK solids need an equation of state"));
}

TEST_CASE("inverted and collapsed hexahedra are reported, a degenerate tetrahedron is accepted") {
  auto l = load_text(std::string(kCube) +
                         "*MAT_ELASTIC\n1,1.0,1.0,0.3\n*SECTION_SOLID\n1,1\n*PART\np\n1,1,1\n"
                         "*ELEMENT_SOLID\n"
                         "1,1\n5,6,7,8,1,2,3,4\n"
                         "2,1\n1,2,3,4,1,2,3,4\n"
                         "3,1\n1,2,4,5,5,5,5,5\n"
                         "4,1\n1,2,3,4,5,6,7,8\n",
                     true);
  CHECK(l->has_message("solid element 1 is inverted"));
  CHECK(l->has_message("solid element 2 is collapsed to zero volume"));
  CHECK_FALSE(l->has_message("solid element 3"));
  CHECK_FALSE(l->has_message("solid element 4"));
  CHECK(l->diags.error_count() == 2);
}

TEST_CASE("what mcdyna cannot run is named: shell and solid ELFORM, shell rules, composites") {
  auto l = load_text(std::string(kCube) +
                         "*MAT_ELASTIC\n1,1.0,1.0,0.3\n*SECTION_SHELL\n1,5\n1.0\n"
                         "*SECTION_SOLID\n2,16\n*SECTION_SHELL\n3,2,1.0,3,1,-2\n1.0\n"
                         "*SECTION_SHELL\n4,2,1.0,2,1,0,1\n1.0\n"
                         "*PART\ns\n1,1,1\n*PART\nt\n2,2,1\n*PART\nu\n3,3,1\n*PART\nv\n4,4,1\n"
                         "*ELEMENT_SHELL\n1,1,1,2,3,4\n3,3,1,2,3,4\n4,4,1,2,3,4\n"
                         "*ELEMENT_SOLID\n2,2\n1,2,3,4,5,6,7,8\n",
                     true);
  CHECK(
      l->has_message("part 1: shell ELFORM 5 of section 1 is not supported for deformable shells"));
  CHECK(l->has_message("solid ELFORM 16 of section 2 is not supported"));
  CHECK(l->has_message("part 3: QR/IRID = -2 of section 3 is not supported"));
  CHECK(l->has_message("part 4: composite shells (ICOMP 1"));
  CHECK(!l->has_message("deformable shells are not supported"));
}

TEST_CASE("no *CONTROL_TERMINATION in a deck with elements is an error") {
  auto l = load_text(
      "*NODE\n1\n2,1\n3,1,1\n4,0,1\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*MAT_ELASTIC\n1,1.0,1.0,0.3\n*SECTION_SOLID\n1\n*PART\np\n1,1,1\n"
      "*ELEMENT_SOLID\n1,1\n1,2,3,4,5,6,7,8\n",
      true);
  CHECK(l->has_message("the deck has no *CONTROL_TERMINATION"));
  CHECK(l->diags.error_count() == 1);
}

TEST_CASE("*SET_NODE_GENERAL applies its rules in order, element sets name their elements") {
  // Two shells: 1 on nodes 1-4, 2 on nodes 2 5 6 3; node 7 on no element. Box 3 holds nodes 1
  // and 4 (x <= 0.5).
  auto l = load_text(
      "*CONTROL_TERMINATION\n1e-3\n"
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n6,2,1,0\n7,5,5,5\n"
      "*PART\np\n1,1,1\n*SECTION_SHELL\n1\n1,1,1,1\n*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n"
      "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,1,2,5,6,3\n*SET_SHELL_LIST\n4\n2\n"
      "*DEFINE_BOX\n3,-0.5,0.5,-0.5,1.5,-0.5,0.5\n"
      "*SET_NODE_GENERAL\n10\nPART,1\nDBOX,3\n"
      "*SET_NODE_GENERAL\n11\nSET_SHELL,4\nDNODE,5\nNODE,7\n"
      "*SET_NODE_GENERAL\n12\nALL\nDPART,1\n"
      "*SET_NODE_GENERAL\n13\nFOO,1\n*SET_SOLID\n5\n99\n"
      "*SET_SHELL_LIST_GENERATE\n6\n1,2\n*SET_NODE_GENERAL\n14\nSET_SHELL,6\nDSHELL,2\n",
      true);
  const auto& sets = l->model().node_sets;
  REQUIRE(sets.size() == 5);
  CHECK(sets[4].nodes == std::vector<mcdyna::model::Id>{1, 4});  // shells 1-2 less shell 2's
  CHECK(sets[0].nodes == std::vector<mcdyna::model::Id>{2, 3, 5, 6});
  CHECK(sets[1].nodes == std::vector<mcdyna::model::Id>{2, 3, 6, 7});
  CHECK(sets[2].nodes == std::vector<mcdyna::model::Id>{7});
  CHECK(l->has_message("*SET_NODE_GENERAL 13: option FOO is not supported"));
  CHECK(l->has_message("solid set 5 contains solid element 99, which is not defined"));
  CHECK(l->diags.error_count() == 2);
}

TEST_CASE("element sets: _GENERAL rules, _GENERATE_INCREMENT, _COLUMN, _COLLECT and part ranges") {
  // Shells 1 (x 0..1) and 2 (x 1..2) of part 1, shell 3 (x 2..3) of part 2; solid 7 of part 3
  // and solid 8 of part 4. Box 9 holds the centroid of shell 1 only.
  auto l = load_text(
      "*CONTROL_TERMINATION\n1e-3\n"
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n6,2,1,0\n7,3,0,0\n8,3,1,0\n"
      "11,0,0,1\n12,1,0,1\n13,1,1,1\n14,0,1,1\n"
      "*PART\np\n1,1,1\n*PART\nq\n2,1,1\n*PART\nr\n3,2,1\n*PART\ns\n4,2,1\n"
      "*SECTION_SHELL\n1\n1,1,1,1\n*SECTION_SOLID\n2\n*MAT_ELASTIC\n1,7.85e-9,210e3,0.3\n"
      "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,1,2,5,6,3\n3,2,5,7,8,6\n"
      "*ELEMENT_SOLID\n7,3\n1,2,3,4,11,12,13,14\n8,4\n1,2,3,4,11,12,13,14\n"
      "*DEFINE_BOX\n9,-0.5,0.9,-0.5,1.5,-0.5,0.5\n"
      "*SET_SHELL_GENERAL\n20\nALL\nDPART,2\n"       // 1 2
      "*SET_SHELL_GENERAL\n21\nBOX,9\nELEM,3\n"      // 1 3
      "*SET_SHELL_GENERAL\n22\nSET,21\nDELEM,1\n"    // 3
      "*SET_SOLID_GENERAL\n23\nPART,3,4\nDSET,24\n"  // 8
      "*SET_SOLID\n24\n7\n"
      "*SET_SHELL_LIST_GENERATE_INCREMENT\n25\n1,3,2\n"                           // 1 3
      "*SET_SHELL_COLUMN\n26,1.0\n2,5.0\n3\n"                                     // 2 3
      "*SET_SHELL_LIST_COLLECT\n27\n1\n*SET_SHELL_GENERAL_COLLECT\n27\nELEM,3\n"  // 1 3
      "*SET_NODE_LIST_GENERATE_INCREMENT\n30\n1,7,3\n"                            // 1 4 7
      "*SET_NODE_COLUMN_COLLECT\n31\n5\n6\n*SET_NODE_COLLECT\n31\n7\n*SET_NODE_LIST_"
      "COLLECT\n31\n8\n"
      "*SET_NODE_GENERAL\n32\nSET_SHELL,22\n"  // shell 3's nodes: 5 6 7 8
      "*SET_PART_LIST_GENERATE\n40\n1,2,4,4\n*SET_PART_LIST_GENERATE_INCREMENT\n41\n1,4,3\n",
      true);
  INFO(l->messages());
  using Ids = std::vector<mcdyna::model::Id>;
  auto elements = [&](mcdyna::model::Id id) {
    for (const auto& s : l->model().element_sets)
      if (s.id == id) return s.elements;
    return Ids{};
  };
  CHECK(elements(20) == Ids{1, 2});
  CHECK(elements(21) == Ids{1, 3});
  CHECK(elements(22) == Ids{3});
  CHECK(elements(23) == Ids{8});
  CHECK(elements(25) == Ids{1, 3});
  CHECK(elements(26) == Ids{2, 3});
  CHECK(elements(27) == Ids{1, 3});
  const auto& nodes = l->model().node_sets;
  REQUIRE(nodes.size() == 3);
  CHECK(nodes[0].nodes == Ids{1, 4, 7});
  CHECK(nodes[1].nodes == Ids{5, 6, 7, 8});  // the column and the two _COLLECT sets
  CHECK(nodes[2].nodes == Ids{5, 6, 7, 8});
  const auto& parts = l->model().part_sets;
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].parts == Ids{1, 2, 4});
  CHECK(parts[1].parts == Ids{1, 4});
  CHECK(l->diags.error_count() == 0);
}

TEST_CASE("two sets of one ID are an error unless both are _COLLECT") {
  auto l =
      load_text(std::string(kCube) + "*SET_NODE_LIST\n5\n1\n*SET_NODE_LIST_COLLECT\n5\n2\n", true);
  CHECK(l->has_message("node set 5 is defined twice"));
}

TEST_CASE("curves for a dynamic-relaxation phase: SIDR 1 refused, SIDR 2 warned") {
  // mcdyna has no dynamic relaxation: a curve that LS-DYNA would apply only there must not run
  // in the transient unannounced.
  auto l = load_text(std::string(kCube) +
                         "*DEFINE_CURVE\n3,1\n0,0\n1,1\n*DEFINE_CURVE\n4,2\n0,0\n1,1\n"
                         "*CONTROL_DAMPING\n",
                     true);
  CHECK(l->has_message("*DEFINE_CURVE 3: SIDR 1 applies the curve in a dynamic-relaxation phase"));
  CHECK(l->has_message("*DEFINE_CURVE 4: SIDR 2: there is no dynamic-relaxation phase"));
}

TEST_CASE("*CONTROL_RIGID: substitutions said at their fields, added joint stiffness refused") {
  auto l = load_text(std::string(kCube) + "*CONTROL_RIGID\n1,0,0,0,0,1,0,0\n0,0.5\n", true);
  CHECK(l->has_message("LMF 1 (Lagrange-multiplier joints) runs as LMF 0"));
  CHECK(l->has_message("JNTF 0 (incremental)"));
  CHECK(l->has_message("METALF 1: the rigid bodies get their full treatment"));
  CHECK(l->has_message("*CONTROL_RIGID card 2 field GJADSTF: value 0.5 is not allowed"));
}
