#pragma once
// The cantilever strip of tools/decks/shell_cantilever.py as deck text, for the shell and join
// tests: steel 100 x 10 x 1 mm (SI units), clamped at x = 0, released with its first mode's
// velocity field (tip velocity 0.1 m/s).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "solver_support.hpp"

namespace mcdyna::test {

// The first cantilever mode: phi(s) at s = x / L (2 at the tip) and its slope d phi / ds.
constexpr double kBetaL = 1.8751040687119611;
inline double mode(double s, bool slope) {
  const double b = kBetaL * s;
  const double sigma =
      (std::cosh(kBetaL) + std::cos(kBetaL)) / (std::sinh(kBetaL) + std::sin(kBetaL));
  if (slope) return kBetaL * (std::sinh(b) + std::sin(b) - sigma * (std::cosh(b) - std::cos(b)));
  return std::cosh(b) - std::cos(b) - sigma * (std::sinh(b) - std::sin(b));
}

// The strip as nx x ny shells. `welded`: the elements beyond the middle column take their own
// copies of its nodes (IDs 100001 + j), each copy joined to its original by a two-node
// *CONSTRAINED_NODAL_RIGID_BODY (IDs 1001 + j, node sets 11 + j): a spot-welded joint.
inline std::string cantilever(int nx, int ny, double end, const std::string& extra = "",
                              int elform = 2, double poisson = 0.3, bool welded = false) {
  const double length = 0.1, width = 0.01, v0 = 0.1, tip = mode(1.0, false);
  auto id = [&](int i, int j) { return 1 + i + (nx + 1) * j; };
  std::string s = fmt::format(
      "*KEYWORD\n*CONTROL_TERMINATION\n{}\n*PART\nstrip\n1,1,1\n"
      "*SECTION_SHELL\n1,{},0.8333333,2\n0.001,0.001,0.001,0.001\n*MAT_ELASTIC\n1,7850,210e9,{}\n",
      end, elform, poisson);
  s += extra + "*NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      s += fmt::format("{},{:.10g},{:.10g},0\n", id(i, j), length * i / nx,
                       width * (static_cast<double>(j) / ny - 0.5));
  const int middle = nx / 2;
  auto copy = [&](int j) { return 100001 + j; };
  if (welded)
    for (int j = 0; j <= ny; ++j)
      s += fmt::format("{},{:.10g},{:.10g},0\n", copy(j), length * middle / nx,
                       width * (static_cast<double>(j) / ny - 0.5));
  // Beyond the middle a welded strip's elements take the copies.
  auto node = [&](int i, int j, bool beyond) {
    return welded && beyond && i == middle ? copy(j) : id(i, j);
  };
  s += "*ELEMENT_SHELL\n";
  int e = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const bool beyond = i >= middle;
      s += fmt::format("{},1,{},{},{},{}\n", ++e, node(i, j, beyond), node(i + 1, j, beyond),
                       node(i + 1, j + 1, beyond), node(i, j + 1, beyond));
    }
  if (welded)
    for (int j = 0; j <= ny; ++j)
      s += fmt::format("*SET_NODE_LIST\n{}\n{},{}\n*CONSTRAINED_NODAL_RIGID_BODY\n{},0,{}\n",
                       11 + j, id(middle, j), copy(j), 1001 + j, 11 + j);
  s += "*SET_NODE_LIST\n1\n";
  for (int j = 0; j <= ny; ++j)
    s += fmt::format("{}\n", id(0, j));
  s += "*BOUNDARY_SPC_SET\n1,0,1,1,1,1,1,1\n*INITIAL_VELOCITY_NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const double x = static_cast<double>(i) / nx;
      const std::string v = fmt::format(",0,0,{:.10g},0,{:.10g},0\n", v0 * mode(x, false) / tip,
                                        -v0 * mode(x, true) / tip / length);
      s += fmt::format("{}{}", id(i, j), v);
      if (welded && i == middle) s += fmt::format("{}{}", copy(j), v);
    }
  return s + "*END\n";
}

// The same deck with each quadrilateral of *ELEMENT_SHELL split into two triangles (N4 = N3)
// along alternating diagonals, so that the mesh has no preferred direction.
inline std::string triangulated(const std::string& deck) {
  const std::size_t begin = deck.find("*ELEMENT_SHELL\n") + 15;
  const std::size_t end = deck.find('*', begin);
  std::string out = deck.substr(0, begin);
  std::size_t at = begin;
  int e = 0;
  while (at < end) {
    const std::size_t eol = deck.find('\n', at);
    int id = 0, part = 0;
    long n[4] = {};
    std::sscanf(deck.substr(at, eol - at).c_str(), "%d,%d,%ld,%ld,%ld,%ld", &id, &part, &n[0],
                &n[1], &n[2], &n[3]);
    // Diagonal 1-3 or 2-4, turn about.
    const int s = (e++ % 2 == 0) ? 0 : 1;
    const long a = n[s], b = n[s + 1], c = n[(s + 2) % 4], d = n[(s + 3) % 4];
    out += fmt::format("{},{},{},{},{},{}\n", 2 * id - 1, part, a, b, c, c);
    out += fmt::format("{},{},{},{},{},{}\n", 2 * id, part, a, c, d, d);
    at = eol + 1;
  }
  return out + deck.substr(end);
}

// The first-mode period of a cantilever deck with 2 elements across (tip crossings of z = 0,
// the tip node (nx, 1) being the last of the strip's 3 (nx + 1) nodes' middle row) and the
// energy drift; `run` sees the simulation after it ends.
template <class After = void (*)(const Simulation&)>
std::pair<double, double> cantilever_period(
    const std::string& deck, int nx, After after = [](const Simulation&) {}) {
  TempDir dir;
  Simulation sim = prepare(dir, deck);
  const solver::Index tip = 2 * nx + 1;
  REQUIRE(sim.state->nodes.initial(0, tip) == doctest::Approx(0.1));
  std::vector<double> crossings;
  double last_z = 0.0, last_t = 0.0;
  EnergyDrift drift;
  solver::RunHooks hooks = drift.hooks();
  hooks.progress = [&](const solver::State& s) {
    const double z = s.nodes.position(2, tip);
    if (last_t > 0.0 && z * last_z < 0.0)
      crossings.push_back(last_t - last_z * (s.time - last_t) / (z - last_z));
    last_z = z;
    last_t = s.time;
  };
  run(sim, hooks);
  REQUIRE_MESSAGE(sim.result.reason == solver::StopReason::end_time, sim.result.message);
  REQUIRE(crossings.size() >= 3);
  after(sim);
  return {2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1),
          drift.worst};
}

}  // namespace mcdyna::test
