// Element pass for 8-node solids, ELFORM 1 (one point + Flanagan-Belytschko hourglass control)
// and ELFORM 2 (selectively reduced: eight deviatoric points, one mean volumetric strain rate).
#include "solver/fe/solid_elements.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/fe/hex_geometry.hpp"
#include "solver/material/constitutive.hpp"

namespace mcdyna::solver {

namespace {

using hex::Corners;

constexpr Index kParallelMinimum = 512;

// Per-thread minimum of (step, element); ties go to the lower element index, so the combined
// result is the same for any thread count.
struct StepMin {
  double step = std::numeric_limits<double>::infinity();
  Index element = -1;
  void take(double s, Index e) {
    if (s < step || (s == step && (element < 0 || e < element))) {
      step = s;
      element = e;
    }
  }
};

// Velocity gradient pieces shared by both formulations.
struct Kinematics {
  double d[6];  // rate of deformation D, xx yy zz xy yz zx
  double w[3];  // spin W: w[0] = W_xy, w[1] = W_yz, w[2] = W_zx
  double trace;
};

Kinematics kinematics(const Corners& v, const double b[8][3]) {
  double l[3][3] = {};  // l[i][j] = dv_i/dx_j
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        l[i][j] += v[n][i] * b[n][j];
  Kinematics k{};
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
void jaumann_rotate(double* s, const double w[3], double dt) {
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
double deviatoric_increment(const Kinematics& k, double dt, double de[6]) {
  const double mean = k.trace / 3.0;
  double dd[6] = {k.d[0] - mean, k.d[1] - mean, k.d[2] - mean, k.d[3], k.d[4], k.d[5]};
  for (int i = 0; i < 6; ++i)
    de[i] = dd[i] * dt;
  return std::sqrt(2.0 / 3.0 * contract(dd, dd));
}

void load_corners(const State& st, Index e, Corners& x, Corners& v) {
  const auto& nd = st.solids.nodes[static_cast<std::size_t>(e)];
  for (int n = 0; n < 8; ++n) {
    const double* xp = st.nodes.position.col(nd[n]).data();
    const double* vp = st.nodes.velocity.col(nd[n]).data();
    for (int i = 0; i < 3; ++i) {
      x[n][i] = xp[i];
      v[n][i] = vp[i];
    }
  }
}

// Artificial bulk viscosity q = rho l (Q1 l tr(D)^2 - Q2 c tr(D)) in compression only.
double bulk_viscosity(const BulkViscosityParams& q, double density, double length, double sound,
                      double trace) {
  if (trace >= 0.0) return 0.0;
  return density * length * (q.quadratic * length * trace * trace - q.linear * sound * trace);
}

// Element step l / (Q + sqrt(Q^2 + c^2)) with Q = Q2 c + Q1 l |tr D| (LS-DYNA). LS-DYNA adds Q
// in compression only; here the linear part Q2 c applies always, so the step does not alternate
// with the sign of tr D from one cycle to the next. Such an alternation, in phase with the
// dissipative viscosity, breaks the energy balance of the central-difference scheme (measured:
// +4.4 % total energy on a vibrating bar); the price is a step ~6 % shorter at Q2 = 0.06.
double element_step(const BulkViscosityParams& q, double length, double sound, double trace) {
  const double qv = q.linear * sound + (trace < 0.0 ? q.quadratic * length * (-trace) : 0.0);
  return length / (qv + std::sqrt(qv * qv + sound * sound));
}

struct ElementContext {
  State& st;
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
                                   double dev_work, double length) {
  Solids& s = c.st.solids;
  const auto i = static_cast<std::size_t>(e);
  const double dt = c.in.step;
  const double v0 = s.initial_volume[i];
  const double rel = volume / v0;
  const double density = c.mat.density / rel;
  const double c2 = wave_speed_squared(c.mat, rel);
  const double sound = std::sqrt(c2);
  const double q = bulk_viscosity(c.block.bulk_viscosity, density, length, sound, trace);
  // The viscosity acting over the step is the mean of the last pass's and this one's, as for
  // the pressure: the trapezoidal rule that matches the central-difference kinetic energy.
  const double q_mean = 0.5 * (s.viscosity[i] + q);
  s.viscosity[i] = q;
  const VolumeChange vc{rel, (volume - s.volume[i]) / v0, trace * dt, q_mean, dev_work / v0};
  const double p_old = s.pressure[i];
  update_pressure(c.mat, vc, s.pressure[i], s.eos_energy[i]);
  const bool zero_dev = apply_pressure_cutoff(c.mat, s.pressure[i]);
  s.internal_energy[i] += dev_work - (0.5 * (p_old + s.pressure[i]) + q_mean) * trace * dt * volume;
  s.volume[i] = volume;
  if (c.mat.specific_heat > 0.0) {
    s.temperature[i] = c.mat.room_temperature + (s.eos_energy[i] - c.mat.eos.initial_energy) /
                                                    (c.mat.density * c.mat.specific_heat);
  }
  return {s.pressure[i] + q, element_step(c.block.bulk_viscosity, length, sound, trace), zero_dev,
          density, c2};
}

// Deviatoric update of one point: rotate, integrate the material, return the work done.
double point_update(ElementContext& c, Index point, const Kinematics& k, double temperature,
                    double pressure, bool& failed) {
  MaterialPoints& mp = c.st.solids.points;
  const double dt = c.in.step;
  double* s = mp.deviator.col(point).data();
  double* alpha = mp.back_stress.size() > 0 ? mp.back_stress.col(point).data() : nullptr;
  jaumann_rotate(s, k.w, dt);
  if (alpha) jaumann_rotate(alpha, k.w, dt);
  double s_old[6];
  std::copy(s, s + 6, s_old);
  double de[6];
  const double rate = deviatoric_increment(k, dt, de);
  const auto p = static_cast<std::size_t>(point);
  const PointResult r = update_deviator(c.mat, PointInput{de, rate, temperature, pressure},
                                        PointState{s, alpha, mp.plastic_strain[p], mp.damage[p]});
  failed = failed || r.failed;
  double mid[6];
  for (int j = 0; j < 6; ++j)
    mid[j] = 0.5 * (s_old[j] + s[j]);
  return contract(mid, de);
}

void zero_point_deviators(State& st, Index first, int count) {
  for (Index p = first; p < first + count; ++p)
    st.solids.points.deviator.col(p).setZero();
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

// Flanagan-Belytschko hourglass forces. gamma = (Gamma - (Gamma . x_i) b_i) / 8 is orthogonal
// to every linear velocity field, so rigid motion and uniform strain see no hourglass force.
// Viscous (IHQ 1-3) uses LS-DYNA's magnitude a_h = QM rho V^(2/3) c / 4 on the +-1 vectors;
// stiffness (IHQ 4/5) integrates Q += kappa dt qdot, kappa = QM (lambda+2mu) V sum|b|^2 / 3.
// The resistance is kept per element so the hourglass work over a step is the trapezoid of the
// last and the new resistance (consistent with the kinetic energy; see solver/energy.hpp).
double hourglass_forces(ElementContext& c, Index e, const Corners& x, const Corners& v,
                        const double b[8][3], double volume, const VolumetricResult& vr,
                        double* f) {
  const HourglassParams& hg = c.block.hourglass;
  if (hg.coefficient <= 0.0) return 0.0;
  double gamma[4][8], qdot[4][3];
  for (int a = 0; a < 4; ++a) {
    double hx[3] = {0, 0, 0};
    for (int n = 0; n < 8; ++n)
      for (int i = 0; i < 3; ++i)
        hx[i] += hex::kHourglass[a][n] * x[n][i];
    for (int n = 0; n < 8; ++n)
      gamma[a][n] =
          0.125 * (hex::kHourglass[a][n] - hx[0] * b[n][0] - hx[1] * b[n][1] - hx[2] * b[n][2]);
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int n = 0; n < 8; ++n)
        sum += gamma[a][n] * v[n][i];
      qdot[a][i] = sum;
    }
  }
  const double rho = vr.density, c2 = vr.wave_speed_squared;
  const double dt = c.in.step;
  double resist[4][3];
  double power = 0.0;
  double* q = &c.st.solids.hourglass_force[12 * static_cast<std::size_t>(e)];
  // Stiffness form: resist = Q_old + kappa dt qdot; viscous form: resist = a_h qdot.
  double rate_factor = 0.0, carry = 0.0;
  if (hg.stiffness()) {
    double bb = 0.0;
    for (int n = 0; n < 8; ++n)
      bb += b[n][0] * b[n][0] + b[n][1] * b[n][1] + b[n][2] * b[n][2];
    rate_factor = hg.coefficient * rho * c2 * volume * bb / 3.0 * dt;
    carry = 1.0;
  } else {
    rate_factor = 16.0 * hg.coefficient * rho * std::cbrt(volume * volume) * std::sqrt(c2);
  }
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) {
      const double old = q[3 * a + i];
      resist[a][i] = carry * old + rate_factor * qdot[a][i];
      q[3 * a + i] = resist[a][i];
      power += 0.5 * (old + resist[a][i]) * qdot[a][i];
    }
  for (int n = 0; n < 8; ++n)
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int a = 0; a < 4; ++a)
        sum += resist[a][i] * gamma[a][n];
      f[3 * n + i] -= sum;
    }
  return power * dt;
}

