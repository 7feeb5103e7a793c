#pragma once
/// The C0 triangle (*SECTION_SHELL ELFORM 4, and the triangles of ELFORM 2 / 16 parts under
/// *CONTROL_SHELL ESORT 1): a flat three-node Mindlin shell in its corotational frame with one
/// in-plane point, as the Belytschko-Tsay quadrilateral but exact on the triangle: constant-strain
/// membrane (CST), constant curvature from the linearly interpolated rotations, and the MITC3
/// transverse shear of Lee and Bathe (2004, Computers & Structures 82: 945-962), tied to the
/// tangential shear at the three edge midpoints so that thin plates do not lock. The MITC3 field
/// is linear; its centroid value (the mean of the midpoints') goes through the layers with the
/// plane-stress return, its linear part is resisted elastically with kappa G t (for an elastic
/// shell: the MITC3 shear energy integrated exactly, A/3 sum over the midpoints). Internal to
/// the shell element pass (shell_elements.cpp).
#include "solver/shells/shell_kernel.hpp"

namespace mcdyna::solver::shell_kernel {

// The triangle's frame: e3 the normal of its two first sides, e1 along side 1-2; the linear
// shape functions' derivatives in b1, b2 (corner 4 repeats corner 3 and takes none).
inline Frame triangle_frame(const Vec3 x[4]) {
  Frame f;
  f.area = 0.0;
  const Vec3 normal = (x[1] - x[0]).cross(x[2] - x[0]);
  const double nn = normal.norm();
  if (!(nn > 0.0)) return f;
  f.e3 = normal / nn;
  f.e1 = (x[1] - x[0]).normalized();
  f.e2 = f.e3.cross(f.e1);
  for (int i = 0; i < 4; ++i) {
    const Vec3 r = x[i] - x[0];
    f.xl[i] = r.dot(f.e1);
    f.yl[i] = r.dot(f.e2);
  }
  f.area = 0.5 * (f.xl[1] * f.yl[2] - f.xl[2] * f.yl[1]);
  if (!(f.area > 0.0)) return f;
  const double h = 0.5 / f.area;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    f.b1[i] = h * (f.yl[j] - f.yl[k]);
    f.b2[i] = h * (f.xl[k] - f.xl[j]);
  }
  f.b1[3] = f.b2[3] = 0.0;
  return f;
}

// MITC3 transverse shear rates (gamma_xz, gamma_yz) = grad w + (theta_y, -theta_x) at the
// centroid (g[0]) and at the midpoints of sides 1-2, 1-3, 2-3 (g[1..3]), from the corners' normal
// velocities and rotation rates in the frame. Covariant components along g_r = x2 - x1 and
// g_s = x3 - x1 are tied to the sides' tangential shear at their midpoints (exact for linear w
// and theta): e_rt = a + c s, e_st = b - c r with a, b the sides 1-2 and 1-3 values and c making
// e_st - e_rt equal side 2-3's.
inline void mitc3_shear(const Frame& f, const double vz[3], const double tx[3], const double ty[3],
                        double g[4][2]) {
  const double gr[2] = {f.xl[1] - f.xl[0], f.yl[1] - f.yl[0]};
  const double gs[2] = {f.xl[2] - f.xl[0], f.yl[2] - f.yl[0]};
  const double gq[2] = {gs[0] - gr[0], gs[1] - gr[1]};
  auto tangential = [&](int i, int j, const double d[2]) {
    return vz[j] - vz[i] + 0.5 * ((ty[i] + ty[j]) * d[0] - (tx[i] + tx[j]) * d[1]);
  };
  const double a = tangential(0, 1, gr), b = tangential(0, 2, gs), side23 = tangential(1, 2, gq);
  const double c = b - a - side23;
  // Covariant (e_rt, e_st) at the centroid (1/3, 1/3) and the midpoints (1/2, 0), (0, 1/2),
  // (1/2, 1/2); Cartesian from [g_r; g_s] gamma = e.
  const double covariant[4][2] = {
      {a + c / 3.0, b - c / 3.0}, {a, b - 0.5 * c}, {a + 0.5 * c, b}, {a + 0.5 * c, b - 0.5 * c}};
  const double det = gr[0] * gs[1] - gr[1] * gs[0];
  for (int p = 0; p < 4; ++p) {
    const double er = covariant[p][0], es = covariant[p][1];
    g[p][0] = (gs[1] * er - gr[1] * es) / det;
    g[p][1] = (gr[0] * es - gs[0] * er) / det;
  }
}

