#include "solver/spg/shape_functions.hpp"

#include <Eigen/Dense>

#include <algorithm>

namespace mcdyna::solver::spg {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// Shape functions of one particle; false when its moment matrix is degenerate.
bool particle_shape(const Eigen::Matrix3Xd& x, const Supports& support, KernelShape shape,
                    const NeighbourList& list, Index i, double minimum_ratio, ShapeFunctions& out) {
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
                               const std::vector<std::uint8_t>& damaged) {
  ShapeFunctions out;
  const std::size_t pairs = list.neighbours.size();
  out.value.assign(pairs, 0.0);
  out.gradient.setZero(3, static_cast<Eigen::Index>(pairs));
  const auto n = static_cast<Index>(list.offsets.size()) - 1;
  std::vector<std::uint8_t> bad(static_cast<std::size_t>(std::max<Index>(n, 0)), 0);
#pragma omp parallel for schedule(dynamic, 256) if (n > 2048)
  for (Index i = 0; i < n; ++i)
    if (list.count(i) > 0 &&
        !particle_shape(x, support, shape, list, i,
                        !damaged.empty() && damaged[static_cast<std::size_t>(i)]
                            ? kMinimumDamagedMomentRatio
                            : kMinimumMomentRatio,
                        out))
      bad[static_cast<std::size_t>(i)] = 1;
  degenerate.clear();
  for (Index i = 0; i < n; ++i)
    if (bad[static_cast<std::size_t>(i)]) degenerate.push_back(i);
  return out;
}

}  // namespace mcdyna::solver::spg
