#pragma once
/// What an integration point (hexahedron Gauss point or SPG particle) does with its velocity
/// gradient: rate of deformation, spin, Jaumann rotation, deviatoric increment, the deviatoric
/// and volumetric updates of its state, and the bulk viscosity and step of its characteristic
/// length. Shared by fe/ and spg/, so elements and particles integrate materials the same way.
#include <algorithm>
#include <cmath>

#include "solver/material/constitutive.hpp"

namespace mcdyna::solver {

/// *CONTROL_BULK_VISCOSITY / *HOURGLASS Q1, Q2.
struct BulkViscosityParams {
  double quadratic = 1.5;  ///< Q1
  double linear = 0.06;    ///< Q2
};

// Velocity gradient pieces shared by both formulations.
struct Kinematics {
  double d[6];  // rate of deformation D, xx yy zz xy yz zx
  double w[3];  // spin W: w[0] = W_xy, w[1] = W_yz, w[2] = W_zx
  double trace;
  /// *CONTROL_ACCURACY OSU 1: the gradient was taken at the mid-step configuration and the
  /// stress turns by the Hughes-Winget rotation (objective to second order) instead of the
  /// Jaumann increment.
  bool objective = false;
};

// D, W and tr D from the velocity gradient l[i][j] = dv_i/dx_j.
inline Kinematics kinematics_from_gradient(const double l[3][3]) {
  Kinematics k;
  k.d[0] = l[0][0];
  k.d[1] = l[1][1];
  k.d[2] = l[2][2];
  k.d[3] = 0.5 * (l[0][1] + l[1][0]);
  k.d[4] = 0.5 * (l[1][2] + l[2][1]);
  k.d[5] = 0.5 * (l[2][0] + l[0][2]);
  k.w[0] = 0.5 * (l[0][1] - l[1][0]);
  k.w[1] = 0.5 * (l[1][2] - l[2][1]);
  k.w[2] = 0.5 * (l[2][0] - l[0][2]);
  k.trace = l[0][0] + l[1][1] + l[2][2];
  return k;
}

// Jaumann (objective) rotation of a symmetric tensor over dt: s += dt (W s - s W).
inline void jaumann_rotate(double* s, const double w[3], double dt) {
  const double wxy = w[0] * dt, wyz = w[1] * dt, wzx = w[2] * dt;
  // W as a matrix: [[0, wxy, -wzx], [-wxy, 0, wyz], [wzx, -wyz, 0]]
  const double sxx = s[0], syy = s[1], szz = s[2], sxy = s[3], syz = s[4], szx = s[5];
  s[0] += 2.0 * (wxy * sxy - wzx * szx);
  s[1] += 2.0 * (-wxy * sxy + wyz * syz);
  s[2] += 2.0 * (wzx * szx - wyz * syz);
  s[3] += wxy * (syy - sxx) + wyz * szx - wzx * syz;
  s[4] += wyz * (szz - syy) - wxy * szx + wzx * sxy;
  s[5] += wzx * (sxx - szz) + wxy * syz - wyz * sxy;
}

// Hughes-Winget rotation of a symmetric tensor over dt: s = Q s Q^T with
// Q = (I - dt/2 W)^-1 (I + dt/2 W), exactly orthogonal for any spin, so the invariants of s are
// kept; to first order it is the Jaumann increment s += dt (W s - s W). With the velocity
// gradient of the mid-step configuration it is the second-order objective update (Hughes and
// Winget 1980) that LS-DYNA's *CONTROL_ACCURACY OSU 1 selects.
inline void hughes_winget_rotate(double* s, const double w[3], double dt) {
  const double h = 0.5 * dt;
  const double a = w[0] * h, b = w[1] * h, c = w[2] * h;  // (dt/2) W_xy, W_yz, W_zx
  // A = (dt/2) W = [[0, a, -c], [-a, 0, b], [c, -b, 0]] is skew, so A^3 = -n2 A with
  // n2 = a^2 + b^2 + c^2, and (I - A) (I + k (A + A^2)) = I + A for k = 2 / (1 + n2): the
  // Cayley transform Q = (I - A)^-1 (I + A) = I + k (A + A^2), no inverse needed.
  const double n2 = a * a + b * b + c * c;
  const double k = 2.0 / (1.0 + n2);
  const double A[3][3] = {{0.0, a, -c}, {-a, 0.0, b}, {c, -b, 0.0}};
  double q[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double a2 = 0.0;
      for (int m = 0; m < 3; ++m)
        a2 += A[i][m] * A[m][j];
      q[i][j] = (i == j ? 1.0 : 0.0) + k * (A[i][j] + a2);
    }
  const double t[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double qt[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      qt[i][j] = q[i][0] * t[0][j] + q[i][1] * t[1][j] + q[i][2] * t[2][j];
  auto r = [&](int i, int j) {
    return qt[i][0] * q[j][0] + qt[i][1] * q[j][1] + qt[i][2] * q[j][2];
  };
  s[0] = r(0, 0);
  s[1] = r(1, 1);
  s[2] = r(2, 2);
  s[3] = r(0, 1);
  s[4] = r(1, 2);
  s[5] = r(2, 0);
}

// The stress rotation of the point's kinematics (Jaumann, or Hughes-Winget under OSU 1).
inline void rotate_stress(double* s, const Kinematics& k, double dt) {
  if (k.objective)
    hughes_winget_rotate(s, k.w, dt);
  else
    jaumann_rotate(s, k.w, dt);
}

// Effective strain rate sqrt(2/3 D':D') and the deviatoric strain increment dev(D) dt.
inline double deviatoric_increment(const Kinematics& k, double dt, double de[6]) {
  const double mean = k.trace / 3.0;
  double dd[6] = {k.d[0] - mean, k.d[1] - mean, k.d[2] - mean, k.d[3], k.d[4], k.d[5]};
  for (int i = 0; i < 6; ++i)
    de[i] = dd[i] * dt;
  return std::sqrt(2.0 / 3.0 * contract(dd, dd));
}

// Artificial bulk viscosity q = rho l (Q1 l tr(D)^2 - Q2 c tr(D)) in compression only.
inline double bulk_viscosity(const BulkViscosityParams& q, double density, double length,
                             double sound, double trace) {
  if (trace >= 0.0) return 0.0;
  return density * length * (q.quadratic * length * trace * trace - q.linear * sound * trace);
}

// Element step l / (Q + sqrt(Q^2 + c^2)) with Q = Q2 c + Q1 l |tr D| (LS-DYNA). LS-DYNA adds Q
// in compression only; here the linear part Q2 c applies always, so the step does not alternate
// with the sign of tr D from one cycle to the next. Such an alternation, in phase with the
// dissipative viscosity, breaks the energy balance of the central-difference scheme (measured:
// +4.4 % total energy on a vibrating bar); the price is a step ~6 % shorter at Q2 = 0.06.
inline double element_step(const BulkViscosityParams& q, double length, double sound,
                           double trace) {
  const double qv = q.linear * sound + (trace < 0.0 ? q.quadratic * length * (-trace) : 0.0);
  return length / (qv + std::sqrt(qv * qv + sound * sound));
}

/// Deviatoric update of one point over dt: rotation of its stress (and back stress), the
/// material update, and the deviatoric work per unit volume at the mid-step stress.
/// OSU 0: the Jaumann increment over the whole step, then the material update (LS-DYNA's
/// default, first order in the rotation). OSU 1: the strain increment D dt belongs to the
/// mid-step configuration, so the stress turns by half a step (Hughes-Winget over dt/2), takes
/// the increment and the return there, and turns by the other half; the work is the mid-step
/// stress in that same frame. Rotating by the whole step first and adding an increment of the
/// mid-step frame leaves an error of order omega dt |C D dt| per step: first order over a
/// spinning run (manual/verification.md, issue 24), where the split is second order.
/// `modified_shear`, when given, receives G-tilde of the paper's Eqs. 11-12,
/// 2 G-tilde = (H_dtau / H_de)^(1/2), the ratio of this update's deviatoric stress and strain
/// increments (G itself while elastic, less while plastic), for ITB 1's stabilisation stress.
template <class Model>
inline double deviatoric_point_update(const Material& m, const Model& model, const Kinematics& k,
                                      double dt, double temperature, double pressure, PointState st,
                                      bool& failed, double* modified_shear = nullptr) {
  double* s = st.deviator;
  const double turn = k.objective ? 0.5 * dt : dt;
  rotate_stress(s, k, turn);
  if (st.back_stress) rotate_stress(st.back_stress, k, turn);
  double s_old[6];
  std::copy(s, s + 6, s_old);
  double de[6];
  const double rate = deviatoric_increment(k, dt, de);
  const PointResult r = update_deviator(m, model, PointInput{de, rate, temperature, pressure}, st);
  failed = failed || r.failed;
  double mid[6];
  for (int j = 0; j < 6; ++j)
    mid[j] = 0.5 * (s_old[j] + s[j]);
  if (modified_shear) {
    double ds[6];
    for (int j = 0; j < 6; ++j)
      ds[j] = s[j] - s_old[j];
    const double h_de = contract(de, de);
    *modified_shear = h_de > 0.0
                          ? std::min(0.5 * std::sqrt(contract(ds, ds) / h_de), m.shear_modulus)
                          : m.shear_modulus;
  }
  if (k.objective) {
    rotate_stress(s, k, turn);
    if (st.back_stress) rotate_stress(st.back_stress, k, turn);
  }
  return contract(mid, de);
}

/// The volume a step's work is taken on: with the rates of the mid-step configuration (OSU 1)
/// the mid-step volume, as the trapezoidal rule of the central-difference energy balance asks;
/// otherwise the end-of-step volume the rates were taken at (LS-DYNA's default).
inline double work_volume(bool mid_step, double old_volume, double volume) {
  return mid_step ? 0.5 * (old_volume + volume) : volume;
}

/// The per-point values a volumetric update changes (element or particle arrays).
struct VolumetricState {
  double& pressure;
  double& eos_energy;       ///< per initial volume
  double& temperature;      ///< JC adiabatic temperature
  double& viscosity;        ///< bulk viscosity q of the last update
  double& internal_energy;  ///< absolute
};

struct PointVolumetrics {
  double viscosity;  ///< q of this update
  double sound;      ///< current wave speed
  double density;
  double wave_speed_squared;
  bool zero_deviator;  ///< pressure cutoff (spall) says the point carries no shear
};

/// Pressure (EOS or hypoelastic), bulk viscosity, internal energy and temperature of one point
/// whose volume went from `old_volume` to `volume` over dt with rate tr D = `trace` (of the
/// mid-step configuration when `mid_step`, OSU 1).
/// The viscosity acting over the step is the mean of the last update's and this one's, as for
/// the pressure: the trapezoidal rule that matches the central-difference kinetic energy.
inline PointVolumetrics volumetric_point_update(const Material& m, const BulkViscosityParams& bv,
                                                double initial_volume, double old_volume,
                                                double volume, double trace, double dt,
                                                double dev_work, double length, VolumetricState st,
                                                bool mid_step) {
  const double rel = volume / initial_volume;
  PointVolumetrics r;
  r.density = m.density / rel;
  r.wave_speed_squared = wave_speed_squared(m, rel);
  r.sound = std::sqrt(r.wave_speed_squared);
  r.viscosity = bulk_viscosity(bv, r.density, length, r.sound, trace);
  const double q_mean = 0.5 * (st.viscosity + r.viscosity);
  st.viscosity = r.viscosity;
  const VolumeChange vc{rel, (volume - old_volume) / initial_volume, trace * dt, q_mean,
                        dev_work / initial_volume};
  const double p_old = st.pressure;
  update_pressure(m, vc, st.pressure, st.eos_energy);
  r.zero_deviator = apply_pressure_cutoff(m, st.pressure);
  st.internal_energy += dev_work - (0.5 * (p_old + st.pressure) + q_mean) * trace * dt *
                                       work_volume(mid_step, old_volume, volume);
  if (m.specific_heat > 0.0) {
    st.temperature =
        m.room_temperature + (st.eos_energy - m.eos.initial_energy) / (m.density * m.specific_heat);
  }
  return r;
}

}  // namespace mcdyna::solver