struct ElementOutcome {
  double step = 0.0;
  bool inverted = false;
  bool failed = false;
};

// Clears the element's corner forces and loads its corner positions and velocities.
double* start_element(State& st, Index e, Corners& x, Corners& v) {
  double* f = &st.solids.corner_force[24 * static_cast<std::size_t>(e)];
  std::fill(f, f + 24, 0.0);
  load_corners(st, e, x, v);
  return f;
}

ElementOutcome one_point_element(ElementContext& c, Index e) {
  Solids& s = c.st.solids;
  const auto i = static_cast<std::size_t>(e);
  Corners x, v;
  double* f = start_element(c.st, e, x, v);
  const hex::Gradients g = hex::centre_gradients(x);
  if (!(g.det > 0.0)) return {0.0, true, false};
  const double volume = 8.0 * g.det;
  const Kinematics k = kinematics(v, g.b);
  const Index point = c.block.point_begin + (e - c.block.begin);
  bool failed = false;
  const double dev_work =
      volume * point_update(c, point, k, s.temperature[i], s.pressure[i], failed);
  const double length = volume / hex::max_face_area(x);
  const VolumetricResult vr = volumetric_update(c, e, volume, k.trace, dev_work, length);
  if (vr.zero_deviator) zero_point_deviators(c.st, point, 1);
  add_stress_forces(s.points.deviator.col(point).data(), vr.pressure_total, volume, g.b, f);
  s.hourglass_energy[i] += hourglass_forces(c, e, x, v, g.b, volume, vr, f);
  return {vr.step, false, failed};
}

