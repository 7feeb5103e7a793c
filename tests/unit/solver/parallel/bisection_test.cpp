// Recursive coordinate bisection (solver/parallel/bisection.hpp).
#include "solver/parallel/bisection.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdyna::test {

namespace parallel = solver::parallel;

TEST_CASE("RCB: equal cells of a uniform grid, compact boxes, weights respected") {
  Eigen::Matrix3Xd p(3, 8 * 4 * 2);
  int k = 0;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 8; ++x)
        p.col(k++) = Eigen::Vector3d(x, y, z);
  const std::vector<double> unit(64, 1.0);
  for (const int parts : {1, 2, 3, 4, 8}) {
    const std::vector<int> cell = parallel::bisect(p, unit, parts);
    std::vector<int> count(static_cast<std::size_t>(parts), 0);
    for (const int c : cell) {
      REQUIRE(c >= 0);
      REQUIRE(c < parts);
      ++count[static_cast<std::size_t>(c)];
    }
    // Each cell within one point of 64 / parts.
    for (const int c : count)
      CHECK(std::abs(c - 64.0 / parts) <= 1.0);
    CHECK(parallel::bisect(p, unit, parts) == cell);  // deterministic
  }
  // 4 parts: the longest extent (x, 8) is cut first, then x again (4 x 4 x 2 halves): four
  // slabs of two x-columns each.
  const std::vector<int> four = parallel::bisect(p, unit, 4);
  for (int i = 0; i < 64; ++i)
    CHECK(four[static_cast<std::size_t>(i)] == static_cast<int>(p(0, i)) / 2);
  // Weights: the first point as heavy as all the others, two parts: it is alone on its side.
  std::vector<double> heavy(64, 1.0);
  heavy[0] = 63.0;
  const std::vector<int> two = parallel::bisect(p, heavy, 2);
  CHECK(std::count(two.begin(), two.end(), two[0]) == 1);  // its weight alone is half
}

}  // namespace mcdyna::test
