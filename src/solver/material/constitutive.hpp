#pragma once
/// Integration-point stress updates (deviatoric part) and the element pressure update (EOS or
/// hypoelastic bulk response). Inline: they run inside the element loops once per point per cycle.
/// Tensors are 6-vectors xx yy zz xy yz zx with tensor (not engineering) shear components.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "solver/material/material.hpp"

namespace mcdyna::solver {

/// s : s for a symmetric tensor stored as 6 components.
inline double contract(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

/// What the deviatoric update needs besides the point's own state.
struct PointInput {
  const double* deviatoric_increment;  ///< de = dev(D) dt
  double effective_strain_rate;        ///< sqrt(2/3 D':D'), 1/time
  double temperature;                  ///< element temperature
  double pressure;                     ///< element pressure at the start of the step
};

/// The point's state, by reference into the MaterialPoints arrays.
struct PointState {
  double* deviator;
  double* back_stress;  ///< nullptr unless the material has kinematic hardening
  double& plastic_strain;
  double& damage;
};

struct PointResult {
  double plastic_increment = 0.0;
  bool failed = false;  ///< erosion criterion met at this point
};

namespace detail {

// Radial return for isotropic hardening: solve g(dp) = q - 3G dp - sy(ep + dp) = 0 for dp >= 0
// by Newton's method kept inside the bracket [0, (q - sy(ep)) / 3G] (sy is non-decreasing in
// ep). sy0 and h0 are the flow stress and slope at ep, which the caller already has. The
// iteration stops on the residual (|g| <= 1e-12 q, far below any stress that matters), so the
// converged point costs no extra evaluation of the hardening law.
template <typename Yield>
double radial_return(double q, double shear, double ep, double sy0, double h0, Yield yield) {
  double lo = 0.0, hi = (q - sy0) / (3.0 * shear);
  double dp = 0.0, g = q - sy0, slope = h0;
  for (int it = 0; it < 20; ++it) {
    const double next = dp + g / (3.0 * shear + slope);
    dp = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    double sy = 0.0;
    yield(ep + dp, sy, slope);
    g = q - 3.0 * shear * dp - sy;
    if (std::abs(g) <= 1.0e-12 * q) break;
    if (g > 0.0)
      lo = dp;
    else
      hi = dp;
  }
  return dp;
}

inline double cowper_symonds(double c, double p, double rate) {
  if (c <= 0.0 || rate <= 0.0) return 1.0;
  return 1.0 + std::pow(rate / c, 1.0 / p);
}

inline void table_yield(const PiecewiseLinearModel& m, double ep, double& sy, double& slope) {
  const auto& x = m.curve_strain;
  const auto& y = m.curve_stress;
  if (x.size() == 1) {
    sy = y[0];
    slope = 0.0;
    return;
  }
  const auto it = std::upper_bound(x.begin(), x.end(), ep);
  std::size_t i = it == x.begin() ? 0 : static_cast<std::size_t>(it - x.begin()) - 1;
  i = std::min(i, x.size() - 2);
  slope = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  sy = y[i] + slope * (ep - x[i]);
}

// Homologous temperature T* = (T - TR) / (TM - TR); 0 when TM is not above TR (no softening).
inline double homologous_temperature(const JohnsonCookModel& m, double room, double temperature) {
  if (m.melt_temperature <= room) return 0.0;
  return (temperature - room) / (m.melt_temperature - room);
}

// 1 - T*^M for 0 < T* < 1.
inline double jc_thermal_factor(const JohnsonCookModel& m, double ts) {
  return ts <= 0.0 ? 1.0 : 1.0 - std::pow(ts, m.m);
}

// A lower bound of 1 - T*^M that needs no power: 1 - T* when M >= 1, else 0.
inline double jc_thermal_floor(const JohnsonCookModel& m, double ts) {
  if (ts <= 0.0) return 1.0;
  return m.m >= 1.0 ? 1.0 - ts : 0.0;
}

// Scales the trial deviator (equivalent stress q) back onto the yield surface; returns dp.
template <typename Yield>
double isotropic_return(double* s, double q, double shear, double& ep, double sy0, double h0,
                        Yield yield) {
  if (q <= sy0) return 0.0;
  const double dp = radial_return(q, shear, ep, sy0, h0, yield);
  const double scale = 1.0 - 3.0 * shear * dp / q;
  for (int k = 0; k < 6; ++k)
    s[k] *= scale;
  ep += dp;
  return dp;
}

}  // namespace detail

// The return of each deviatoric model, after the elastic trial s += 2 G de (update_deviator).

inline void return_deviator(const Material& /*m*/, const ElasticModel& /*model*/,
                            const PointInput& /*in*/, PointState /*st*/, PointResult& /*r*/) {}

// Mixed hardening (BETA) with Cowper-Symonds scaling of the yield stress.
inline void return_deviator(const Material& m, const PlasticKinematicModel& k, const PointInput& in,
                            PointState st, PointResult& r) {
  double* s = st.deviator;
  const double rf =
      detail::cowper_symonds(k.cowper_symonds_c, k.cowper_symonds_p, in.effective_strain_rate);
  const double beta = k.isotropic_fraction, hp = k.hardening_modulus;
  double xi[6];
  for (int i = 0; i < 6; ++i)
    xi[i] = s[i] - (st.back_stress ? st.back_stress[i] : 0.0);
  const double q = std::sqrt(1.5 * contract(xi, xi));
  const double sy = rf * (k.yield_stress + beta * hp * st.plastic_strain);
  if (q > sy) {
    const double dp = (q - sy) / (3.0 * m.shear_modulus + hp * (beta * rf + (1.0 - beta)));
    const double shrink = 3.0 * m.shear_modulus * dp / q;
    const double shift = (1.0 - beta) * hp * dp / q;
    for (int i = 0; i < 6; ++i) {
      s[i] -= shrink * xi[i];
      if (st.back_stress) st.back_stress[i] += shift * xi[i];
    }
    st.plastic_strain += dp;
    r.plastic_increment = dp;
  }
}

inline void return_deviator(const Material& m, const PiecewiseLinearModel& t, const PointInput& in,
                            PointState st, PointResult& r) {
  double* s = st.deviator;
  const double rf =
      detail::cowper_symonds(t.cowper_symonds_c, t.cowper_symonds_p, in.effective_strain_rate);
  double sy0 = 0.0, slope = 0.0;
  detail::table_yield(t, st.plastic_strain, sy0, slope);
  const double q = std::sqrt(1.5 * contract(s, s));
  r.plastic_increment = detail::isotropic_return(s, q, m.shear_modulus, st.plastic_strain, rf * sy0,
                                                 rf * slope, [&](double ep, double& sy, double& h) {
                                                   detail::table_yield(t, ep, sy, h);
                                                   sy *= rf;
                                                   h *= rf;
                                                 });
}

// sigma_y = (A + B ep^N)(1 + C ln rate*)(1 - T*^M); rate* clamped at 1 so slow rates do not
// soften below the quasi-static curve.
inline void return_deviator(const Material& m, const JohnsonCookModel& jc, const PointInput& in,
                            PointState st, PointResult& r) {
  double* s = st.deviator;
  const double ts = detail::homologous_temperature(jc, m.room_temperature, in.temperature);
  if (ts >= 1.0) {  // molten: no deviatoric strength
    for (int i = 0; i < 6; ++i)
      s[i] = 0.0;
    return;
  }
  // The flow stress is at least A times a lower bound of the rate and thermal factors (B >= 0,
  // checked at compile): most elastic points are settled without log or pow.
  const double q = std::sqrt(1.5 * contract(s, s));
  const double rate_floor = jc.c >= 0.0 ? 1.0 : 0.0;
  if (q <= rate_floor * detail::jc_thermal_floor(jc, ts) * jc.a) return;
  const double rate_star = std::max(in.effective_strain_rate / jc.reference_rate, 1.0);
  const double rate_factor = jc.c != 0.0 ? 1.0 + jc.c * std::log(rate_star) : 1.0;
  if (rate_factor <= 0.0) {
    for (int i = 0; i < 6; ++i)
      s[i] = 0.0;
    return;
  }
  const double rf = rate_factor * detail::jc_thermal_factor(jc, ts);
  if (q <= rf * jc.a) return;
  auto yield = [&](double ep, double& sy, double& h) {
    if (ep > 0.0) {
      const double pw = std::pow(ep, jc.n);
      sy = rf * (jc.a + jc.b * pw);
      h = rf * jc.b * jc.n * pw / ep;
    } else {
      // Slope B N ep^(N-1) at ep = 0: 0 for N > 1, B for N = 1, unbounded for N < 1 (a stiff
      // stand-in; the bracketed Newton iteration takes it from there).
      sy = rf * jc.a;
      if (jc.n > 1.0)
        h = 0.0;
      else if (jc.n == 1.0)
        h = rf * jc.b;
      else
        h = 1.0e3 * m.shear_modulus;
    }
  };
  double sy0 = 0.0, h0 = 0.0;
  yield(st.plastic_strain, sy0, h0);
  const double dp =
      detail::isotropic_return(s, q, m.shear_modulus, st.plastic_strain, sy0, h0, yield);
  r.plastic_increment = dp;
  if (dp > 0.0 && jc.damage_active) {
    const double q_returned = std::sqrt(1.5 * contract(s, s));
    const double triax = q_returned > 0.0 ? -in.pressure / q_returned : 0.0;
    const auto& d = jc.damage;
    double ef = (d[0] + d[1] * std::exp(d[2] * triax)) * (1.0 + d[3] * std::log(rate_star)) *
                (1.0 + d[4] * ts);
    ef = std::max(ef, jc.min_failure_strain);
    st.damage = std::min(1.0, st.damage + dp / ef);
    if (st.damage >= 1.0) r.failed = true;
  }
}

/// Deviatoric stress update of one point (Jaumann rotation already applied to its state) with
/// the material's deviatoric model `model` (the alternative its block visited).
template <class Model>
inline PointResult update_deviator(const Material& m, const Model& model, const PointInput& in,
                                   PointState st) {
  PointResult r;
  double* s = st.deviator;
  const double g2 = 2.0 * m.shear_modulus;
  for (int k = 0; k < 6; ++k)
    s[k] += g2 * in.deviatoric_increment[k];
  if constexpr (std::is_same_v<Model, ElasticModel>) return r;
  return_deviator(m, model, in, st, r);
  if ((m.failure_strain > 0.0 && st.plastic_strain >= m.failure_strain) ||
      (m.erosion_plastic_strain > 0.0 && st.plastic_strain >= m.erosion_plastic_strain)) {
    r.failed = true;
  }
  return r;
}

/// Volumetric state change of one element over the step.
struct VolumeChange {
  double relative_volume;   ///< V^{n+1} / V0
  double increment;         ///< (V^{n+1} - V^n) / V0
  double strain_increment;  ///< tr(D) dt
  double viscosity;         ///< bulk viscosity q (stress) acting this step
  double deviatoric_work;   ///< deviatoric work this step per initial volume
};

/// Updates the element pressure (and, with an EOS, its internal energy per initial volume E).
/// The EOS is affine in E, p = a(mu) + b(mu) E, so the trapezoidal energy equation
/// E1 = E0 + w_dev - (p0 + p1 + 2q)/2 dV is solved exactly for p1.
inline void update_pressure(const Material& m, const VolumeChange& v, double& pressure,
                            double& energy) {
  const EosParams& e = m.eos;
  if (e.kind == EosModel::none) {
    pressure -= m.bulk_modulus * v.strain_increment;
    return;
  }
  const double mu = 1.0 / v.relative_volume - 1.0;
  double a = 0.0, b = 0.0;
  if (e.kind == EosModel::gruneisen) {
    const double rc2 = m.density * e.sound_speed * e.sound_speed;
    b = e.gamma0 + e.volume_correction * mu;
    if (mu > 0.0) {
      const double den = 1.0 - (e.s1 - 1.0) * mu - e.s2 * mu * mu / (mu + 1.0) -
                         e.s3 * mu * mu * mu / ((mu + 1.0) * (mu + 1.0));
      a = rc2 * mu * (1.0 + (1.0 - 0.5 * e.gamma0) * mu - 0.5 * e.volume_correction * mu * mu) /
          (den * den);
    } else {
      a = rc2 * mu;
    }
  } else {
    const auto& c = e.c;
    const double mu2 = mu > 0.0 ? mu * mu : 0.0;  // C2 and C6 terms act in compression only
    a = c[0] + c[1] * mu + c[2] * mu2 + c[3] * mu * mu * mu;
    b = c[4] + c[5] * mu + c[6] * mu2;
  }
  const double e_star =
      energy + v.deviatoric_work - 0.5 * (pressure + 2.0 * v.viscosity) * v.increment;
  pressure = (a + b * e_star) / (1.0 + 0.5 * b * v.increment);
  energy = e_star - 0.5 * pressure * v.increment;
}

/// Pressure cutoff PC of MAT_015 (PC = 0: none). Returns true when the deviator must be zeroed
/// (SPALL 2 and 3: the element carries no tension once it has spalled).
inline bool apply_pressure_cutoff(const Material& m, double& pressure) {
  if (m.pressure_cutoff >= 0.0) return false;  // set by MAT_015 only
  if (pressure >= m.pressure_cutoff) return false;
  if (m.spall == Spall::hold_cutoff) {
    pressure = m.pressure_cutoff;
    return false;
  }
  pressure = 0.0;
  return true;
}

/// Bulk modulus at the reference state: the EOS's (rho0 C^2 for Gruneisen, C1 for the linear
/// polynomial) when the material has one, else the elastic K.
inline double reference_bulk_modulus(const Material& m) {
  if (m.eos.kind == EosModel::gruneisen) return m.density * m.eos.sound_speed * m.eos.sound_speed;
  if (m.eos.kind == EosModel::linear_polynomial) return m.eos.c[1];
  return m.bulk_modulus;
}

/// Dilatational wave speed squared at the current density.
inline double wave_speed_squared(const Material& m, double relative_volume) {
  return (reference_bulk_modulus(m) + 4.0 / 3.0 * m.shear_modulus) * relative_volume / m.density;
}

}  // namespace mcdyna::solver
