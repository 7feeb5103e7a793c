// SPG approximation: kernel functions (value and gradient), neighbour search against brute force,
// reproducing-kernel shape functions reproducing linear fields at every particle (boundary ones
// too), degenerate neighbourhoods named, and particles generated from hexahedra.
#include <doctest/doctest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "solver/spg/particles.hpp"
#include "solver/spg/shape_functions.hpp"

namespace mcdyna::solver::spg {

namespace {

constexpr KernelShape kShapes[] = {KernelShape::cubic_box, KernelShape::quadratic_box,
                                   KernelShape::cubic_sphere};

// An n x n x n lattice of spacing h, jittered by up to `jitter` h, and supports of `scale` h
// varied by up to +-10 % per particle and direction.
struct Cloud {
  Eigen::Matrix3Xd x, support;
};

Cloud jittered_lattice(int n, double h, double jitter, double scale, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Cloud c;
  c.x.resize(3, n * n * n);
  c.support.resize(3, n * n * n);
  int p = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++p) {
        c.x.col(p) =
            h * Eigen::Vector3d(i + jitter * u(rng), j + jitter * u(rng), k + jitter * u(rng));
        c.support.col(p) =
            scale * h * Eigen::Vector3d(1 + 0.1 * u(rng), 1 + 0.1 * u(rng), 1 + 0.1 * u(rng));
      }
  return c;
}

// The same supports deformed by a shear and a stretch (the updated-Lagrangian kernel, Eq. 34):
// S = (F A0^2 F^T)^(1/2) as renewal.cpp builds it, different per particle.
Supports deformed_supports(const Cloud& c, KernelShape shape) {
  Eigen::Matrix<double, 9, Eigen::Dynamic> s(9, c.support.cols());
  for (Eigen::Index j = 0; j < c.support.cols(); ++j) {
    Eigen::Matrix3d f;
    f << 1.2, 0.3 + 0.01 * static_cast<double>(j % 7), 0.0, 0.0, 0.9, 0.1, 0.05, 0.0, 1.1;
    const Eigen::Matrix3d fa = f * c.support.col(j).asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(fa * fa.transpose());
    Eigen::Map<Eigen::Matrix3d>(s.col(j).data()) = eig.operatorSqrt();
  }
  return deformed(shape, s);
}

}  // namespace

