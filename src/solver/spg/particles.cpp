#include "solver/spg/particles.hpp"

#include <algorithm>

namespace mcdyna::solver::spg {

GeneratedParticles particles_from_hexahedra(const Eigen::Matrix3Xd& positions,
                                            const std::vector<std::array<Index, 8>>& elements,
                                            const std::vector<double>& volumes) {
  static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  GeneratedParticles p;
  for (const auto& e : elements)
    p.nodes.insert(p.nodes.end(), e.begin(), e.end());
  std::sort(p.nodes.begin(), p.nodes.end());
  p.nodes.erase(std::unique(p.nodes.begin(), p.nodes.end()), p.nodes.end());
  auto particle = [&](Index node) {
    return static_cast<std::size_t>(std::lower_bound(p.nodes.begin(), p.nodes.end(), node) -
                                    p.nodes.begin());
  };
  p.volume.assign(p.nodes.size(), 0.0);
  p.spacing.setZero(3, static_cast<Eigen::Index>(p.nodes.size()));
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const auto& e = elements[k];
    for (const Index n : e)  // a repeated node of a degenerate element gets each share
      p.volume[particle(n)] += volumes[k] / 8.0;
    for (const auto& edge : kEdges) {
      const Index a = e[static_cast<std::size_t>(edge[0])],
                  b = e[static_cast<std::size_t>(edge[1])];
      const Eigen::Vector3d extent = (positions.col(a) - positions.col(b)).cwiseAbs();
      for (const Index n : {a, b}) {
        auto s = p.spacing.col(static_cast<Eigen::Index>(particle(n)));
        s = s.cwiseMax(extent);
      }
    }
  }
  return p;
}

Eigen::Matrix3Xd support_sizes(const GeneratedParticles& p, const Eigen::Vector3d& scale) {
  Eigen::Matrix3Xd a(3, static_cast<Eigen::Index>(p.nodes.size()));
  for (std::size_t i = 0; i < p.nodes.size(); ++i)
    a.col(static_cast<Eigen::Index>(i)) =
        scale.cwiseProduct(p.spacing.col(static_cast<Eigen::Index>(i)));
  return a;
}

}  // namespace mcdyna::solver::spg
