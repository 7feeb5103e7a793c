#include "solver/spg/shape_functions.hpp"

#include <Eigen/Dense>

#include <algorithm>

namespace mcdyna::solver::spg {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;
using Vec10 = Eigen::Matrix<double, 10, 1>;
using Mat10 = Eigen::Matrix<double, 10, 10>;

// The quadratic basis [1, z, z1^2, z2^2, z3^2, z1 z2, z2 z3, z3 z1].
Vec10 quadratic_basis(const Eigen::Vector3d& z) {
  Vec10 h;
  h << 1.0, z.x(), z.y(), z.z(), z.x() * z.x(), z.y() * z.y(), z.z() * z.z(), z.x() * z.y(),
      z.y() * z.z(), z.z() * z.x();
  return h;
}

// Second-derivative functions of particle I's row (ShapeFunctions::hessian), from the window
// values w_J (`windows`, in row order). With r = X_I - X_J and z = B r (B = I's support
// matrix), a quadratic g has g(X_J) = l_J^T a_L + q_J^T a_Q, l = [1, z], q = [z1^2, z2^2, z3^2,
// z1 z2, z2 z3, z3 z1], a_Q = [Hz11/2, Hz22/2, Hz33/2, Hz12, Hz23, Hz31] (Hz the z-Hessian).
// With the moment blocks A = sum w l l^T, Bq = sum w l q^T, C = sum w q q^T, the quadratic part
// of each neighbour orthogonal to the linear basis, q'_J = q_J - Bq^T A^-1 l_J, has
// sum_J w q'_J l_J^T = 0, so psi_J = w_J S^+ q'_J (S = C - Bq^T A^-1 Bq, the Schur complement)
// gives sum_J psi_J g(X_J) = S^+ S a_Q: exactly zero for every linear field whatever S^+ keeps,
// and exact for the curvature in the directions S resolves. A row on a surface has two layers
// of neighbours across it (support 1.5 spacings), where z_n^2 is a multiple of z_n: S is
// singular along that combination, and near-singular once the layers are perturbed; a direction
// of S weaker than kMinimumHessianRatio times its largest is left out (its curvature zero), so
// no row's stiffness exceeds about 1 / kMinimumHessianRatio times a resolved row's.
// The x-Hessian is B^T Hz B.
void row_hessian(const Eigen::Matrix3Xd& x, const Eigen::Matrix3d& to_unit,
                 const NeighbourList& list, Index i, const std::vector<double>& windows,
                 std::size_t first, std::size_t last, ShapeFunctions& out) {
  const Eigen::Vector3d xi = x.col(i);
  Mat10 m = Mat10::Zero();
  for (std::size_t p = first; p < last; ++p) {
    const Vec10 h = quadratic_basis(to_unit * (xi - x.col(list.neighbours[p])));
    m.noalias() += windows[p - first] * h * h.transpose();
  }
  for (std::size_t p = first; p < last; ++p)
    out.hessian.col(static_cast<Eigen::Index>(p)).setZero();
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Mat46 = Eigen::Matrix<double, 4, 6>;
  const Eigen::LDLT<Mat4> linear(m.topLeftCorner<4, 4>());  // well conditioned: checked by caller
  const Mat46 projection = linear.solve(m.topRightCorner<4, 6>());  // A^-1 Bq
  const Mat6 schur =
      m.bottomRightCorner<6, 6>() - m.topRightCorner<4, 6>().transpose() * projection;
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(schur);
  const double hi = eig.eigenvalues()[5];
  if (!(hi > 0.0)) return;
  Mat6 inverse = Mat6::Zero();
  for (int k = 0; k < 6; ++k)
    if (eig.eigenvalues()[k] > kMinimumHessianRatio * hi)
      inverse.noalias() +=
          eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose() / eig.eigenvalues()[k];
  // Hz entries from a_Q: the squares carry a factor 2.
  const Eigen::Matrix<double, 6, 1> factor =
      (Eigen::Matrix<double, 6, 1>() << 2, 2, 2, 1, 1, 1).finished();
  const int pa[6] = {0, 1, 2, 0, 1, 2}, pb[6] = {0, 1, 2, 1, 2, 0};
  for (std::size_t p = first; p < last; ++p) {
    const Vec10 h = quadratic_basis(to_unit * (xi - x.col(list.neighbours[p])));
    const Eigen::Matrix<double, 6, 1> q = h.tail<6>() - projection.transpose() * h.head<4>();
    const Eigen::Matrix<double, 6, 1> hz = windows[p - first] * factor.cwiseProduct(inverse * q);
    Eigen::Matrix3d z;  // the z-Hessian function of this pair, symmetric
    for (int c = 0; c < 6; ++c) {
      z(pa[c], pb[c]) = hz[c];
      z(pb[c], pa[c]) = hz[c];
    }
    const Eigen::Matrix3d hx = to_unit.transpose() * z * to_unit;
    for (int c = 0; c < 6; ++c)
      out.hessian(c, static_cast<Eigen::Index>(p)) = hx(pa[c], pb[c]);
  }
}

// Shape functions of one particle; false when its moment matrix is degenerate.
bool particle_shape(const Eigen::Matrix3Xd& x, const Supports& support, KernelShape shape,
                    const NeighbourList& list, Index i, double minimum_ratio, bool second,
                    ShapeFunctions& out) {
  const auto first = static_cast<std::size_t>(list.offsets[static_cast<std::size_t>(i)]);
  const auto last = static_cast<std::size_t>(list.offsets[static_cast<std::size_t>(i) + 1]);
  // The linear basis in particle I's own support coordinates B_I r: the span, and so phi, is
  // that of [1, r], but the moment matrix no longer depends on how the support is stretched,
  // so its conditioning measures how the neighbours are placed, not how the material deformed.
  const Eigen::Matrix3d to_unit = support.matrix(i);
  const Eigen::Vector3d xi = x.col(i);
  Mat4 m = Mat4::Zero();
  Mat4 dm[3] = {Mat4::Zero(), Mat4::Zero(), Mat4::Zero()};
  for (std::size_t p = first; p < last; ++p) {
    const Index j = list.neighbours[p];
    const Eigen::Vector3d r = xi - x.col(j);
    const KernelValue k = kernel(shape, r, Eigen::Matrix3d(support.matrix(j)));
    Vec4 h;
    h << 1.0, to_unit * r;
    m.noalias() += k.w * h * h.transpose();
    for (int d = 0; d < 3; ++d) {
      // d_d (w H H^T) = (d_d w) H H^T + w (e H^T + H e^T), e = d_d H = [0, B_I e_d].
      Vec4 e;
      e << 0.0, to_unit.col(d);
      dm[d].noalias() +=
          k.grad[d] * h * h.transpose() + k.w * (e * h.transpose() + h * e.transpose());
    }
    out.value[p] = k.w;  // kernel values and gradients kept for the second pass
    out.gradient.col(static_cast<Eigen::Index>(p)) = k.grad;
  }
  // Degenerate when the neighbours do not span 3-D (ratio of extreme eigenvalues).
  const Eigen::SelfAdjointEigenSolver<Mat4> eig(m, Eigen::EigenvaluesOnly);
  const double lo = eig.eigenvalues()[0], hi = eig.eigenvalues()[3];
  if (!(hi > 0.0) || !(lo > minimum_ratio * hi)) {
    for (std::size_t p = first; p < last; ++p) {
      out.value[p] = 0.0;
      out.gradient.col(static_cast<Eigen::Index>(p)).setZero();
    }
    return false;
  }
  if (second) {
    const std::vector<double> windows(out.value.begin() + static_cast<std::ptrdiff_t>(first),
                                      out.value.begin() + static_cast<std::ptrdiff_t>(last));
    row_hessian(x, to_unit, list, i, windows, first, last, out);
  }
  const Eigen::LDLT<Mat4> solve(m);
  const Vec4 b = solve.solve(Vec4::UnitX());
  Vec4 db[3];
  for (int d = 0; d < 3; ++d)
    db[d] = -solve.solve(dm[d] * b);
  for (std::size_t p = first; p < last; ++p) {
    const Index j = list.neighbours[p];
    const Eigen::Vector3d r = xi - x.col(j);
    Vec4 h;
    h << 1.0, to_unit * r;
    const double w = out.value[p];
    const Eigen::Vector3d grad_w = out.gradient.col(static_cast<Eigen::Index>(p));
    const double bh = b.dot(h);
    out.value[p] = w * bh;
    for (int d = 0; d < 3; ++d)
      out.gradient(d, static_cast<Eigen::Index>(p)) =
          grad_w[d] * bh + w * (db[d].dot(h) + b.tail<3>().dot(to_unit.col(d)));
  }
  return true;
}

}  // namespace

