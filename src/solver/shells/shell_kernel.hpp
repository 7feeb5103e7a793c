#pragma once
/// What the shell elements share (Belytschko-Tsay, shell_elements.cpp; fully integrated,
/// shell_fully_integrated.hpp): the element's corotational frame, the mid-surface rates, the
/// plane-stress layers through the thickness and their resultants, the element step. Internal
/// to the shell element pass.
#include <algorithm>
#include <cmath>

#include "solver/material/plane_stress.hpp"
#include "solver/shells/shell_elements.hpp"

namespace mcdyna::solver::shell_kernel {

// The element's frame and centre derivatives at the current geometry.
struct Frame {
  Vec3 e1, e2, e3;
  double xl[4], yl[4];  // corner coordinates in the frame
  double area;          // <= 0: inverted or collapsed
  double b1[4], b2[4];  // dN_I/dx^, dN_I/dy^ at the centre
};

inline Frame frame(const Vec3 x[4]) {
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

// Stress resultants per unit length: N = int sigma dz, M = int z sigma dz, Q = int sigma_z. dz.
struct Resultants {
  double n[3] = {}, m[3] = {}, q[2] = {};  // xx yy xy; xx yy xy; xz yz
  double thickness_strain = 0.0;           // mean over the layers (ISTUPD)
};

struct ShellContext {
  State& st;
  Shells& sh;
  const ShellBlock& block;
  const Material& mat;
  const ShellPassInput& in;
  double young, poisson;
};

// Layers through the thickness at one in-plane point (its layers from `first`): the
// plane-stress update of each, and the resultants. Adds the failed points to `failed`; returns
// the work per unit area.
template <class Model>
double integrate_layers(ShellContext& c, const Model& model, Index e, Index first, const Rates& r,
                        double t, Resultants& res, int& failed) {
  Shells& sh = c.sh;
  const ShellBlock& b = c.block;
  const auto i = static_cast<std::size_t>(e);
  const double dt = c.in.step;
  const double kappa = b.shear_factor;
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
    const double elastic = b.thickness_update == ThicknessUpdate::plastic
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
  return work;
}

// The element's work this step (area times work per area) into its internal energy and, for
// MAT_015, its adiabatic temperature.
inline void charge_work(ShellContext& c, Index e, double work) {
  Shells& sh = c.sh;
  const auto i = static_cast<std::size_t>(e);
  sh.internal_energy[i] += work;
  if (c.mat.specific_heat > 0.0) {
    sh.temperature[i] = c.mat.room_temperature +
                        sh.internal_energy[i] / (c.mat.density * sh.initial_area[i] *
                                                 sh.initial_thickness[i] * c.mat.specific_heat);
  }
}

// The element step: the shortest characteristic length over the plane-stress wave speed
// sqrt(E / (rho (1 - nu^2))); the length is A over the longest side (quadrilateral) or 2A over it
// (triangle), LS-DYNA's ISDO 0.
inline double shell_step(const Vec3 x[4], double area, bool triangle, double young, double poisson,
                         double density) {
  double longest = 0.0;
  const int n = triangle ? 3 : 4;
  for (int i = 0; i < n; ++i)
    longest = std::max(longest, (x[(i + 1) % n] - x[i]).squaredNorm());
  const double length = (triangle ? 2.0 : 1.0) * area / std::sqrt(longest);
  const double speed = std::sqrt(young / (density * (1.0 - poisson * poisson)));
  return length / speed;
}

inline double shell_step(const ShellContext& c, const Vec3 x[4], double area, bool triangle) {
  return shell_step(x, area, triangle, c.young, c.poisson, c.mat.density);
}

// The element's corners at the start of its pass: positions, velocities, angular velocities.
struct Corners {
  Vec3 x[4], v[4], w[4];
  bool triangle = false;  ///< the fourth corner repeats the third
};

inline Corners corners(const State& st, const Shells& sh, Index e) {
  Corners k;
  const auto& conn = sh.nodes[static_cast<std::size_t>(e)];
  k.triangle = conn[3] == conn[2];
  for (std::size_t n = 0; n < 4; ++n) {
    k.x[n] = st.nodes.position.col(conn[n]);
    k.v[n] = st.nodes.velocity.col(conn[n]);
    k.w[n] = st.nodes.angular_velocity.col(conn[n]);
  }
  return k;
}

// The corners' velocities and rotation rates on the element's frame (`n` corners).
struct FrameVelocities {
  double vx[4], vy[4], vz[4], tx[4], ty[4];
};

inline FrameVelocities in_frame(const Corners& k, const Frame& f, int n) {
  FrameVelocities u{};
  for (int i = 0; i < n; ++i) {
    u.vx[i] = k.v[i].dot(f.e1);
    u.vy[i] = k.v[i].dot(f.e2);
    u.vz[i] = k.v[i].dot(f.e3);
    u.tx[i] = k.w[i].dot(f.e1);
    u.ty[i] = k.w[i].dot(f.e2);
  }
  return u;
}

// The start of an element's pass: its corners, its frame, and its corner forces cleared.
struct ElementStart {
  Corners k;
  Frame f;
  double* out;
};

inline ElementStart start_element(const State& st, Shells& sh, Index e) {
  double* out = &sh.corner_force[24 * static_cast<std::size_t>(e)];
  std::fill(out, out + 24, 0.0);
  const Corners k = corners(st, sh, e);
  return {k, frame(k.x), out};
}

// Corner n's internal force (fx fy fz) and moment (mx my) in the frame, applied to its node
// with the opposite sign in global axes (a triangle's fourth corner is its third).
inline void add_corner(double* out, const Frame& f, int n, bool triangle, double fx, double fy,
                       double fz, double mx, double my) {
  const Vec3 force = -(fx * f.e1 + fy * f.e2 + fz * f.e3);
  const Vec3 moment = -(mx * f.e1 + my * f.e2);
  const int corner = triangle && n == 3 ? 2 : n;
  for (int k = 0; k < 3; ++k) {
    out[6 * corner + k] += force[k];
    out[6 * corner + 3 + k] += moment[k];
  }
}

}  // namespace mcdyna::solver::shell_kernel