// The rotary inertia a corner of a C0 triangle needs for its rotations to stay below the
// element's highest membrane frequency 2 / dt (dt its L / c step estimate): the MITC3 shear ties
// the rotations harder than the Belytschko-Tsay quadrilateral's quarter weights, so its
// max(t^2 / 12, A / 8) m inertia is not enough (a cantilever of them blows up at TSSFAC 0.9).
// Gershgorin bound on the rotation rows of the elastic shear stiffness K, scaled by the corner
// masses: sum_theta |K_ij| / I + sum_w |K_ij| / sqrt(I m) <= (2 / dt)^2, solved for I.
inline double c0_triangle_inertia(const Vec3 x[4], double kappa_g_t, double corner_mass,
                                  double dt) {
  const Frame f = triangle_frame(x);
  if (!(f.area > 0.0) || !(dt > 0.0)) return 0.0;
  // Unit responses of the shear at the centroid and the midpoints to each corner's w, theta_x,
  // theta_y (DOF 3 n + k).
  double unit[9][4][2];
  for (int dof = 0; dof < 9; ++dof) {
    double uz[3] = {}, ux[3] = {}, uy[3] = {};
    (dof % 3 == 0 ? uz : dof % 3 == 1 ? ux : uy)[dof / 3] = 1.0;
    mitc3_shear(f, uz, ux, uy, unit[dof]);
  }
  auto stiffness = [&](int i, int j) {
    double k = 0.0;
    for (int a = 0; a < 2; ++a) {
      k += unit[i][0][a] * unit[j][0][a];
      for (int p = 1; p < 4; ++p)
        k += (unit[i][p][a] - unit[i][0][a]) * (unit[j][p][a] - unit[j][0][a]) / 3.0;
    }
    return kappa_g_t * f.area * k;
  };
  const double omega2 = 4.0 / (dt * dt);
  double needed = 0.0;
  for (int i = 0; i < 9; ++i) {
    if (i % 3 == 0) continue;  // a w row
    double rotations = 0.0, translations = 0.0;
    for (int j = 0; j < 9; ++j)
      (j % 3 == 0 ? translations : rotations) += std::abs(stiffness(i, j));
    // x = 1 / sqrt(I): rotations x^2 + translations / sqrt(m) x <= omega^2.
    const double b = translations / std::sqrt(corner_mass);
    const double root = (-b + std::sqrt(b * b + 4.0 * rotations * omega2)) / (2.0 * rotations);
    needed = std::max(needed, 1.0 / (root * root));
  }
  return needed;
}

