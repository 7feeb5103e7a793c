#pragma once
/// *DEFINE_CURVE as the solver evaluates it: scales and offsets applied once at compile time
/// (x = SFA * a + OFFA, y = SFO * o + OFFO), piecewise-linear in between, linear extrapolation
/// from the end segments as LS-DYNA load curves do.
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::solver {

class LoadCurve {
 public:
  LoadCurve() = default;
  explicit LoadCurve(const model::Curve& curve);

  /// Ordinate at abscissa `x`; the first/last segment is extended beyond the ends.
  [[nodiscard]] double operator()(double x) const;
  /// Integral of the curve from x0 to x1 (exact for the piecewise-linear curve).
  [[nodiscard]] double integral(double x0, double x1) const;
  [[nodiscard]] double last_abscissa() const { return x_.empty() ? 0.0 : x_.back(); }
  [[nodiscard]] model::Id id() const { return id_; }

 private:
  [[nodiscard]] double primitive(double x) const;
  model::Id id_ = 0;
  std::vector<double> x_, y_;
  std::vector<double> cumulative_;  ///< integral from x_[0] to x_[i]
};

}  // namespace mcdyna::solver