TEST_CASE("SPG kernels: continuous, zero outside the support, gradient = finite difference") {
  const Eigen::Vector3d a(0.3, 0.4, 0.5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  for (const KernelShape shape : kShapes) {
    CHECK(kernel(shape, Eigen::Vector3d(0.31, 0.0, 0.0), a).w == 0.0);
    CHECK(kernel(shape, Eigen::Vector3d::Zero(), a).w > 0.0);
    double worst = 0.0;
    for (int t = 0; t < 200; ++t) {
      const Eigen::Vector3d r(u(rng) * 0.5, u(rng) * 0.6, u(rng) * 0.8);
      // Axis-aligned (half-sizes a) and deformed (B = a general matrix) supports.
      Eigen::Matrix3d sheared;
      sheared << 1.0 / 0.3, 1.2, 0.0, -0.4, 1.0 / 0.4, 0.3, 0.2, 0.0, 1.0 / 0.5;
      for (const Eigen::Matrix3d& b :
           {Eigen::Matrix3d(a.cwiseInverse().asDiagonal()), Eigen::Matrix3d(sheared)}) {
        const KernelValue k = kernel(shape, r, b);
        CHECK(k.w >= 0.0);
        CHECK((k.w > 0.0) == in_unit_support(shape, b * r));
        for (int d = 0; d < 3; ++d) {
          const double e = 1e-6;
          Eigen::Vector3d rp = r, rm = r;
          rp[d] += e;
          rm[d] -= e;
          const double fd = (kernel(shape, rp, b).w - kernel(shape, rm, b).w) / (2 * e);
          worst = std::max(worst, std::abs(fd - k.grad[d]));
        }
      }
    }
    // Central differences of a C1 piecewise polynomial: error O(e^2 / a^3) plus round-off.
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("SPG neighbour search equals brute force for every kernel shape and thread count") {
  const Cloud c = jittered_lattice(9, 0.1, 0.3, 1.6, 11);
  for (const KernelShape shape : kShapes)
    for (const Supports& support : {axis_aligned(c.support), deformed_supports(c, shape)}) {
      const NeighbourList brute = find_neighbours_brute_force(c.x, support, shape);
      omp_set_num_threads(1);
      const NeighbourList one = find_neighbours(c.x, support, shape);
      omp_set_num_threads(2);
      const NeighbourList two = find_neighbours(c.x, support, shape);
      omp_set_num_threads(omp_get_num_procs());
      CHECK(one.offsets == brute.offsets);
      CHECK(one.neighbours == brute.neighbours);
      CHECK(two.neighbours == brute.neighbours);
      // An interior particle of a box support of 1.6 h has about 3^3 neighbours.
      CHECK(brute.count(9 * 9 * 4 + 9 * 4 + 4) >= 8);
    }
  // Inactive particles are in no list and have none.
  std::vector<std::uint8_t> active(static_cast<std::size_t>(c.x.cols()), 1);
  active[100] = 0;
  const NeighbourList some =
      find_neighbours(c.x, axis_aligned(c.support), KernelShape::cubic_box, active);
  CHECK(some.count(100) == 0);
  CHECK(std::find(some.neighbours.begin(), some.neighbours.end(), 100) == some.neighbours.end());
}

TEST_CASE("RK shape functions reproduce constant and linear fields and their gradients") {
  const Cloud c = jittered_lattice(7, 0.2, 0.25, 1.6, 5);
  for (const KernelShape shape : kShapes)
    for (const Supports& support : {axis_aligned(c.support), deformed_supports(c, shape)}) {
      const NeighbourList list = find_neighbours(c.x, support, shape);
      std::vector<Index> degenerate;
      const ShapeFunctions sf = shape_functions(c.x, support, shape, list, degenerate);
      CHECK(degenerate.empty());
      double worst_value = 0.0, worst_gradient = 0.0;
      for (Index i = 0; i < c.x.cols(); ++i) {  // every particle, the boundary ones included
        double sum = 0.0;
        Eigen::Vector3d linear = Eigen::Vector3d::Zero(), grad_sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d grad_linear = Eigen::Matrix3d::Zero();
        for (Index p = list.offsets[static_cast<std::size_t>(i)];
             p < list.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
          const Index j = list.neighbours[static_cast<std::size_t>(p)];
          const double phi = sf.value[static_cast<std::size_t>(p)];
          sum += phi;
          linear += phi * c.x.col(j);
          grad_sum += sf.gradient.col(p);
          grad_linear += c.x.col(j) * sf.gradient.col(p).transpose();
        }
        worst_value = std::max({worst_value, std::abs(sum - 1.0), (linear - c.x.col(i)).norm()});
        worst_gradient = std::max(
            {worst_gradient, grad_sum.norm(), (grad_linear - Eigen::Matrix3d::Identity()).norm()});
      }
      CHECK(worst_value < 1e-12);
      CHECK(worst_gradient < 1e-10);
    }
}

TEST_CASE("a degenerate (flat) particle neighbourhood is named, not silently used") {
  // One layer of particles: every moment matrix is singular in z.
  Cloud c = jittered_lattice(5, 0.2, 0.0, 1.6, 1);
  Eigen::Matrix3Xd flat = c.x.leftCols(25);
  const Supports support = axis_aligned(c.support.leftCols(25));
  const NeighbourList list = find_neighbours(flat, support, KernelShape::cubic_box);
  std::vector<Index> degenerate;
  const ShapeFunctions sf =
      shape_functions(flat, support, KernelShape::cubic_box, list, degenerate);
  CHECK(degenerate.size() == 25);
  for (double v : sf.value)
    CHECK(v == 0.0);
}

TEST_CASE("particles from hexahedra: lumped volume, spacing per axis from the incident edges") {
  // Two unit cubes side by side in x, then scaled by 0.5 in z.
  Eigen::Matrix3Xd x(3, 12);
  int n = 0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        x.col(n++) = Eigen::Vector3d(i, j, 0.5 * k);
  auto id = [](int i, int j, int k) { return static_cast<Index>(i + 3 * (j + 2 * k)); };
  std::vector<std::array<Index, 8>> hexes;
  for (int i = 0; i < 2; ++i)
    hexes.push_back({id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1),
                     id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)});
  const GeneratedParticles p = particles_from_hexahedra(x, hexes, {0.5, 0.5});
  REQUIRE(p.nodes.size() == 12);
  double total = 0.0;
  for (double v : p.volume)
    total += v;
  CHECK(total == doctest::Approx(1.0));
  CHECK(p.volume[static_cast<std::size_t>(id(1, 0, 0))] == doctest::Approx(0.125));  // shared
  CHECK(p.volume[static_cast<std::size_t>(id(0, 0, 0))] == doctest::Approx(0.0625));
  for (Eigen::Index i = 0; i < p.spacing.cols(); ++i)  // edges of 1 in x and y, 0.5 in z
    CHECK((p.spacing.col(i) - Eigen::Vector3d(1.0, 1.0, 0.5)).norm() == doctest::Approx(0.0));
  // DX, DY, DZ differ: the global axes, half-sizes DX/DY/DZ x spacing.
  const auto a = support_matrices(p, Eigen::Vector3d(1.5, 1.6, 1.7));
  CHECK(Eigen::Map<const Eigen::Matrix3d>(a.col(0).data())
            .isApprox(Eigen::Vector3d(1.5, 1.6, 0.85).asDiagonal().toDenseMatrix()));
  // A mesh along x, y, z keeps the global frame, also with equal DX, DY, DZ.
  const auto b = support_matrices(p, Eigen::Vector3d::Constant(1.5));
  for (Eigen::Index i = 0; i < b.cols(); ++i)
    CHECK(Eigen::Map<const Eigen::Matrix3d>(b.col(i).data())
              .isApprox(Eigen::Vector3d(1.5, 1.5, 0.75).asDiagonal().toDenseMatrix()));
  // The mesh turned by 45 degrees about z: the x and y extents of its edges shrink to 0.71.
  const double c = std::sqrt(0.5);
  Eigen::Matrix3d turn;
  turn << c, -c, 0.0, c, c, 0.0, 0.0, 0.0, 1.0;
  const GeneratedParticles q = particles_from_hexahedra(turn * x, hexes, {0.5, 0.5});
  CHECK((q.spacing.col(0) - Eigen::Vector3d(c, c, 0.5)).norm() == doctest::Approx(0.0));
}

TEST_CASE("particles from hexahedra: the support turns with a turned mesh") {
  // 3 x 3 x 1 cells of 1 x 2 x 1 turned by 30 degrees about z: the four nodes inside the
  // square in plane (4 elements around them) measure the spacing along the mesh lines, (1, 2,
  // 1), and their support turns with the mesh: A0 = T diag(1.5, 3, 1.5) T^T.
  const double angle = std::acos(-1.0) / 6.0;
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Matrix3Xd x(3, 32);
  auto id = [](int i, int j, int k) { return static_cast<Index>(i + 4 * (j + 4 * k)); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        x.col(id(i, j, k)) = turn * Eigen::Vector3d(i, 2 * j, k);
  std::vector<std::array<Index, 8>> hexes;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      hexes.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0),
                       id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1)});
  const GeneratedParticles p =
      particles_from_hexahedra(x, hexes, std::vector<double>(hexes.size(), 1.0));
  const auto a = support_matrices(p, Eigen::Vector3d::Constant(1.5));
  const Eigen::Matrix3d expected =
      turn * Eigen::Vector3d(1.5, 3.0, 1.5).asDiagonal() * turn.transpose();
  for (int k = 0; k < 2; ++k)
    for (int j = 1; j < 3; ++j)
      for (int i = 1; i < 3; ++i) {
        const Eigen::Index col = id(i, j, k);
        Eigen::Vector3d sorted = p.frame_spacing.col(col);  // the frame's axes in any order
        std::sort(sorted.begin(), sorted.end());
        CHECK((sorted - Eigen::Vector3d(1.0, 1.0, 2.0)).norm() < 1e-12);
        CHECK((Eigen::Map<const Eigen::Matrix3d>(a.col(col).data()) - expected).norm() < 1e-12);
        // Along x the edges reach only 2 sin 30 = 1 (the y edge): the global box is smaller.
        CHECK(p.spacing(0, col) == doctest::Approx(2.0 * std::sin(angle)));
      }
}

}  // namespace mcdyna::solver::spg
