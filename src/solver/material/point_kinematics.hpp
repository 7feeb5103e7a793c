#pragma once
/// What an integration point (hexahedron Gauss point or SPG particle) needs from its velocity
/// gradient: rate of deformation, spin, Jaumann rotation, deviatoric increment; and the bulk
/// viscosity and step of the point's characteristic length. Shared by fe/ and spg/.
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

}  // namespace mcdyna::solver
