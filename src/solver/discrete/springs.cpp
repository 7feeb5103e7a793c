#include "solver/discrete/springs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdyna::solver::discrete {

double axial_force(const SpringLaw& law, const std::vector<LoadCurve>& curves, double scale,
                   double d, double rate) {
  switch (law.law) {
    case Law::linear_spring:
      return scale * law.stiffness * d;
    case Law::viscous_damper:
      return scale * law.damping * rate;
    case Law::curve_spring: {
      const double f = curves[static_cast<std::size_t>(law.force_curve)](d);
      const double r =
          law.rate_curve >= 0 ? curves[static_cast<std::size_t>(law.rate_curve)](rate) : 1.0;
      return scale * f * r;
    }
  }
  return 0.0;
}

double stable_step(double k, double c, double m) {
  if (k > 0.0) return 2.0 * (std::sqrt(m / k + c * c / (4.0 * k * k)) - c / (2.0 * k));
  if (c > 0.0) return 2.0 * m / c;
  return std::numeric_limits<double>::infinity();
}

double steepest_slope(const model::Curve& curve) {
  double steepest = 0.0;
  const auto& p = curve.points;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double dx = curve.abscissa_scale * (p[i].first - p[i - 1].first);
    const double dy = curve.ordinate_scale * (p[i].second - p[i - 1].second);
    if (dx != 0.0) steepest = std::max(steepest, std::abs(dy / dx));
  }
  return steepest;
}

}  // namespace mcdyna::solver::discrete