template <class Model>
fe::ElementOutcome c0_triangle(ShellContext& c, const Model& model, Index e) {
  Shells& sh = c.sh;
  const auto i = static_cast<std::size_t>(e);
  double* out = &sh.corner_force[24 * i];
  std::fill(out, out + 24, 0.0);
  const Corners k = corners(c.st, c.sh, e);
  const Frame f = triangle_frame(k.x);
  if (!(f.area > 0.0)) return {0.0, true, false};
  const auto [vx, vy, vz, tx, ty] = in_frame(k, f, 3);
  Rates r{};
  for (int n = 0; n < 3; ++n) {
    r.d[0] += f.b1[n] * vx[n];
    r.d[1] += f.b2[n] * vy[n];
    r.d[2] += f.b2[n] * vx[n] + f.b1[n] * vy[n];
    r.k[0] += f.b1[n] * ty[n];
    r.k[1] -= f.b2[n] * tx[n];
    r.k[2] += f.b2[n] * ty[n] - f.b1[n] * tx[n];
  }
  double shear[4][2];
  mitc3_shear(f, vz, tx, ty, shear);
  r.g[0] = shear[0][0];
  r.g[1] = shear[0][1];
  const double t = sh.thickness[i];
  Resultants res;
  int failed = 0;
  const Index first =
      c.block.point_begin + c.block.layers * c.block.in_plane_points * (e - c.block.begin);
  double work = f.area * integrate_layers(c, model, e, first, r, t, res, failed);
  // The linear part of the MITC3 shear, elastic: resistances S_p (per unit area) at the
  // midpoints 1 and 2 kept between steps (S_3 = -S_1 - S_2, as the deviations sum to zero).
  const double kappa = c.block.shear_factor, dt = c.in.step;
  const double stiffness = kappa * c.mat.shear_modulus * t;
  double* kept = &sh.hourglass_force[5 * i];
  double s_old[3][2], s_new[3][2], deviation[3][2];
  for (int p = 0; p < 3; ++p)
    for (int a = 0; a < 2; ++a)
      deviation[p][a] = shear[p + 1][a] - shear[0][a];
  for (int a = 0; a < 2; ++a) {
    s_old[0][a] = kept[a];
    s_old[1][a] = kept[2 + a];
    s_old[2][a] = -s_old[0][a] - s_old[1][a];
    for (int p = 0; p < 3; ++p)
      s_new[p][a] = s_old[p][a] + stiffness * deviation[p][a] * dt;
    kept[a] = s_new[0][a];
    kept[2 + a] = s_new[1][a];
  }
  for (int p = 0; p < 3; ++p)
    for (int a = 0; a < 2; ++a)
      work += f.area / 3.0 * 0.5 * (s_old[p][a] + s_new[p][a]) * deviation[p][a] * dt;
  charge_work(c, e, work);
  if (c.block.thickness_update != ThicknessUpdate::none)
    sh.thickness[i] = t * (1.0 + res.thickness_strain);
  // Shear forces by virtual power: each corner's normal velocity and rotation rates enter the
  // shear linearly; their coefficients from unit rates.
  double fz[3] = {}, mx[3] = {}, my[3] = {};
  for (int n = 0; n < 3; ++n) {
    for (int dof = 0; dof < 3; ++dof) {
      double uz[3] = {}, ux[3] = {}, uy[3] = {};
      (dof == 0 ? uz : dof == 1 ? ux : uy)[n] = 1.0;
      double unit[4][2];
      mitc3_shear(f, uz, ux, uy, unit);
      double power = f.area * kappa * (unit[0][0] * res.q[0] + unit[0][1] * res.q[1]);
      for (int p = 0; p < 3; ++p)
        for (int a = 0; a < 2; ++a)
          power += f.area / 3.0 * s_new[p][a] * (unit[p + 1][a] - unit[0][a]);
      (dof == 0 ? fz : dof == 1 ? mx : my)[n] = power;
    }
  }
  const double a = f.area;
  for (int n = 0; n < 3; ++n) {
    const double fx = a * (f.b1[n] * res.n[0] + f.b2[n] * res.n[2]);
    const double fy = a * (f.b2[n] * res.n[1] + f.b1[n] * res.n[2]);
    const double bx = -a * (f.b2[n] * res.m[1] + f.b1[n] * res.m[2]);
    const double by = a * (f.b1[n] * res.m[0] + f.b2[n] * res.m[2]);
    add_corner(out, f, n, true, fx, fy, fz[n], bx + mx[n], by + my[n]);
  }
  const bool all_failed = failed == c.block.layers;
  return {shell_step(c, k.x, f.area, true), false, all_failed,
          fe::runaway(f.area, sh.initial_area[i])};
}

}  // namespace mcdyna::solver::shell_kernel
