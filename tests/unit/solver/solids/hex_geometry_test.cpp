// Hexahedron geometry: the pattern-sum transforms the one-point element is built on, checked
// against the direct sums over the corners, and the one-point element's behaviour under rigid
// motion of a distorted element (no stress, no hourglass energy).
#include <cmath>
#include <random>

#include "solver/solids/hex_geometry.hpp"
#include "solver_support.hpp"

namespace mcdyna::test {

namespace {

namespace hex = solver::hex;

// Pattern k at corner n straight from the definition: the product of the parent coordinates
// named by the bits of k.
double pattern(int k, int n) {
  double p = 1.0;
  for (int bit = 0; bit < 3; ++bit)
    if (k & (1 << bit)) p *= hex::kXi[n][bit];
  return p;
}

hex::Corners random_corners(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hex::Corners x;
  for (auto& c : x)
    for (auto& v : c)
      v = u(rng);
  return x;
}

}  // namespace

TEST_CASE("corner pattern sums equal the direct sums and their transpose adds back") {
  std::mt19937 rng(7);
  const hex::Corners x = random_corners(rng);
  double m[8][3];
  hex::pattern_sums(x, m);
  double worst = 0.0;
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) {
      double direct = 0.0;
      for (int n = 0; n < 8; ++n)
        direct += pattern(k, n) * x[static_cast<std::size_t>(n)][static_cast<std::size_t>(i)];
      worst = std::max(worst, std::abs(m[k][i] - direct));
    }
  CHECK(worst < 1e-14);

  double c[8][3], direct[24] = {}, f[24] = {};
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& row : c)
    for (auto& v : row)
      v = u(rng);
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k)
        direct[3 * n + i] += c[k][i] * pattern(k, n);
  hex::add_pattern_combination(c, f);
  worst = 0.0;
  for (int j = 0; j < 24; ++j)
    worst = std::max(worst, std::abs(f[j] - direct[j]));
  CHECK(worst < 1e-14);

  // kHourglassPattern names the Flanagan-Belytschko (1981) hourglass base vectors.
  const double fb[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                           {1, -1, -1, 1, -1, 1, 1, -1},
                           {1, -1, 1, -1, 1, -1, 1, -1},
                           {-1, 1, -1, 1, 1, -1, 1, -1}};
  for (int a = 0; a < 4; ++a)
    for (int n = 0; n < 8; ++n)
      CHECK(fb[a][n] == pattern(hex::kHourglassPattern[a], n));
}

// One skewed element with non-parallel faces (free format *NODE), moving with VELOCITY_CARDS.
std::string skewed_element_deck(const std::string& velocity_cards) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n       1.0         1\n"
         "*PART\nskew\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
         "*HOURGLASS\n         1         1       0.1\n"
         "*MAT_ELASTIC\n         1       1.0     100.0       0.3\n"
         "*NODE\n1,0.0,0.0,0.0\n2,1.1,0.1,-0.1\n3,1.3,1.2,0.1\n4,-0.2,0.9,0.0\n"
         "5,0.1,-0.1,1.0\n6,0.9,0.0,1.2\n7,1.0,1.1,0.9\n8,0.0,1.0,1.1\n"
         "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6"
         "       7       8\n" +
         velocity_cards + "*END\n";
}

TEST_CASE(
    "one-point hex: rigid motion of a distorted element gives no strain rate and no "
    "hourglass force, an hourglass mode is resisted") {
  TempDir dir;
  // Translation + spin about an axis through (0.5, 0.5, 0.5): the hourglass rates vanish, since
  // gamma is orthogonal to every linear field. (The stress does not stay zero: a constant
  // spin velocity moves the corners along straight lines, a stretch of order (omega dt)^2.)
  Simulation rigid = prepare(
      dir, skewed_element_deck("*INITIAL_VELOCITY_GENERATION\n         1         2       2.0"
                               "       0.3      -0.2       0.1\n"
                               "       0.5       0.5       0.5       0.3       0.4       1.0\n"));
  run(rigid);
  REQUIRE(rigid.state->cycle == 1);
  double hourglass = 0.0;
  for (double q : solver::solids_of(*rigid.state).hourglass_force)
    hourglass = std::max(hourglass, std::abs(q));
  CHECK(hourglass < 1e-12);

  // The xi-eta hourglass pattern (+1 -1 +1 -1 on both layers) as x-velocity: no strain at the
  // centre, but a resisting hourglass force and positive hourglass work.
  std::string cards = "*INITIAL_VELOCITY_NODE\n";
  const double mode[8] = {1, -1, 1, -1, 1, -1, 1, -1};
  for (int n = 0; n < 8; ++n)
    cards += fmt::format("{:8d}{:16.8f}\n", n + 1, 0.01 * mode[n]);
  Simulation hg = prepare(dir, skewed_element_deck(cards));
  run(hg);
  REQUIRE(hg.state->cycle == 1);
  CHECK(solver::solids_of(*hg.state).hourglass_energy[0] > 0.0);
  // The force opposes the mode: sum_n mode_n f_x,n < 0.
  double resisting = 0.0;
  for (int n = 0; n < 8; ++n)
    resisting +=
        mode[n] * solver::solids_of(*hg.state).corner_force[static_cast<std::size_t>(3 * n)];
  CHECK(resisting < 0.0);
}

}  // namespace mcdyna::test
