// Element pass for 8-node solids, ELFORM 1 (one point + Flanagan-Belytschko hourglass control)
// and ELFORM 2 (selectively reduced: eight deviatoric points, one mean volumetric strain rate).
#include "solver/solids/solid_elements.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "solver/fe/element_loop.hpp"
#include "solver/material/constitutive.hpp"
#include "solver/material/point_kinematics.hpp"
#include "solver/solids/hex_geometry.hpp"

namespace mcdyna::solver {

namespace {

using hex::Corners;

using fe::ElementOutcome;
using fe::kParallelMinimum;

Kinematics kinematics(const Corners& v, const double b[8][3]) {
  double l[3][3] = {};
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        l[i][j] += v[n][i] * b[n][j];
  return kinematics_from_gradient(l);
}

void load_corners(const State& st, const Solids& so, Index e, Corners& x, Corners& v) {
  const auto& nd = so.nodes[static_cast<std::size_t>(e)];
  for (int n = 0; n < 8; ++n) {
    const double* xp = st.nodes.position.col(nd[n]).data();
    const double* vp = st.nodes.velocity.col(nd[n]).data();
    for (int i = 0; i < 3; ++i) {
      x[n][i] = xp[i];
      v[n][i] = vp[i];
    }
  }
}

struct ElementContext {
  State& st;
  Solids& so;
  const SolidBlock& block;
  const Material& mat;
  const ElementPassInput& in;
};

// Everything after the deviatoric updates is common: pressure, energy, time step, erosion.
struct VolumetricResult {
  double pressure_total;  // p + q
  double step;
  bool zero_deviator;
  double density;             // current
  double wave_speed_squared;  // current
};

VolumetricResult volumetric_update(ElementContext& c, Index e, double volume, double trace,
                                   double dev_work, double length, bool mid_step) {
  Solids& s = c.so;
  const auto i = static_cast<std::size_t>(e);
  const PointVolumetrics v =
      volumetric_point_update(c.mat, c.block.bulk_viscosity, s.initial_volume[i], s.volume[i],
                              volume, trace, c.in.step, dev_work, length,
                              VolumetricState{s.pressure[i], s.eos_energy[i], s.temperature[i],
                                              s.viscosity[i], s.internal_energy[i]},
                              mid_step);
  s.volume[i] = volume;
  return {s.pressure[i] + v.viscosity, element_step(c.block.bulk_viscosity, length, v.sound, trace),
          v.zero_deviator, v.density, v.wave_speed_squared};
}

// Deviatoric update of one point with the block's model; returns the work per unit volume.
template <class Model>
double point_update(ElementContext& c, const Model& model, Index point, const Kinematics& k,
                    double temperature, double pressure, bool& failed) {
  MaterialPoints& mp = c.so.points;
  const auto p = static_cast<std::size_t>(point);
  double* alpha = mp.back_stress.size() > 0 ? mp.back_stress.col(point).data() : nullptr;
  return deviatoric_point_update(
      c.mat, model, k, c.in.step, temperature, pressure,
      PointState{mp.deviator.col(point).data(), alpha, mp.plastic_strain[p], mp.damage[p]}, failed);
}

void zero_point_deviators(Solids& so, Index first, int count) {
  for (Index p = first; p < first + count; ++p)
    so.points.deviator.col(p).setZero();
}

// Corner forces f_I = -V sigma b_I for a point with deviator s and pressure + viscosity pq.
void add_stress_forces(const double* s, double pq, double weight, const double b[8][3], double* f) {
  const double sxx = s[0] - pq, syy = s[1] - pq, szz = s[2] - pq;
  for (int n = 0; n < 8; ++n) {
    const double* bn = b[n];
    f[3 * n + 0] -= weight * (sxx * bn[0] + s[3] * bn[1] + s[5] * bn[2]);
    f[3 * n + 1] -= weight * (s[3] * bn[0] + syy * bn[1] + s[4] * bn[2]);
    f[3 * n + 2] -= weight * (s[5] * bn[0] + s[4] * bn[1] + szz * bn[2]);
  }
}

// The one-point element (ELFORM 1) in terms of corner pattern sums (hex::pattern_sums): at the
// centre J[i][k] = Hx[2^k][i] / 8 and b_n = (xi_n / 8) J^-1, so every sum over the corners
// against b_n or the hourglass vectors becomes a pattern sum and a 3x3 product, and the corner
// forces one transform back (hex::add_pattern_combination).
struct CentrePoint {
  double hx[8][3], hv[8][3];  // pattern sums of positions and velocities
  double ji[3][3];            // J^-1: ji[k][i] = dxi_k / dx_i
  double l[3][3];             // velocity gradient dv_i / dx_j
  double volume;              // 8 det J (<= 0: inverted)
};

// l[i][j] = dv_i / dx_j at the centre from the velocity pattern sums and J^-1.
void centre_velocity_gradient(const double hv[8][3], const double ji[3][3], double l[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      l[i][j] = 0.125 * (hv[1][i] * ji[0][j] + hv[2][i] * ji[1][j] + hv[4][i] * ji[2][j]);
}

CentrePoint centre_point(const Corners& x, const Corners& v) {
  CentrePoint p;
  hex::pattern_sums(x, p.hx);
  hex::pattern_sums(v, p.hv);
  double jac[3][3];
  hex::centre_jacobian(p.hx, jac);
  p.volume = 8.0 * hex::invert(jac, p.ji);
  if (!(p.volume > 0.0)) return p;
  centre_velocity_gradient(p.hv, p.ji, p.l);
  return p;
}

// *CONTROL_ACCURACY OSU 1: the velocity gradient at the mid-step configuration x - dt/2 v (the
// pattern sums are linear in x, so Hx - dt/2 Hv), which makes a rigid rotation strain-free to
// round-off; the forces and the hourglass rates stay at the end-of-step geometry. False when
// the mid-step element is inverted.
bool mid_step_gradient(const CentrePoint& p, double half_step, double l[3][3]) {
  double hx[8][3];
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      hx[a][i] = p.hx[a][i] - half_step * p.hv[a][i];
  double jac[3][3], ji[3][3];
  hex::centre_jacobian(hx, jac);
  if (!(hex::invert(jac, ji) > 0.0)) return false;
  centre_velocity_gradient(p.hv, ji, l);
  return true;
}

// Flanagan-Belytschko hourglass forces. gamma_a = (h_a - (h_a . x_n) b_n) / 8 is orthogonal
// to every linear velocity field, so rigid motion and uniform strain see no hourglass force;
// the hourglass rate is q_a = gamma_a . v = (Hv_a - l Hx_a) / 8 and the force -sum_a Q_a gamma_a
// splits into pattern coefficients (-Q_a / 8) and a b-term folded into the stress matrix m.
// Viscous (IHQ 1-3) uses LS-DYNA's magnitude a_h = QM rho V^(2/3) c / 4 on the +-1 vectors;
// stiffness (IHQ 4/5) integrates Q += kappa dt qdot, kappa = QM (lambda+2mu) V sum|b|^2 / 3.
// The resistance is kept per element so the hourglass work over a step is the trapezoid of the
// last and the new resistance (consistent with the kinetic energy; see solver/energy.hpp).
double hourglass_forces(ElementContext& c, Index e, const CentrePoint& p,
                        const VolumetricResult& vr, double m[3][3], double coef[8][3]) {
  const HourglassParams& hg = c.block.hourglass;
  if (hg.coefficient <= 0.0) return 0.0;
  const double rho = vr.density, c2 = vr.wave_speed_squared;
  const double dt = c.in.step;
  double* q = &c.so.hourglass_force[12 * static_cast<std::size_t>(e)];
  // Stiffness form: resist = Q_old + kappa dt qdot; viscous form: resist = a_h qdot.
  double rate_factor = 0.0, carry = 0.0;
  if (hg.stiffness()) {
    double bb = 0.0;  // sum_n |b_n|^2 = sum |J^-1|^2 / 8
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        bb += p.ji[k][i] * p.ji[k][i];
    rate_factor = hg.coefficient * rho * c2 * p.volume * (0.125 * bb) / 3.0 * dt;
    carry = 1.0;
  } else {
    rate_factor = 16.0 * hg.coefficient * rho * std::cbrt(p.volume * p.volume) * std::sqrt(c2);
  }
  double power = 0.0;
#pragma GCC unroll 4
  for (int a = 0; a < 4; ++a) {
    const double* hx = p.hx[hex::kHourglassPattern[a]];
    const double* hv = p.hv[hex::kHourglassPattern[a]];
    double resist[3];
    for (int i = 0; i < 3; ++i) {
      const double qdot =
          0.125 * (hv[i] - (p.l[i][0] * hx[0] + p.l[i][1] * hx[1] + p.l[i][2] * hx[2]));
      const double old = q[3 * a + i];
      resist[i] = carry * old + rate_factor * qdot;
      q[3 * a + i] = resist[i];
      power += 0.5 * (old + resist[i]) * qdot;
    }
    for (int i = 0; i < 3; ++i) {
      coef[hex::kHourglassPattern[a]][i] = -0.125 * resist[i];
      for (int j = 0; j < 3; ++j)
        m[i][j] -= 0.125 * resist[i] * hx[j];
    }
  }
  return power * dt;
}

// Clears the element's corner forces and loads its corner positions and velocities.
double* start_element(const State& st, Solids& so, Index e, Corners& x, Corners& v) {
  double* f = &so.corner_force[24 * static_cast<std::size_t>(e)];
  std::fill(f, f + 24, 0.0);
  load_corners(st, so, e, x, v);
  return f;
}

template <class Model>
ElementOutcome one_point_element(ElementContext& c, const Model& model, Index e) {
  Solids& s = c.so;
  const auto i = static_cast<std::size_t>(e);
  Corners x, v;
  double* f = start_element(c.st, c.so, e, x, v);
  const CentrePoint cp = centre_point(x, v);
  if (!(cp.volume > 0.0)) return {0.0, true, false};
  const double volume = cp.volume;
  double mid[3][3];
  if (c.block.objective && !mid_step_gradient(cp, 0.5 * c.in.step, mid)) return {0.0, true, false};
  Kinematics k = kinematics_from_gradient(c.block.objective ? mid : cp.l);
  k.objective = c.block.objective;
  const Index point = c.block.point_begin + (e - c.block.begin);
  bool failed = false;
  const double dev_work = work_volume(k.objective, s.volume[i], volume) *
                          point_update(c, model, point, k, s.temperature[i], s.pressure[i], failed);
  const double length = volume / hex::max_face_area(x);
  const VolumetricResult vr =
      volumetric_update(c, e, volume, k.trace, dev_work, length, k.objective);
  if (vr.zero_deviator) zero_point_deviators(c.so, point, 1);
  // Corner forces f_n = -m b_n + hourglass, with m = V sigma (less the hourglass b-term).
  const double* dev = s.points.deviator.col(point).data();
  const double pq = vr.pressure_total;
  double m[3][3] = {{volume * (dev[0] - pq), volume * dev[3], volume * dev[5]},
                    {volume * dev[3], volume * (dev[1] - pq), volume * dev[4]},
                    {volume * dev[5], volume * dev[4], volume * (dev[2] - pq)}};
  double coef[8][3] = {};
  s.hourglass_energy[i] += hourglass_forces(c, e, cp, vr, m, coef);
  for (int kk = 0; kk < 3; ++kk)
    for (int r = 0; r < 3; ++r)
      coef[1 << kk][r] =
          -0.125 * (m[r][0] * cp.ji[kk][0] + m[r][1] * cp.ji[kk][1] + m[r][2] * cp.ji[kk][2]);
  hex::add_pattern_combination(coef, f);
  return {vr.step, false, failed, fe::runaway(volume, s.initial_volume[i])};
}

template <class Model>
ElementOutcome selective_reduced_element(ElementContext& c, const Model& model, Index e) {
  Solids& s = c.so;
  const auto i = static_cast<std::size_t>(e);
  Corners x, v;
  double* f = start_element(c.st, c.so, e, x, v);
  const hex::GaussPoints& gauss = hex::gauss_points();
  hex::Gradients g[8];
  Kinematics k[8];
  double volume = 0.0, trace = 0.0;
  Corners mid;  // OSU 1: strain rates at the mid-step configuration, forces at the end
  if (c.block.objective)
    for (int n = 0; n < 8; ++n)
      for (int i = 0; i < 3; ++i)
        mid[n][i] = x[n][i] - 0.5 * c.in.step * v[n][i];
  for (int p = 0; p < 8; ++p) {
    g[p] = hex::gradients(x, gauss.gradients[p]);
    if (!(g[p].det > 0.0)) return {0.0, true, false};
    if (c.block.objective) {
      const hex::Gradients gm = hex::gradients(mid, gauss.gradients[p]);
      if (!(gm.det > 0.0)) return {0.0, true, false};
      k[p] = kinematics(v, gm.b);
      k[p].objective = true;
    } else {
      k[p] = kinematics(v, g[p].b);
    }
    volume += g[p].det;
    trace += g[p].det * k[p].trace;
  }
  trace /= volume;  // mean volumetric strain rate shared by all points (B-bar)
  const Index first = c.block.point_begin + 8 * (e - c.block.begin);
  bool failed = false;
  double dev_work = 0.0;
  for (int p = 0; p < 8; ++p) {
    k[p].trace = trace;
    dev_work +=
        g[p].det * point_update(c, model, first + p, k[p], s.temperature[i], s.pressure[i], failed);
  }
  // OSU 1: the work on the mid-step volume (the points' weights scale with the element's).
  if (c.block.objective) dev_work *= work_volume(true, s.volume[i], volume) / volume;
  const double length = volume / hex::max_face_area(x);
  const VolumetricResult vr =
      volumetric_update(c, e, volume, trace, dev_work, length, c.block.objective);
  if (vr.zero_deviator) zero_point_deviators(c.so, first, 8);
  for (int p = 0; p < 8; ++p)
    add_stress_forces(s.points.deviator.col(first + p).data(), vr.pressure_total, g[p].det, g[p].b,
                      f);
  return {vr.step, false, failed, fe::runaway(volume, s.initial_volume[i])};
}

// The elements of one block with its material's deviatoric model (visited once per block).
template <class Model>
void block_pass(ElementContext& c, const Model& model, fe::PassTotals& totals) {
  Solids& s = c.so;
  const SolidBlock& block = c.block;
  const bool one_point = block.formulation == SolidFormulation::one_point;
  fe::element_loop(
      block.begin, block.end,
      fe::ElementArrays{s.eroded, s.corner_force, 24, s.mass, s.added_mass, s.time_step},
      c.in.scale_factor, c.in.mass_scaling_step,
      // Over several processes, the elements another process computes alone are skipped.
      [&](Index e) { return !c.st.ownership.computes_element(e); },
      [&](Index e) {
        return one_point ? one_point_element(c, model, e) : selective_reduced_element(c, model, e);
      },
      totals);
}

}  // namespace

ElementPassResult solid_element_pass(State& state, Solids& solids, const ElementPassInput& input) {
  fe::PassTotals totals;
  for (const SolidBlock& block : solids.blocks) {
    const Material& mat = state.materials[static_cast<std::size_t>(block.material)];
    ElementContext c{state, solids, block, mat, input};
    std::visit([&](const auto& model) { block_pass(c, model, totals); }, mat.model);
  }
  return totals.result();
}

void gather_solid_forces(const State& state, const Solids& solids, NodalForces& forces) {
  const Nodes& nd = state.nodes;
  const double* cf = solids.corner_force.data();
  double* f = forces.force.data();
  // Another process gathers the nodes this one does not move.
  const std::size_t count = state.ownership.moved_count(nd.count());
#pragma omp parallel for schedule(static) if (count > 4 * kParallelMinimum)
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = state.ownership.moved_node(k);
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (Index k = solids.corner_offsets[static_cast<std::size_t>(n)];
         k < solids.corner_offsets[static_cast<std::size_t>(n) + 1]; ++k) {
      const double* c =
          cf + 3 * static_cast<std::size_t>(solids.node_corners[static_cast<std::size_t>(k)]);
      fx += c[0];
      fy += c[1];
      fz += c[2];
    }
    f[3 * n] += fx;
    f[3 * n + 1] += fy;
    f[3 * n + 2] += fz;
  }
}

}  // namespace mcdyna::solver
