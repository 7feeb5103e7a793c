#include "solver/curve.hpp"

#include <algorithm>

namespace mcdyna::solver {

LoadCurve::LoadCurve(const model::Curve& curve) : id_(curve.id) {
  for (const auto& [a, o] : curve.points) {
    x_.push_back(curve.abscissa_scale * a + curve.abscissa_offset);
    y_.push_back(curve.ordinate_scale * o + curve.ordinate_offset);
  }
  cumulative_.assign(x_.size(), 0.0);
  for (std::size_t i = 1; i < x_.size(); ++i)
    cumulative_[i] = cumulative_[i - 1] + 0.5 * (y_[i] + y_[i - 1]) * (x_[i] - x_[i - 1]);
}

namespace {
// Segment [i, i+1] that covers x, the end segments extended outwards. Repeated abscissae (steps)
// pick the later segment, so a step takes its new value at the step.
std::size_t segment(const std::vector<double>& x, double at) {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const auto i = static_cast<std::size_t>(it - x.begin());
  if (i == 0) return 0;
  return std::min(i - 1, x.size() - 2);
}
}  // namespace

double LoadCurve::operator()(double at) const {
  if (x_.empty()) return 0.0;
  if (x_.size() == 1) return y_[0];
  const std::size_t i = segment(x_, at);
  const double span = x_[i + 1] - x_[i];
  if (span <= 0.0) return y_[i + 1];
  return y_[i] + (y_[i + 1] - y_[i]) * (at - x_[i]) / span;
}

double LoadCurve::primitive(double at) const {
  if (x_.empty()) return 0.0;
  if (x_.size() == 1) return y_[0] * (at - x_[0]);
  const std::size_t i = segment(x_, at);
  return cumulative_[i] + 0.5 * (y_[i] + (*this)(at)) * (at - x_[i]);
}

double LoadCurve::integral(double x0, double x1) const {
  return primitive(x1) - primitive(x0);
}

}  // namespace mcdyna::solver
