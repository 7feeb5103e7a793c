#pragma once
/// The layer points of the shells and of the Hughes-Liu beams' fibres (shells/shells.hpp,
/// beams/beams.hpp).
#include <Eigen/Core>

#include <vector>

namespace mcdyna::solver {

/// The points of the shells: the full Cauchy stress in the element's corotational frame (z the
/// normal; sigma_zz = 0, plane stress), rows xx yy zz xy yz zx.
struct ShellPoints {
  Eigen::Matrix<double, 6, Eigen::Dynamic> stress;
  Eigen::Matrix<double, 6, Eigen::Dynamic> back_stress;  ///< MAT_003 kinematic part, or empty
  std::vector<double> plastic_strain, damage;
};

}  // namespace mcdyna::solver
