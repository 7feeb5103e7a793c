#pragma once
/// Discrete springs and dampers (*ELEMENT_DISCRETE on a *SECTION_DISCRETE part): two nodes, an
/// axial force along N1 -> N2 from the change of length (deflection, tension positive) and its
/// rate. The laws of *MAT_SPRING_ELASTIC (F = K d), *MAT_DAMPER_VISCOUS (F = DC d') and
/// *MAT_SPRING_NONLINEAR_ELASTIC (F = LCD(d) LCR(d')), each times the element's scale S. The
/// elements carry no mass: their nodes take it from elsewhere.
#include <array>
#include <vector>

#include "model/entities.hpp"
#include "solver/curve.hpp"

namespace mcdyna::solver::discrete {

using Index = std::int32_t;

enum class Law { linear_spring, viscous_damper, curve_spring };

/// A compiled spring or damper material.
struct SpringLaw {
  Law law = Law::linear_spring;
  double stiffness = 0.0;  ///< K, force per length
  double damping = 0.0;    ///< DC, force per velocity
  Index force_curve = -1;  ///< LCD, force against deflection (index into the state's curves)
  Index rate_curve = -1;   ///< LCR, scale against deflection rate, or -1
  /// The stiffness the stable step sees: K, or LCD's steepest segment (0 for a damper).
  double step_stiffness = 0.0;
};

/// The elements, in deck order, and what changes as they work.
struct Springs {
  std::vector<model::Id> ids, parts;  ///< user IDs (element, part)
  std::vector<Index> part_index;      ///< the part's position in the deck's parts
  std::vector<std::array<Index, 2>> nodes;
  std::vector<Index> law;  ///< into `laws`
  std::vector<double> scale, offset, initial_length;
  std::vector<SpringLaw> laws;
  /// Last force pass: axial force (tension positive), deflection (change of length + OFFSET)
  /// and its rate; and the work done on the element so far (stored in springs, dissipated in
  /// dampers), summed by the trapezoidal rule over each step's change of deflection.
  std::vector<double> force, deflection, rate, work;
  [[nodiscard]] Index count() const { return static_cast<Index>(ids.size()); }
};

/// The axial force of a law, scaled by S, at deflection `d` and rate `rate`.
double axial_force(const SpringLaw& law, const std::vector<LoadCurve>& curves, double scale,
                   double d, double rate);

/// The stable step of a spring of stiffness k and damping c between masses that answer with
/// the reduced mass m: the critical step 2/w (sqrt(1 + z^2) - z) of the damped oscillator
/// (w^2 = k/m, z = c / (2 m w)), which is 2 m / c for a pure damper; infinite for neither.
double stable_step(double stiffness, double damping, double reduced_mass);

/// The steepest slope of a force curve as the solver evaluates it (scales applied).
double steepest_slope(const model::Curve& curve);

}  // namespace mcdyna::solver::discrete