ElementOutcome selective_reduced_element(ElementContext& c, Index e) {
  Solids& s = c.st.solids;
  const auto i = static_cast<std::size_t>(e);
  Corners x, v;
  double* f = start_element(c.st, e, x, v);
  const hex::GaussPoints& gauss = hex::gauss_points();
  hex::Gradients g[8];
  Kinematics k[8];
  double volume = 0.0, trace = 0.0;
  for (int p = 0; p < 8; ++p) {
    g[p] = hex::gradients(x, gauss.gradients[p]);
    if (!(g[p].det > 0.0)) return {0.0, true, false};
    k[p] = kinematics(v, g[p].b);
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
        g[p].det * point_update(c, first + p, k[p], s.temperature[i], s.pressure[i], failed);
  }
  const double length = volume / hex::max_face_area(x);
  const VolumetricResult vr = volumetric_update(c, e, volume, trace, dev_work, length);
  if (vr.zero_deviator) zero_point_deviators(c.st, first, 8);
  for (int p = 0; p < 8; ++p)
    add_stress_forces(s.points.deviator.col(first + p).data(), vr.pressure_total, g[p].det, g[p].b,
                      f);
  return {vr.step, false, failed};
}

// Mass scaling (DT2MS): give the element enough added mass that its step reaches the target;
// added mass never decreases. Returns the element step with the added mass.
double scale_mass(Solids& s, std::size_t i, double step, const ElementPassInput& in,
                  bool& changed) {
  const double with_added = step * std::sqrt((s.mass[i] + s.added_mass[i]) / s.mass[i]);
  if (in.mass_scaling_step <= 0.0 || in.scale_factor * with_added >= in.mass_scaling_step)
    return with_added;
  const double ratio = in.mass_scaling_step / (in.scale_factor * step);
  s.added_mass[i] = s.mass[i] * (ratio * ratio - 1.0);
  changed = true;
  return in.mass_scaling_step / in.scale_factor;
}

}  // namespace

