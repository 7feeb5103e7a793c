// Element pass for Belytschko-Tsay shells (ELFORM 2). Notation of Belytschko, Lin and Tsay
// (1984) and the LS-DYNA Theory Manual: hats are the element's corotational frame (e3 the
// normal of the diagonals, e1 along the first side), B1 and B2 the centre derivatives of the
// bilinear shape functions, theta the nodal angular velocities.
#include "solver/fe/shell_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "solver/fe/element_loop.hpp"
#include "solver/material/plane_stress.hpp"

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
using fe::kParallelMinimum;

// The element's frame and centre derivatives at the current geometry.
struct Frame {
  Vec3 e1, e2, e3;
  double xl[4], yl[4];  // corner coordinates in the frame
  double area;          // <= 0: inverted or collapsed
  double b1[4], b2[4];  // dN_I/dx^, dN_I/dy^ at the centre
};

Frame frame(const Vec3 x[4]) {
  Frame f;
  const Vec3 normal = (x[2] - x[0]).cross(x[3] - x[1]);
  const double nn = normal.norm();
  f.area = 0.0;
  if (!(nn > 0.0)) return f;
  f.e3 = normal / nn;
  const Vec3 r21 = x[1] - x[0];
  Vec3 s1 = r21 - r21.dot(f.e3) * f.e3;
  const double n1 = s1.norm();
  if (!(n1 > 0.0)) return f;
  f.e1 = s1 / n1;
  f.e2 = f.e3.cross(f.e1);
  for (int i = 0; i < 4; ++i) {
    const Vec3 r = x[i] - x[0];
    f.xl[i] = r.dot(f.e1);
    f.yl[i] = r.dot(f.e2);
  }
  f.area =
      0.5 * ((f.xl[2] - f.xl[0]) * (f.yl[3] - f.yl[1]) - (f.xl[3] - f.xl[1]) * (f.yl[2] - f.yl[0]));
  if (!(f.area > 0.0)) return f;
  const double h = 0.5 / f.area;
  f.b1[0] = h * (f.yl[1] - f.yl[3]);
  f.b1[1] = h * (f.yl[2] - f.yl[0]);
  f.b1[2] = h * (f.yl[3] - f.yl[1]);
  f.b1[3] = h * (f.yl[0] - f.yl[2]);
  f.b2[0] = h * (f.xl[3] - f.xl[1]);
  f.b2[1] = h * (f.xl[0] - f.xl[2]);
  f.b2[2] = h * (f.xl[1] - f.xl[3]);
  f.b2[3] = h * (f.xl[2] - f.xl[0]);
  return f;
}

// Mid-surface rates: membrane d (xx, yy, 2xy), curvature rates k (xx, yy, 2xy), transverse
// shear rates g (2 d_xz, 2 d_yz); and the hourglass rates (membrane x y, bending x y, warping).
struct Rates {
  double d[3], k[3], g[2];
  double hourglass[5];
};

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

// Stress resultants per unit length: N = int sigma dz, M = int z sigma dz, Q = int sigma_z. dz.
struct Resultants {
  double n[3] = {}, m[3] = {}, q[2] = {};  // xx yy xy; xx yy xy; xz yz
  double thickness_strain = 0.0;           // mean over the layers (ISTUPD)
};

struct ShellContext {
  State& st;
  const ShellBlock& block;
  const Material& mat;
  const ShellPassInput& in;
  double young, poisson;
};

