// Element pass for Belytschko-Tsay shells (ELFORM 2). Notation of Belytschko, Lin and Tsay
// (1984) and the LS-DYNA Theory Manual: hats are the element's corotational frame (e3 the
// normal of the diagonals, e1 along the first side), B1 and B2 the centre derivatives of the
// bilinear shape functions, theta the nodal angular velocities.
#include "solver/shells/shell_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "solver/fe/element_loop.hpp"
#include "solver/shells/shell_c0_triangle.hpp"
#include "solver/shells/shell_fully_integrated.hpp"
#include "solver/shells/shell_kernel.hpp"

namespace mcdyna::solver {

double youngs_modulus(const Material& m) {
  const double g = m.shear_modulus, k = m.bulk_modulus;
  return 9.0 * k * g / (3.0 * k + g);
}

double poisson_ratio(const Material& m) {
  const double g = m.shear_modulus, k = m.bulk_modulus;
  return (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
}

namespace {

using fe::ElementOutcome;
using namespace shell_kernel;

Rates rates(const Frame& f, const double gamma[4], const Vec3 v[4], const Vec3 w[4]) {
  Rates r{};
  for (int i = 0; i < 4; ++i) {
    const double vx = v[i].dot(f.e1), vy = v[i].dot(f.e2), vz = v[i].dot(f.e3);
    const double tx = w[i].dot(f.e1), ty = w[i].dot(f.e2);
    r.d[0] += f.b1[i] * vx;
    r.d[1] += f.b2[i] * vy;
    r.d[2] += f.b2[i] * vx + f.b1[i] * vy;
    r.k[0] += f.b1[i] * ty;
    r.k[1] -= f.b2[i] * tx;
    r.k[2] += f.b2[i] * ty - f.b1[i] * tx;
    r.g[0] += f.b1[i] * vz + 0.25 * ty;
    r.g[1] += f.b2[i] * vz - 0.25 * tx;
    r.hourglass[0] += gamma[i] * vx;
    r.hourglass[1] += gamma[i] * vy;
    r.hourglass[2] += gamma[i] * tx;
    r.hourglass[3] += gamma[i] * ty;
    r.hourglass[4] += gamma[i] * vz;
  }
  return r;
}

// The hourglass vector gamma_I = h_I - (h . x^) B1_I - (h . y^) B2_I, h = (1, -1, 1, -1):
// orthogonal to every linear field, so rigid motion and uniform strain give no hourglass rate.
void hourglass_vector(const Frame& f, double gamma[4]) {
  static constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};
  double hx = 0.0, hy = 0.0;
  for (int i = 0; i < 4; ++i) {
    hx += h[i] * f.xl[i];
    hy += h[i] * f.yl[i];
  }
  for (int i = 0; i < 4; ++i)
    gamma[i] = h[i] - hx * f.b1[i] - hy * f.b2[i];
}

// The hourglass resistances (local frame) and their work this step. Stiffness (IHQ 4, 5):
// Q += r k qdot dt with the stiffnesses of Belytschko, Lin and Tsay, membrane E t A sum|B|^2 / 8,
// bending E t^3 A sum|B|^2 / 192, warping kappa G t^3 sum|B|^2 / 12, r = QM, QB, QW.
// Viscous (IHQ 1-3): Q = r sqrt(k m) qdot, r times the critical damping of the mode (whose
// squared norm |gamma|^2 is about 4) with the corner mass or rotary inertia.
double hourglass(ShellContext& c, Index e, const Frame& f, const Rates& r, double t,
                 double resist[5]) {
  const ShellBlock& b = c.block;
  double* q = &c.sh.hourglass_force[5 * static_cast<std::size_t>(e)];
  double bb = 0.0;
  for (int i = 0; i < 4; ++i)
    bb += f.b1[i] * f.b1[i] + f.b2[i] * f.b2[i];
  const double g = c.mat.shear_modulus;
  const double k_membrane = c.young * t * f.area * bb / 8.0;
  const double k_bending = c.young * t * t * t * f.area * bb / 192.0;
  const double k_warping = b.shear_factor * g * t * t * t * bb / 12.0;
  const double stiff[5] = {k_membrane, k_membrane, k_bending, k_bending, k_warping};
  const double coef[5] = {b.hourglass.coefficient, b.hourglass.coefficient, b.bending_hourglass,
                          b.bending_hourglass, b.warping_hourglass};
  const bool stiffness = b.hourglass.stiffness();
  const double corner_mass = 0.25 * c.sh.mass[static_cast<std::size_t>(e)];
  const double inertia = c.sh.corner_inertia[static_cast<std::size_t>(e)];
  const double dt = c.in.step;
  double power = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double old = q[k];
    if (stiffness) {
      resist[k] = old + coef[k] * stiff[k] * r.hourglass[k] * dt;
    } else {
      const double m = (k == 2 || k == 3) ? inertia : corner_mass;
      resist[k] = coef[k] * std::sqrt(stiff[k] * m) * r.hourglass[k];
    }
    q[k] = resist[k];
    power += 0.5 * (old + resist[k]) * r.hourglass[k];
  }
  return power * dt;
}

template <class Model>
ElementOutcome belytschko_tsay(ShellContext& c, const Model& model, Index e) {
  Shells& sh = c.sh;
  const auto i = static_cast<std::size_t>(e);
  const auto [k, f, out] = start_element(c.st, c.sh, e);
  if (!(f.area > 0.0)) return {0.0, true, false};
  double gamma[4];
  hourglass_vector(f, gamma);
  const Rates r = rates(f, gamma, k.v, k.w);
  const double t = sh.thickness[i];
  Resultants res;
  int failed = 0;
  const Index first = c.block.point_begin + c.block.layers * (e - c.block.begin);
  charge_work(c, e, f.area * integrate_layers(c, model, e, first, r, t, res, failed));
  double q[5];
  sh.hourglass_energy[i] += hourglass(c, e, f, r, t, q);
  if (c.block.thickness_update != ThicknessUpdate::none)
    sh.thickness[i] = t * (1.0 + res.thickness_strain);
  // Internal forces, the transpose of the rates (virtual power), plus the hourglass
  // resistances on gamma.
  const double a = f.area, kappa = c.block.shear_factor;
  for (int n = 0; n < 4; ++n) {
    const double fx = a * (f.b1[n] * res.n[0] + f.b2[n] * res.n[2]) + gamma[n] * q[0];
    const double fy = a * (f.b2[n] * res.n[1] + f.b1[n] * res.n[2]) + gamma[n] * q[1];
    const double fz = a * kappa * (f.b1[n] * res.q[0] + f.b2[n] * res.q[1]) + gamma[n] * q[4];
    const double mx = -a * (f.b2[n] * res.m[1] + f.b1[n] * res.m[2]) - 0.25 * a * kappa * res.q[1] +
                      gamma[n] * q[2];
    const double my = a * (f.b1[n] * res.m[0] + f.b2[n] * res.m[2]) + 0.25 * a * kappa * res.q[0] +
                      gamma[n] * q[3];
    add_corner(out, f, n, k.triangle, fx, fy, fz, mx, my);
  }
  const bool all_failed = failed == c.block.layers;
  return {shell_step(c, k.x, f.area, k.triangle), false, all_failed,
          fe::runaway(f.area, c.sh.initial_area[static_cast<std::size_t>(e)])};
}

template <class Model>
void block_pass(ShellContext& c, const Model& model, fe::PassTotals& totals) {
  Shells& s = c.sh;
  fe::element_loop(
      c.block.begin, c.block.end,
      fe::ElementArrays{s.eroded, s.corner_force, 24, s.mass, s.added_mass, s.time_step},
      c.in.scale_factor, c.in.mass_scaling_step, [](Index) { return false; },
      [&](Index e) {
        const bool triangle =
            s.nodes[static_cast<std::size_t>(e)][3] == s.nodes[static_cast<std::size_t>(e)][2];
        ElementOutcome o = c.block.formulation == ShellFormulation::c0_triangle ||
                                   (triangle && c.block.sort_triangles)
                               ? c0_triangle(c, model, e)
                           : c.block.formulation == ShellFormulation::fully_integrated
                               ? fully_integrated(c, model, e)
                               : belytschko_tsay(c, model, e);
        if (!std::isfinite(s.internal_energy[static_cast<std::size_t>(e)])) o.step = NAN;
        return o;
      },
      totals);
}

}  // namespace

