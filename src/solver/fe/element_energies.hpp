#pragma once
/// The finite-element blocks' shares of glstat and matsum: the internal and hourglass energy of
/// elements that carry both (solids, shells), eroded ones' in the eroded terms, in element order;
/// and a corner's lumped share of its part's kinetic energy and momentum.
#include "solver/energy.hpp"

namespace mcdyna::solver::fe {

template <class Elements>
void add_element_energies(const Elements& el, EnergySummary& e) {
  for (std::size_t i = 0; i < el.ids.size(); ++i) {
    (el.eroded[i] ? e.eroded_internal : e.internal) += el.internal_energy[i];
    (el.eroded[i] ? e.eroded_hourglass : e.hourglass) += el.hourglass_energy[i];
  }
}

/// Node n's share m of an element's mass: 1/2 m v^{n-1/2} . v^{n+1/2} and m times the mean
/// velocity (`previous` = v^{n-1/2}).
inline void add_corner_motion(PartSummary& ps, const Nodes& nd, const Eigen::Matrix3Xd& previous,
                              Index n, double m) {
  ps.kinetic += 0.5 * m * previous.col(n).dot(nd.velocity.col(n));
  ps.momentum += 0.5 * m * (previous.col(n) + nd.velocity.col(n));
  ps.mass += m;
}

/// The same with the corner's rotary inertia (shells, beams): 1/2 I w^{n-1/2} . w^{n+1/2} too.
inline void add_corner_motion(PartSummary& ps, const Nodes& nd, const Eigen::Matrix3Xd& previous,
                              Index n, double m, double inertia) {
  ps.kinetic += 0.5 * m * previous.col(n).dot(nd.velocity.col(n)) +
                0.5 * inertia * nd.previous_angular_velocity.col(n).dot(nd.angular_velocity.col(n));
  ps.momentum += 0.5 * m * (previous.col(n) + nd.velocity.col(n));
  ps.mass += m;
}

}  // namespace mcdyna::solver::fe