// Layers through the thickness: the plane-stress update of each point, its work, and the
// resultants. Returns the number of failed points.
template <class Model>
int integrate_layers(ShellContext& c, const Model& model, Index e, const Frame& f, const Rates& r,
                     double t, Resultants& res) {
  Shells& sh = c.st.shells;
  const ShellBlock& b = c.block;
  const auto i = static_cast<std::size_t>(e);
  const double dt = c.in.step;
  const double kappa = b.shear_factor;
  const Index first = b.point_begin + b.layers * (e - b.begin);
  int failed = 0;
  double work = 0.0;
  for (int l = 0; l < b.layers; ++l) {
    const Index p = first + l;
    const auto pp = static_cast<std::size_t>(p);
    const double z = 0.5 * t * (b.layer_z[static_cast<std::size_t>(l)] - b.reference_surface);
    const double w = 0.5 * t * b.layer_weight[static_cast<std::size_t>(l)];
    double* sigma = sh.points.stress.col(p).data();
    if (sh.points.damage[pp] >= 1.0) {  // a failed point carries nothing
      ++failed;
      continue;
    }
    const double eps[6] = {
        (r.d[0] + z * r.k[0]) * dt,       (r.d[1] + z * r.k[1]) * dt, 0.0,
        0.5 * (r.d[2] + z * r.k[2]) * dt, 0.5 * r.g[1] * dt,          0.5 * r.g[0] * dt};
    double old[6];
    std::copy(sigma, sigma + 6, old);
    double* alpha =
        sh.points.back_stress.size() > 0 ? sh.points.back_stress.col(p).data() : nullptr;
    const PlaneStressResult ps = plane_stress_update(
        c.mat, model, eps, dt, sh.temperature[i], b.plane_stress_iterations,
        ShellPointState{sigma, alpha, sh.points.plastic_strain[pp], sh.points.damage[pp]});
    // ISTUPD 4 leaves out the elastic part, -nu / E (d sigma_xx + d sigma_yy).
    const double elastic = b.thickness_update == 4
                               ? -c.poisson / c.young * (sigma[0] - old[0] + sigma[1] - old[1])
                               : 0.0;
    res.thickness_strain +=
        0.5 * b.layer_weight[static_cast<std::size_t>(l)] * (ps.thickness_strain - elastic);
    if (ps.failed) {
      sh.points.damage[pp] = 1.0;
      std::fill(sigma, sigma + 6, 0.0);
      ++failed;
    }
    // Work per unit area of the layer: the mid-step stress on the increment (tensor shears
    // twice; the transverse shear with the shear factor, as the forces take it).
    double dw = 0.0;
    for (int k = 0; k < 6; ++k) {
      const double mid = 0.5 * (old[k] + sigma[k]);
      const double factor = k < 3 ? 1.0 : (k == 3 ? 2.0 : 2.0 * kappa);
      dw += factor * mid * eps[k];
    }
    work += w * dw;
    res.n[0] += w * sigma[0];
    res.n[1] += w * sigma[1];
    res.n[2] += w * sigma[3];
    res.m[0] += w * z * sigma[0];
    res.m[1] += w * z * sigma[1];
    res.m[2] += w * z * sigma[3];
    res.q[0] += w * sigma[5];
    res.q[1] += w * sigma[4];
  }
  sh.internal_energy[i] += f.area * work;
  if (c.mat.specific_heat > 0.0) {
    // Adiabatic heating of MAT_015: the element's work per volume into its temperature.
    sh.temperature[i] = c.mat.room_temperature +
                        sh.internal_energy[i] / (c.mat.density * sh.initial_area[i] *
                                                 sh.initial_thickness[i] * c.mat.specific_heat);
  }
  return failed;
}