Mat3 shell_axes(const Nodes& nodes, const Shells& shells, Index element) {
  const auto& conn = shells.nodes[static_cast<std::size_t>(element)];
  Vec3 x[4];
  for (int n = 0; n < 4; ++n)
    x[n] = nodes.position.col(conn[static_cast<std::size_t>(n)]);
  const Frame f = frame(x);
  Mat3 r = Mat3::Identity();
  if (f.area > 0.0) {
    r.col(0) = f.e1;
    r.col(1) = f.e2;
    r.col(2) = f.e3;
  }
  return r;
}

ElementPassResult shell_element_pass(State& state, Shells& shells, const ShellPassInput& input) {
  fe::PassTotals totals;
  for (const ShellBlock& block : shells.blocks) {
    const Material& mat = state.materials[static_cast<std::size_t>(block.material)];
    ShellContext c{state, shells, block, mat, input, youngs_modulus(mat), poisson_ratio(mat)};
    std::visit([&](const auto& model) { block_pass(c, model, totals); }, mat.model);
  }
  return totals.result();
}

void gather_shell_forces(const State& state, const Shells& shells, NodalForces& f) {
  fe::gather_forces_and_moments(state, shells.corner_force, shells.corner_offsets,
                                shells.node_corners, f);
}

}  // namespace mcdyna::solver
