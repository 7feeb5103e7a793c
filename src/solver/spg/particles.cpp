#include "solver/spg/particles.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace mcdyna::solver::spg {

namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// The mesh frame must beat the global axes by this share of the box volume: a nearly isotropic
// edge set (a structured mesh with a little skew) has an arbitrary eigenframe, which must not
// turn its support.
constexpr double kFrameGain = 0.95;

// Volume measure of the smallest box along the axes V around the nodes of the adjacent
// elements (relative positions r): the product of the largest projections.
double box_measure(const std::vector<Vec3>& r, const Mat3& v) {
  Vec3 reach = Vec3::Zero();
  for (const Vec3& q : r)
    reach = reach.cwiseMax((v.transpose() * q).cwiseAbs());
  return reach.prod();
}

// An orthonormal frame whose first axis is along e and whose second lies in the plane of e and
// the incident edge most nearly perpendicular to it.
Mat3 edge_frame(const Vec3& e, const std::vector<Vec3>& edges) {
  const Vec3 u = e.normalized();
  Vec3 best = Vec3::Zero();
  for (const Vec3& f : edges) {
    const Vec3 g = f - f.dot(u) * u;
    if (g.squaredNorm() > best.squaredNorm() * (1.0 + 1e-12)) best = g;
  }
  Mat3 v;
  v.col(0) = u;
  v.col(1) = best.normalized();
  v.col(2) = u.cross(v.col(1));
  return v;
}

// The frame with the smallest box around the nodes of the adjacent elements, among the
// principal axes of the incident edges and the frames along each incident edge (the principal
// axes are arbitrary where the edges are isotropic, as on a square mesh); the global axes unless
// another frame is clearly smaller. (Boxes around the edges alone would prefer a diamond on a
// structured mesh: the neighbours across the element diagonals decide.)
Mat3 mesh_frame(const std::vector<Vec3>& edges, const std::vector<Vec3>& adjacent) {
  Mat3 best = Mat3::Identity();
  double smallest = kFrameGain * box_measure(adjacent, best);
  auto consider = [&](const Mat3& v) {
    const double m = box_measure(adjacent, v);
    if (m < smallest) {
      smallest = m;
      best = v;
    }
  };
  Mat3 t = Mat3::Zero();
  for (const Vec3& e : edges)
    t.noalias() += e * e.transpose();
  consider(Eigen::SelfAdjointEigenSolver<Mat3>(t).eigenvectors());
  for (const Vec3& e : edges)
    if (e.squaredNorm() > 0.0) consider(edge_frame(e, edges));
  return best;
}

void sort_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

GeneratedParticles particles_from_hexahedra(const Eigen::Matrix3Xd& positions,
                                            const std::vector<std::array<Index, 8>>& elements,
                                            const std::vector<double>& volumes) {
  static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  GeneratedParticles p;
  for (const auto& e : elements)
    p.nodes.insert(p.nodes.end(), e.begin(), e.end());
  sort_unique(p.nodes);
  auto particle = [&](Index node) {
    return static_cast<std::size_t>(std::lower_bound(p.nodes.begin(), p.nodes.end(), node) -
                                    p.nodes.begin());
  };
  const std::size_t n = p.nodes.size();
  p.volume.assign(n, 0.0);
  std::vector<std::vector<Index>> edge_ends(n), adjacent(n);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const auto& e = elements[k];
    for (const Index node : e) {  // a repeated node of a degenerate element gets each share
      p.volume[particle(node)] += volumes[k] / 8.0;
      auto& a = adjacent[particle(node)];
      a.insert(a.end(), e.begin(), e.end());
    }
    for (const auto& edge : kEdges) {
      const Index a = e[static_cast<std::size_t>(edge[0])],
                  b = e[static_cast<std::size_t>(edge[1])];
      if (a == b) continue;
      edge_ends[particle(a)].push_back(b);
      edge_ends[particle(b)].push_back(a);
    }
  }
  p.spacing.setZero(3, static_cast<Eigen::Index>(n));
  p.frame.resize(9, static_cast<Eigen::Index>(n));
  p.frame_spacing.setZero(3, static_cast<Eigen::Index>(n));
  std::vector<Vec3> edges, around;
  for (std::size_t i = 0; i < n; ++i) {
    const auto col = static_cast<Eigen::Index>(i);
    const Vec3 xi = positions.col(p.nodes[i]);
    sort_unique(edge_ends[i]);
    sort_unique(adjacent[i]);
    edges.clear();
    around.clear();
    for (const Index b : edge_ends[i])
      edges.push_back(positions.col(b) - xi);
    for (const Index b : adjacent[i])
      around.push_back(positions.col(b) - xi);
    const Mat3 v = mesh_frame(edges, around);
    Eigen::Map<Mat3>(p.frame.col(col).data()) = v;
    for (const Vec3& e : edges) {
      p.spacing.col(col) = p.spacing.col(col).cwiseMax(e.cwiseAbs());
      p.frame_spacing.col(col) = p.frame_spacing.col(col).cwiseMax((v.transpose() * e).cwiseAbs());
    }
  }
  return p;
}

Eigen::Matrix<double, 9, Eigen::Dynamic> support_matrices(const GeneratedParticles& p,
                                                          const Eigen::Vector3d& scale) {
  const bool isotropic = scale.x() == scale.y() && scale.y() == scale.z();
  Eigen::Matrix<double, 9, Eigen::Dynamic> a(9, static_cast<Eigen::Index>(p.nodes.size()));
  for (Eigen::Index i = 0; i < a.cols(); ++i) {
    Eigen::Map<Mat3> ai(a.col(i).data());
    if (isotropic) {
      const Eigen::Map<const Mat3> v(p.frame.col(i).data());
      ai = v * scale.cwiseProduct(p.frame_spacing.col(i)).asDiagonal() * v.transpose();
    } else {
      ai = scale.cwiseProduct(p.spacing.col(i)).asDiagonal();
    }
  }
  return a;
}

}  // namespace mcdyna::solver::spg
