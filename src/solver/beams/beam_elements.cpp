// Element pass for the beams (beam_elements.hpp). Local axes r s t; "s" quantities are about or
// along s. Rates per unit length; generalized forces from the rates by virtual power, so the work
// the forces do is exactly the work charged to the element.
#include "solver/beams/beam_elements.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <variant>

#include "solver/fe/element_loop.hpp"
#include "solver/material/plane_stress.hpp"
#include "solver/shells/shell_elements.hpp"  // youngs_modulus

namespace mcdyna::solver {

namespace {

using fe::ElementOutcome;

struct Axes {
  Vec3 r, s, t;
  double length = 0.0;
};

// The current axes: r from the nodes; s carried from the last pass by the mean spin of the two
// nodes over dt (Rodrigues' rotation), then made normal to r. Stores the new s.
Axes advance_axes(const Nodes& nd, Beams& bm, Index e, double dt) {
  const auto i = static_cast<Eigen::Index>(e);
  const auto& conn = bm.nodes[static_cast<std::size_t>(e)];
  const Vec3 d = nd.position.col(conn[1]) - nd.position.col(conn[0]);
  Axes a;
  a.length = d.norm();
  if (!(a.length > 0.0)) return a;
  a.r = d / a.length;
  Vec3 s = bm.s_axis.col(i);
  const Vec3 spin = 0.5 * (nd.angular_velocity.col(conn[0]) + nd.angular_velocity.col(conn[1]));
  const double angle = spin.norm() * dt;
  if (angle > 0.0) s = Eigen::AngleAxisd(angle, spin.normalized()) * s;
  s -= s.dot(a.r) * a.r;
  a.s = s.normalized();
  a.t = a.r.cross(a.s);
  bm.s_axis.col(i) = a.s;
  return a;
}

// Deformation rates in the local axes: axial strain rate, twist and curvature rates (about r, s,
// t), and the transverse shear rates (engineering, in the r-s and r-t planes).
struct Rates {
  double axial, twist, curvature_s, curvature_t, shear_s, shear_t;
  double chord_s, chord_t;  // rotation rate of the chord about s and t
  double spin1_s, spin1_t, spin2_s, spin2_t;
};

Rates rates(const Nodes& nd, const Beams& bm, Index e, const Axes& a) {
  const auto& conn = bm.nodes[static_cast<std::size_t>(e)];
  const Vec3 dv = nd.velocity.col(conn[1]) - nd.velocity.col(conn[0]);
  const Vec3 w1 = nd.angular_velocity.col(conn[0]), w2 = nd.angular_velocity.col(conn[1]);
  const double l = a.length;
  Rates r{};
  r.axial = dv.dot(a.r) / l;
  r.twist = (w2 - w1).dot(a.r) / l;
  r.spin1_s = w1.dot(a.s);
  r.spin2_s = w2.dot(a.s);
  r.spin1_t = w1.dot(a.t);
  r.spin2_t = w2.dot(a.t);
  r.curvature_s = (r.spin2_s - r.spin1_s) / l;
  r.curvature_t = (r.spin2_t - r.spin1_t) / l;
  // A transverse velocity along s turns the chord about +t; one along t turns it about -s.
  r.chord_t = dv.dot(a.s) / l;
  r.chord_s = -dv.dot(a.t) / l;
  r.shear_s = r.chord_t - 0.5 * (r.spin1_t + r.spin2_t);
  r.shear_t = -r.chord_s + 0.5 * (r.spin1_s + r.spin2_s);
  return r;
}

// Local internal forces and moments at the two ends.
struct EndForces {
  Vec3 f1 = Vec3::Zero(), m1 = Vec3::Zero(), f2 = Vec3::Zero(), m2 = Vec3::Zero();
};

// Applies the internal end forces to the nodes with the opposite sign, in global axes.
void store_ends(Beams& bm, Index e, const Axes& a, const EndForces& f) {
  double* out = &bm.corner_force[12 * static_cast<std::size_t>(e)];
  Mat3 rot;
  rot.col(0) = a.r;
  rot.col(1) = a.s;
  rot.col(2) = a.t;
  const Vec3 g[4] = {-(rot * f.f1), -(rot * f.m1), -(rot * f.f2), -(rot * f.m2)};
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c)
      out[3 * k + c] = g[k][c];
}

struct BeamContext {
  State& st;
  Beams& bm;
  const BeamBlock& block;
  const Material& mat;
  const BeamPassInput& in;
  double young;
};

// The stable step: the axial wave across the length, or the element's bending and torsion
// modes (their compile-time step, scaled with the length).
double beam_step(const BeamContext& c, Index e, double length) {
  const auto i = static_cast<std::size_t>(e);
  const double axial = length / std::sqrt(c.young / c.mat.density);
  return std::min(axial, c.bm.flexural_step[i] * length / c.bm.initial_length[i]);
}

// *MAT_SPOTWELD on a spot-weld beam: it fails at TFAIL, or when
// (max(N, 0) / NRR)^2 + (Vs / NRS)^2 + (Vt / NRT)^2 + (T / MRR)^2 + (Ms / MSS)^2 + (Mt / MTT)^2
// reaches 1 (terms with a zero strength left out; the axial term in tension only), the bending
// moments taken at the weld's more loaded end: |Ms| + L |Vt| / 2, |Mt| + L |Vs| / 2 (the
// resultants are the element's mid-length values, the shear adds its lever to either end).
bool spot_weld_fails(const BeamContext& c, const double* res, double length) {
  const Material& m = c.mat;
  if (m.failure_time > 0.0 && c.in.time >= m.failure_time) return true;
  const std::array<double, 6> load = {std::max(res[0], 0.0),
                                      res[1],
                                      res[2],
                                      res[3],
                                      std::abs(res[4]) + 0.5 * length * std::abs(res[2]),
                                      std::abs(res[5]) + 0.5 * length * std::abs(res[1])};
  double sum = 0.0;
  bool any = false;
  for (std::size_t k = 0; k < 6; ++k) {
    if (!(m.failure_resultants[k] > 0.0)) continue;
    any = true;
    const double ratio = load[k] / m.failure_resultants[k];
    sum += ratio * ratio;
  }
  return any && sum >= 1.0;
}

// Hughes-Liu: the fibres' uniaxial-stress updates and the resultants they give.
template <class Model>
ElementOutcome hughes_liu(BeamContext& c, const Model& model, Index e) {
  Beams& bm = c.bm;
  const auto i = static_cast<std::size_t>(e);
  const Axes a = advance_axes(c.st.nodes, c.bm, e, c.in.step);
  if (!(a.length > 0.0)) return {0.0, true, false};
  const Rates r = rates(c.st.nodes, c.bm, e, a);
  const BeamBlock& b = c.block;
  const double dt = c.in.step, kappa = b.shear_factor;
  double n = 0.0, vs = 0.0, vt = 0.0, torque = 0.0, ms = 0.0, mt = 0.0, work = 0.0;
  int failed = 0;
  const Index first = b.point_begin + b.points * (e - b.begin);
  for (int k = 0; k < b.points; ++k) {
    const Index p = first + k;
    const auto pp = static_cast<std::size_t>(p);
    const auto kk = static_cast<std::size_t>(k);
    if (bm.points.damage[pp] >= 1.0) {  // a failed fibre carries nothing
      ++failed;
      continue;
    }
    const double y = b.point_s[kk] * bm.width_s[i], z = b.point_t[kk] * bm.width_t[i];
    const double w = b.point_weight[kk] * bm.area[i];
    const double eps[6] = {(r.axial - y * r.curvature_t + z * r.curvature_s) * dt,
                           0.0,
                           0.0,
                           0.5 * (r.shear_s - z * r.twist) * dt,
                           0.0,
                           0.5 * (r.shear_t + y * r.twist) * dt};
    double* sigma = bm.points.stress.col(p).data();
    const double old[3] = {sigma[0], sigma[3], sigma[5]};
    double* alpha =
        bm.points.back_stress.size() > 0 ? bm.points.back_stress.col(p).data() : nullptr;
    const PlaneStressResult u = constrained_update(
        c.mat, model, eps, dt, bm.temperature[i], b.constrained_iterations,
        ShellPointState{sigma, alpha, bm.points.plastic_strain[pp], bm.points.damage[pp]},
        StressConstraint::uniaxial);
    if (u.failed) {
      bm.points.damage[pp] = 1.0;
      std::fill(sigma, sigma + 6, 0.0);
      ++failed;
    }
    // Work of the fibre (tensor shears twice, with the shear factor as the forces take it).
    work += w * (0.5 * (old[0] + sigma[0]) * eps[0] +
                 2.0 * kappa *
                     (0.5 * (old[1] + sigma[3]) * eps[3] + 0.5 * (old[2] + sigma[5]) * eps[5]));
    n += w * sigma[0];
    vs += kappa * w * sigma[3];
    vt += kappa * w * sigma[5];
    torque += kappa * w * (y * sigma[5] - z * sigma[3]);
    ms += w * z * sigma[0];
    mt -= w * y * sigma[0];
  }
  bm.internal_energy[i] += a.length * work;
  double* res = &bm.resultants[6 * i];
  res[0] = n;
  res[1] = vs;
  res[2] = vt;
  res[3] = torque;
  res[4] = ms;
  res[5] = mt;
  // Virtual power: N on the axial rate, V on the shear rates (which hold the mean spins),
  // T and M on the twist and curvature rates, all times L.
  const double l = a.length;
  EndForces f;
  f.f1 = Vec3(-n, -vs, -vt);
  f.f2 = Vec3(n, vs, vt);
  f.m1 = Vec3(-torque, -ms + 0.5 * l * vt, -mt - 0.5 * l * vs);
  f.m2 = Vec3(torque, ms + 0.5 * l * vt, mt - 0.5 * l * vs);
  store_ends(c.bm, e, a, f);
  const bool fibres_failed = b.points > 0 && failed == b.points;
  return {beam_step(c, e, l), false, fibres_failed || spot_weld_fails(c, res, l)};
}

// Belytschko-Schwer: elastic resultants; the end moments from the deformational rotation rates
// (spin minus chord rotation) by the Timoshenko stiffness EI / (L (1 + phi)) [4 + phi, 2 - phi;
// 2 - phi, 4 + phi], phi = 12 E I / (G SA L^2).
ElementOutcome belytschko_schwer(BeamContext& c, Index e) {
  Beams& bm = c.bm;
  const auto i = static_cast<std::size_t>(e);
  const Axes a = advance_axes(c.st.nodes, c.bm, e, c.in.step);
  if (!(a.length > 0.0)) return {0.0, true, false};
  const Rates r = rates(c.st.nodes, c.bm, e, a);
  const double dt = c.in.step, l = a.length;
  const double young = c.young, g = c.mat.shear_modulus;
  double* res = &bm.resultants[6 * i];
  double old[6];
  std::copy(res, res + 6, old);
  const double d1s = r.spin1_s - r.chord_s, d2s = r.spin2_s - r.chord_s;
  const double d1t = r.spin1_t - r.chord_t, d2t = r.spin2_t - r.chord_t;
  auto bend = [&](double inertia, double d1, double d2, double& m1, double& m2) {
    const double phi = 12.0 * young * inertia / (g * bm.shear_area[i] * l * l);
    const double k = young * inertia / (l * (1.0 + phi));
    m1 += k * ((4.0 + phi) * d1 + (2.0 - phi) * d2) * dt;
    m2 += k * ((2.0 - phi) * d1 + (4.0 + phi) * d2) * dt;
  };
  res[0] += young * bm.area[i] * r.axial * dt;
  res[1] += g * bm.torsion[i] * r.twist * dt;
  bend(bm.inertia_s[i], d1s, d2s, res[2], res[3]);
  bend(bm.inertia_t[i], d1t, d2t, res[4], res[5]);
  const double rate[6] = {r.axial * l, r.twist * l, d1s, d2s, d1t, d2t};
  double work = 0.0;
  for (int k = 0; k < 6; ++k)
    work += 0.5 * (old[k] + res[k]) * rate[k] * dt;
  bm.internal_energy[i] += work;
  // Virtual power: the chord rotations carry the end moments' sum onto the transverse
  // velocities (chord_t = v_s / L, chord_s = -v_t / L).
  const double sum_s = res[2] + res[3], sum_t = res[4] + res[5];
  EndForces f;
  f.f1 = Vec3(-res[0], sum_t / l, -sum_s / l);
  f.f2 = Vec3(res[0], -sum_t / l, sum_s / l);
  f.m1 = Vec3(-res[1], res[2], res[4]);
  f.m2 = Vec3(res[1], res[3], res[5]);
  store_ends(c.bm, e, a, f);
  return {beam_step(c, e, l), false, false};
}

template <class Model>
void block_pass(BeamContext& c, const Model& model, fe::PassTotals& totals) {
  Beams& b = c.bm;
  fe::element_loop(
      c.block.begin, c.block.end,
      fe::ElementArrays{b.eroded, b.corner_force, 12, b.mass, b.added_mass, b.time_step},
      c.in.scale_factor, c.in.mass_scaling_step, [](Index) { return false; },
      [&](Index e) {
        ElementOutcome o = c.block.formulation == BeamFormulation::belytschko_schwer
                               ? belytschko_schwer(c, e)
                               : hughes_liu(c, model, e);
        if (!std::isfinite(b.internal_energy[static_cast<std::size_t>(e)])) o.step = NAN;
        return o;
      },
      totals);
}

}  // namespace

Mat3 beam_axes(const State& state, const Beams& beams, Index element) {
  const auto& conn = beams.nodes[static_cast<std::size_t>(element)];
  const Vec3 d = state.nodes.position.col(conn[1]) - state.nodes.position.col(conn[0]);
  Mat3 axes = Mat3::Identity();
  if (!(d.norm() > 0.0)) return axes;
  axes.col(0) = d.normalized();
  Vec3 s = beams.s_axis.col(element);
  s -= s.dot(axes.col(0)) * axes.col(0);
  axes.col(1) = s.normalized();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}

ElementPassResult beam_element_pass(State& state, Beams& beams, const BeamPassInput& input) {
  fe::PassTotals totals;
  for (const BeamBlock& block : beams.blocks) {
    const Material& mat = state.materials[static_cast<std::size_t>(block.material)];
    BeamContext c{state, beams, block, mat, input, youngs_modulus(mat)};
    std::visit([&](const auto& model) { block_pass(c, model, totals); }, mat.model);
  }
  return totals.result();
}

void gather_beam_forces(const State& state, const Beams& beams, NodalForces& f) {
  fe::gather_forces_and_moments(state, beams.corner_force, beams.end_offsets, beams.ends, f);
}

}  // namespace mcdyna::solver
