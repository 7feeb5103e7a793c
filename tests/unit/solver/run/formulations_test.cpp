// The formulations' registry (solver/run/formulations.hpp): one line per formulation gives its
// compile pass and its blocks; the passes run in the registry's order, moved after what they read.
#include <doctest/doctest.h>

#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/run/formulations.hpp"

using namespace mcdyna::solver;

namespace {

std::vector<std::string> names(const std::vector<Formulation>& lines,
                               const std::vector<std::size_t>& order) {
  std::vector<std::string> out;
  for (const std::size_t k : order)
    out.emplace_back(lines[k].name);
  return out;
}

std::size_t position(const std::vector<std::string>& order, const char* name) {
  for (std::size_t i = 0; i < order.size(); ++i)
    if (order[i] == name) return i;
  FAIL("no line ", name);
  return 0;
}

}  // namespace

TEST_CASE("the compile passes follow what they read, otherwise the loop's order") {
  const std::vector<Formulation>& lines = formulations();
  const std::vector<std::string> order = names(lines, compile_order(lines));
  REQUIRE(order.size() == lines.size());
  // Every pass after the lines it names.
  for (const Formulation& f : lines)
    for (const char* before : f.after)
      CHECK_MESSAGE(position(order, before) < position(order, f.name), f.name, " after ", before);
  // The order the physics needs, as compile() ran it before the registry: elements, the rigid
  // bodies (whole before any condition reads them: the line that stops at errors), joints,
  // constraints, motions, then the SPG parts that these pin, their initial velocities, the
  // walls that track their nodes, the ties (which move their slave nodes onto the master
  // surfaces) and contact, whose slave nodes they all are; the sensors last,
  // as they read the cycle's results and switch the blocks before them.
  const char* const expected[] = {
      "solids",      "shells",          "beams",      "rigid bodies",  "joints",
      "constraints", "motions",         "spg",        "discrete",      "initial velocities",
      "rigid walls", "geometric walls", "body loads", "applied loads", "global damping",
      "ties",        "contact",         "sensors"};
  REQUIRE(order.size() == std::size(expected));
  for (std::size_t i = 0; i < order.size(); ++i)
    CHECK(order[i] == expected[i]);
  for (const Formulation& f : lines)
    if (f.stop_on_errors) CHECK(std::string(f.name) == "rigid bodies");
}

TEST_CASE("a registry line naming an unknown line or a cycle is a programming error") {
  const std::vector<Formulation> unknown = {{"a", {"b"}}};
  CHECK_THROWS_AS(compile_order(unknown), std::logic_error);
  const std::vector<Formulation> cycle = {{"a", {"b"}}, {"b", {"a"}}};
  CHECK_THROWS_AS(compile_order(cycle), std::logic_error);
  // Without dependencies the registry's order stands; a line waits only as long as it must.
  const std::vector<Formulation> waits = {{"a", {"c"}}, {"b", {}}, {"c", {}}};
  const std::vector<std::string> waited = names(waits, compile_order(waits));
  REQUIRE(waited.size() == 3);
  CHECK(waited[0] == "b");
  CHECK(waited[1] == "c");
  CHECK(waited[2] == "a");
}
