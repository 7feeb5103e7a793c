#pragma once
// Helpers for solver tests: a box mesh as deck text and one-call simulation of a deck.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "solver/compile.hpp"
#include "solver/driver.hpp"
#include "test_support.hpp"

namespace mcdyna::test {

/// *NODE and *ELEMENT_SOLID text of an nx x ny x nz box of edge h from the origin, part 1.
inline std::string box_mesh(int nx, int ny, int nz, double h, int first_node = 1,
                            int first_element = 1, int part = 1, double z0 = 0.0) {
  auto id = [&](int i, int j, int k) { return first_node + i + (nx + 1) * (j + (ny + 1) * k); };
  std::string s = "*NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        s += fmt::format("{:8d}{:16.8f}{:16.8f}{:16.8f}\n", id(i, j, k), i * h, j * h, z0 + k * h);
  s += "*ELEMENT_SOLID\n";
  int e = first_element;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, part,
                         id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                         id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                         id(i, j + 1, k + 1));
  return s;
}

struct Simulation {
  std::unique_ptr<Loaded> loaded;
  std::unique_ptr<solver::State> state;
  solver::RunResult result;
};

/// Reads, checks and compiles a deck (REQUIREs no errors); run() then runs it.
inline Simulation prepare(const TempDir& dir, const std::string& text) {
  Simulation sim;
  sim.loaded = load_file(dir.write("deck.k", text), true);
  REQUIRE_MESSAGE(!sim.loaded->diags.has_errors(), sim.loaded->messages());
  core::Diagnostics d;
  sim.state = solver::compile(sim.loaded->model(), d);
  REQUIRE(sim.state != nullptr);
  return sim;
}

inline void run(Simulation& sim, const solver::RunHooks& hooks = {}) {
  sim.result = solver::run(*sim.state, hooks);
}

}  // namespace mcdyna::test