// The hourglass resistances (local frame) and their work this step. Stiffness (IHQ 4, 5):
// Q += r k qdot dt with the stiffnesses of Belytschko, Lin and Tsay, membrane E t A sum|B|^2 / 8,
// bending E t^3 A sum|B|^2 / 192, warping kappa G t^3 sum|B|^2 / 12, r = QM, QB, QW.
// Viscous (IHQ 1-3): Q = r sqrt(k m) qdot, r times the critical damping of the mode (whose
// squared norm |gamma|^2 is about 4) with the corner mass or rotary inertia.
double hourglass(ShellContext& c, Index e, const Frame& f, const Rates& r, double t,
                 double resist[5]) {
  const ShellBlock& b = c.block;
  double* q = &c.st.shells.hourglass_force[5 * static_cast<std::size_t>(e)];
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
  const double corner_mass = 0.25 * c.st.shells.mass[static_cast<std::size_t>(e)];
  const double inertia = c.st.shells.corner_inertia[static_cast<std::size_t>(e)];
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

// The element step: the shortest characteristic length over the plane-stress wave speed
// sqrt(E / (rho (1 - nu^2))); the length is A over the longest side (quadrilateral) or 2A over it
// (triangle), LS-DYNA's ISDO 0.
double shell_step(const ShellContext& c, const Vec3 x[4], double area, bool triangle) {
  double longest = 0.0;
  const int n = triangle ? 3 : 4;
  for (int i = 0; i < n; ++i)
    longest = std::max(longest, (x[(i + 1) % n] - x[i]).squaredNorm());
  const double length = (triangle ? 2.0 : 1.0) * area / std::sqrt(longest);
  const double speed = std::sqrt(c.young / (c.mat.density * (1.0 - c.poisson * c.poisson)));
  return length / speed;
}

template <class Model>
ElementOutcome belytschko_tsay(ShellContext& c, const Model& model, Index e) {
  State& st = c.st;
  Shells& sh = st.shells;
  const auto i = static_cast<std::size_t>(e);
  const auto& conn = sh.nodes[i];
  const bool triangle = conn[3] == conn[2];
  Vec3 x[4], v[4], w[4];
  for (int n = 0; n < 4; ++n) {
    x[n] = st.nodes.position.col(conn[static_cast<std::size_t>(n)]);
    v[n] = st.nodes.velocity.col(conn[static_cast<std::size_t>(n)]);
    w[n] = st.nodes.angular_velocity.col(conn[static_cast<std::size_t>(n)]);
  }
  double* out = &sh.corner_force[24 * i];
  std::fill(out, out + 24, 0.0);
  const Frame f = frame(x);
  if (!(f.area > 0.0)) return {0.0, true, false};
  double gamma[4];
  hourglass_vector(f, gamma);
  const Rates r = rates(f, gamma, v, w);
  const double t = sh.thickness[i];
  Resultants res;
  const int failed = integrate_layers(c, model, e, f, r, t, res);
  double q[5];
  sh.hourglass_energy[i] += hourglass(c, e, f, r, t, q);
  if (c.block.thickness_update != 0) sh.thickness[i] = t * (1.0 + res.thickness_strain);
  // Internal forces, the transpose of the rates (virtual power), plus the hourglass
  // resistances on gamma; applied to the nodes with the opposite sign.
  const double a = f.area, kappa = c.block.shear_factor;
  for (int n = 0; n < 4; ++n) {
    const double fx = a * (f.b1[n] * res.n[0] + f.b2[n] * res.n[2]) + gamma[n] * q[0];
    const double fy = a * (f.b2[n] * res.n[1] + f.b1[n] * res.n[2]) + gamma[n] * q[1];
    const double fz = a * kappa * (f.b1[n] * res.q[0] + f.b2[n] * res.q[1]) + gamma[n] * q[4];
    const double mx = -a * (f.b2[n] * res.m[1] + f.b1[n] * res.m[2]) - 0.25 * a * kappa * res.q[1] +
                      gamma[n] * q[2];
    const double my = a * (f.b1[n] * res.m[0] + f.b2[n] * res.m[2]) + 0.25 * a * kappa * res.q[0] +
                      gamma[n] * q[3];
    const Vec3 force = -(fx * f.e1 + fy * f.e2 + fz * f.e3);
    const Vec3 moment = -(mx * f.e1 + my * f.e2);
    const int corner = triangle && n == 3 ? 2 : n;  // a triangle's fourth corner is its third
    for (int k = 0; k < 3; ++k) {
      out[6 * corner + k] += force[k];
      out[6 * corner + 3 + k] += moment[k];
    }
  }
  const bool all_failed = failed == c.block.layers;
  return {shell_step(c, x, f.area, triangle), false, all_failed};
}

template <class Model>
void block_pass(ShellContext& c, const Model& model, fe::PassTotals& totals) {
  Shells& s = c.st.shells;
  fe::element_loop(
      c.block.begin, c.block.end,
      fe::ElementArrays{s.eroded, s.corner_force, 24, s.mass, s.added_mass, s.time_step},
      c.in.scale_factor, c.in.mass_scaling_step, [](Index) { return false; },
      [&](Index e) {
        ElementOutcome o = belytschko_tsay(c, model, e);
        if (!std::isfinite(s.internal_energy[static_cast<std::size_t>(e)])) o.step = NAN;
        return o;
      },
      totals);
}

}  // namespace

Mat3 shell_axes(const State& state, Index element) {
  const auto& conn = state.shells.nodes[static_cast<std::size_t>(element)];
  Vec3 x[4];
  for (int n = 0; n < 4; ++n)
    x[n] = state.nodes.position.col(conn[static_cast<std::size_t>(n)]);
  const Frame f = frame(x);
  Mat3 r = Mat3::Identity();
  if (f.area > 0.0) {
    r.col(0) = f.e1;
    r.col(1) = f.e2;
    r.col(2) = f.e3;
  }
  return r;
}

ElementPassResult shell_element_pass(State& state, const ShellPassInput& input) {
  fe::PassTotals totals;
  for (const ShellBlock& block : state.shells.blocks) {
    const Material& mat = state.materials[static_cast<std::size_t>(block.material)];
    ShellContext c{state, block, mat, input, youngs_modulus(mat), poisson_ratio(mat)};
    std::visit([&](const auto& model) { block_pass(c, model, totals); }, mat.model);
  }
  return totals.result();
}

void gather_shell_forces(State& state) {
  Nodes& nd = state.nodes;
  const double* cf = state.shells.corner_force.data();
  const std::size_t count = state.ownership.moved_count(nd.count());
#pragma omp parallel for schedule(static) if (count > 4 * kParallelMinimum)
  for (std::size_t k = 0; k < count; ++k) {
    const Index n = state.ownership.moved_node(k);
    const auto nn = static_cast<std::size_t>(n);
    const Index begin = nd.shell_corner_offsets[nn], end = nd.shell_corner_offsets[nn + 1];
    if (begin == end) continue;
    double sum[6] = {};
    for (Index j = begin; j < end; ++j) {
      const double* c =
          cf + 6 * static_cast<std::size_t>(nd.shell_corners[static_cast<std::size_t>(j)]);
      for (int d = 0; d < 6; ++d)
        sum[d] += c[d];
    }
    for (int d = 0; d < 3; ++d) {
      nd.force(d, n) += sum[d];
      nd.moment(d, n) += sum[3 + d];
    }
  }
}

}  // namespace mcdyna::solver
