// The smallest principal stretch the SPG step follows (spg/smallest_stretch.hpp), held against
// Eigen's iterative eigensolver of F^T F on deformations of every kind the plate sees.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "solver/spg/smallest_stretch.hpp"

namespace mcdyna::test {

namespace {

using Mat3 = Eigen::Matrix3d;
namespace spg = solver::spg;

// sqrt(lambda_min(F^T F)) by Jacobi-like QR iteration: accurate to round-off of |C|.
double reference_stretch(const Mat3& f) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(f.transpose() * f, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eig.eigenvalues()(0), 0.0));
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

// F = R diag(stretches) Q: principal stretches given, directions at random.
Mat3 deformation(std::mt19937& rng, double a, double b, double c) {
  return random_rotation(rng) * Eigen::Vector3d(a, b, c).asDiagonal() * random_rotation(rng);
}

// Eigen's closed form, which the solver used before: the same cubic, solved with atan2/sincos.
double direct_stretch(const Mat3& f) {
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(f.transpose() * f, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eig.eigenvalues()(0), 0.0));
}

// |lambda - lambda_ref| against |C| = largest stretch squared, of `stretch_of`.
template <class Stretch>
double eigenvalue_error(const Mat3& f, Stretch&& stretch_of) {
  const double got = stretch_of(f), want = reference_stretch(f);
  const double largest = Eigen::JacobiSVD<Mat3>(f).singularValues()(0);
  return std::abs(got * got - want * want) / (largest * largest);
}
double eigenvalue_error(const Mat3& f) {
  return eigenvalue_error(f, [](const Mat3& g) { return spg::smallest_stretch(g); });
}

}  // namespace

TEST_CASE("smallest stretch: distinct stretches to the polynomial's accuracy") {
  // Stretches 0.05-3 in any order and any directions: the three roots apart, so the error is
  // the fit's 4.9e-13 times p (<= |C|) plus round-off of |C|: 1e-12 |C| bounds it.
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> stretch(0.05, 3.0);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double a = stretch(rng), b = stretch(rng), c = stretch(rng);
    const double gap = std::min({std::abs(a - b), std::abs(b - c), std::abs(a - c)});
    if (gap < 1e-3 * std::max({a, b, c})) continue;
    worst = std::max(worst, eigenvalue_error(deformation(rng, a, b, c)));
  }
  MESSAGE("largest error, distinct stretches: " << worst << " |C|");
  CHECK(worst < 1e-12);
}

TEST_CASE("smallest stretch: equal stretches (double and triple roots)") {
  // Where two roots meet, a root of the cubic moves as the square root of a change of its
  // coefficients, so their round-off (eps |C|) moves it by sqrt(eps) |C| = 1.5e-8 |C|, in any
  // closed form: Eigen's computeDirect, which the solver used before, is measured beside it.
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> stretch(0.1, 2.0);
  const auto direct = [](const Mat3& g) { return direct_stretch(g); };
  double worst = 0.0, worst_direct = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const double a = stretch(rng), b = stretch(rng);
    for (const Mat3& f : {deformation(rng, a, b, b), deformation(rng, b, a, b),  // uniaxial
                          deformation(rng, a, a, a)}) {                          // a rotation
      worst = std::max(worst, eigenvalue_error(f));
      worst_direct = std::max(worst_direct, eigenvalue_error(f, direct));
    }
  }
  MESSAGE("largest error, equal stretches: " << worst << " |C| (computeDirect " << worst_direct
                                             << " |C|)");
  CHECK(worst < std::sqrt(std::numeric_limits<double>::epsilon()));
  // Exact cases: the identity, a pure rotation, a uniaxial squeeze along x.
  CHECK(spg::smallest_stretch(Mat3::Identity()) == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(spg::smallest_stretch(random_rotation(rng)) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(spg::smallest_stretch(Eigen::Vector3d(0.6, 1.0, 1.0).asDiagonal().toDenseMatrix()) ==
        doctest::Approx(0.6).epsilon(1e-12));
}

TEST_CASE("smallest stretch: a collapsed direction gives zero, never a NaN") {
  Mat3 flat = Mat3::Identity();
  flat(2, 2) = 0.0;  // the support squeezed to a plane
  // lambda = 0 within the fit's 4.9e-13 p (p = 1/3 here): the stretch within sqrt of that.
  CHECK(spg::smallest_stretch(flat) < 1e-6);
  CHECK(std::isfinite(spg::smallest_stretch(Mat3::Zero())));
  CHECK(spg::smallest_stretch(Mat3::Zero()) == 0.0);
}

}  // namespace mcdyna::test