ShapeFunctions shape_functions(const Eigen::Matrix3Xd& x, const Supports& support,
                               KernelShape shape, const NeighbourList& list,
                               std::vector<Index>& degenerate,
                               const std::vector<std::uint8_t>& damaged, bool second_derivatives) {
  ShapeFunctions out;
  const std::size_t pairs = list.neighbours.size();
  out.value.assign(pairs, 0.0);
  out.gradient.setZero(3, static_cast<Eigen::Index>(pairs));
  if (second_derivatives) out.hessian.setZero(6, static_cast<Eigen::Index>(pairs));
  const auto n = static_cast<Index>(list.offsets.size()) - 1;
  std::vector<std::uint8_t> bad(static_cast<std::size_t>(std::max<Index>(n, 0)), 0);
#pragma omp parallel for schedule(dynamic, 256) if (n > 2048)
  for (Index i = 0; i < n; ++i)
    if (list.count(i) > 0 &&
        !particle_shape(x, support, shape, list, i,
                        !damaged.empty() && damaged[static_cast<std::size_t>(i)]
                            ? kMinimumDamagedMomentRatio
                            : kMinimumMomentRatio,
                        second_derivatives, out))
      bad[static_cast<std::size_t>(i)] = 1;
  degenerate.clear();
  for (Index i = 0; i < n; ++i)
    if (bad[static_cast<std::size_t>(i)]) degenerate.push_back(i);
  return out;
}

}  // namespace mcdyna::solver::spg
