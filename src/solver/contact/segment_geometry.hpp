#pragma once
/// Closest points on contact segments. A quadrilateral segment is taken as its two triangles
/// (0 1 2) and (0 2 3) with the quadrilateral's normal (the cross product of its diagonals),
/// exact for flat segments and a small smoothing of warped ones; a triangle repeats node 2.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

namespace mcdyna::solver::contact {

struct SegmentPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< closest point on the segment
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit segment normal
  std::array<double, 4> weights{};  ///< point = sum weights_k x_k (for the master forces)
};

/// Closest point on triangle (a, b, c) to p, as barycentric weights (Ericson, Real-Time
/// Collision Detection, §5.1.5).
std::array<double, 3> closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Closest point on the segment with corners x (x[3] == x[2] for a triangle) to p.
SegmentPoint closest_on_segment(const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 4>& x);

}  // namespace mcdyna::solver::contact