ElementPassResult solid_element_pass(State& state, const ElementPassInput& input) {
  Solids& s = state.solids;
  ElementPassResult result;
  StepMin global;
  Index inverted = std::numeric_limits<Index>::max();
  Index eroded = 0;
  bool mass_changed = false;
  for (const SolidBlock& block : s.blocks) {
    ElementContext c{state, block, state.materials[static_cast<std::size_t>(block.material)],
                     input};
    const bool one_point = block.formulation == SolidFormulation::one_point;
    // Small blocks run serially: a parallel region costs more than a few elements.
#pragma omp parallel if (block.end - block.begin > kParallelMinimum)
    {
      StepMin local;
      Index local_inverted = std::numeric_limits<Index>::max();
      Index local_eroded = 0;
      bool local_changed = false;
#pragma omp for schedule(static) nowait
      for (Index e = block.begin; e < block.end; ++e) {
        const auto i = static_cast<std::size_t>(e);
        if (s.eroded[i]) continue;
        const ElementOutcome o =
            one_point ? one_point_element(c, e) : selective_reduced_element(c, e);
        if (o.inverted) {
          local_inverted = std::min(local_inverted, e);
          continue;
        }
        if (o.failed) {
          s.eroded[i] = 1;
          std::fill(&s.corner_force[24 * i], &s.corner_force[24 * i] + 24, 0.0);
          ++local_eroded;
          continue;
        }
        const double step = scale_mass(s, i, o.step, input, local_changed);
        s.time_step[i] = step;
        local.take(step, e);
      }
#pragma omp critical
      {
        global.take(local.step, local.element);
        inverted = std::min(inverted, local_inverted);
        eroded += local_eroded;
        mass_changed = mass_changed || local_changed;
      }
    }
  }
  result.critical_step = global.step;
  result.controlling = global.element;
  result.inverted = inverted == std::numeric_limits<Index>::max() ? -1 : inverted;
  result.newly_eroded = eroded;
  result.mass_changed = mass_changed;
  return result;
}

void gather_solid_forces(State& state) {
  const Nodes& nd = state.nodes;
  const double* cf = state.solids.corner_force.data();
  double* f = state.nodes.force.data();
  const Index n_nodes = nd.count();
#pragma omp parallel for schedule(static) if (n_nodes > 4 * kParallelMinimum)
  for (Index n = 0; n < n_nodes; ++n) {
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (Index k = nd.corner_offsets[static_cast<std::size_t>(n)];
         k < nd.corner_offsets[static_cast<std::size_t>(n) + 1]; ++k) {
      const double* c = cf + 3 * static_cast<std::size_t>(nd.corners[static_cast<std::size_t>(k)]);
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
