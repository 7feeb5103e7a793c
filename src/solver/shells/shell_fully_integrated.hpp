#pragma once
/// Fully integrated shell (ELFORM 16): the Belytschko-Tsay element's corotational frame and
/// plane-stress layers, but 2 x 2 Gauss points in the plane instead of one, so that the
/// membrane and bending fields have no zero-energy modes and need no hourglass control, and the
/// transverse shear of Bathe and Dvorkin (1985, MITC4): the covariant shear strains are sampled
/// at the edge midpoints and interpolated, which keeps a thin element from locking in shear.
/// Every in-plane point has its own layers (points 4 x NIP per element).
#include "solver/shells/shell_kernel.hpp"

namespace mcdyna::solver::shell_kernel {

// Natural coordinates of the corners (counter-clockwise).
constexpr double kCornerXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kCornerEta[4] = {-1.0, -1.0, 1.0, 1.0};

// Bilinear shape functions and their natural derivatives at (xi, eta).
struct Shape {
  double n[4], dxi[4], deta[4];
};

inline Shape shape(double xi, double eta) {
  Shape s;
  for (int i = 0; i < 4; ++i) {
    s.n[i] = 0.25 * (1.0 + kCornerXi[i] * xi) * (1.0 + kCornerEta[i] * eta);
    s.dxi[i] = 0.25 * kCornerXi[i] * (1.0 + kCornerEta[i] * eta);
    s.deta[i] = 0.25 * kCornerEta[i] * (1.0 + kCornerXi[i] * xi);
  }
  return s;
}

// A transverse shear rate as its coefficients on each corner's normal velocity and angular
// velocities about the frame's e1 and e2.
struct ShearRow {
  double vz[4] = {}, tx[4] = {}, ty[4] = {};
};

inline ShearRow blend(const ShearRow& a, double wa, const ShearRow& b, double wb) {
  ShearRow r;
  for (int i = 0; i < 4; ++i) {
    r.vz[i] = wa * a.vz[i] + wb * b.vz[i];
    r.tx[i] = wa * a.tx[i] + wb * b.tx[i];
    r.ty[i] = wa * a.ty[i] + wb * b.ty[i];
  }
  return r;
}

// The covariant shear rate along xi (along = 0) or eta (1) at (xi, eta): the slope of the
// normal velocity along that direction plus the rotation's tilt of it,
// w_,a + theta_y x_,a - theta_x y_,a (gamma_xz = w_,x + theta_y, gamma_yz = w_,y - theta_x).
inline ShearRow covariant_shear(const Frame& f, double xi, double eta, int along) {
  const Shape s = shape(xi, eta);
  const double* d = along == 0 ? s.dxi : s.deta;
  double xa = 0.0, ya = 0.0;
  for (int i = 0; i < 4; ++i) {
    xa += d[i] * f.xl[i];
    ya += d[i] * f.yl[i];
  }
  ShearRow r;
  for (int i = 0; i < 4; ++i) {
    r.vz[i] = d[i];
    r.ty[i] = s.n[i] * xa;
    r.tx[i] = -s.n[i] * ya;
  }
  return r;
}

template <class Model>
fe::ElementOutcome fully_integrated(ShellContext& c, const Model& model, Index e) {
  Shells& sh = c.sh;
  const auto i = static_cast<std::size_t>(e);
  const auto [k, f, out] = start_element(c.st, c.sh, e);
  if (!(f.area > 0.0)) return {0.0, true, false};
  const auto [vx, vy, vz, tx, ty] = in_frame(k, f, 4);
  // Tying points of the assumed shear: the xi-shear at the edge midpoints (0, -1) and (0, 1),
  // the eta-shear at (-1, 0) and (1, 0).
  const ShearRow xi_low = covariant_shear(f, 0.0, -1.0, 0),
                 xi_high = covariant_shear(f, 0.0, 1.0, 0);
  const ShearRow eta_low = covariant_shear(f, -1.0, 0.0, 1),
                 eta_high = covariant_shear(f, 1.0, 0.0, 1);
  const double t = sh.thickness[i], kappa = c.block.shear_factor;
  const int layers = c.block.layers;
  const Index first = c.block.point_begin + 4 * layers * (e - c.block.begin);
  double work = 0.0, thickness_strain = 0.0, area = 0.0;
  double fx[4] = {}, fy[4] = {}, fz[4] = {}, mx[4] = {}, my[4] = {};
  int failed = 0;
  const double g = 1.0 / std::sqrt(3.0);  // 2-point Gauss abscissa, weight 1
  for (int p = 0; p < 4; ++p) {
    const double xi = g * kCornerXi[p], eta = g * kCornerEta[p];
    const Shape s = shape(xi, eta);
    // J = [x_xi y_xi; x_eta y_eta] in the frame; [N_x; N_y] = J^-1 [N_xi; N_eta].
    double j11 = 0.0, j12 = 0.0, j21 = 0.0, j22 = 0.0;
    for (int n = 0; n < 4; ++n) {
      j11 += s.dxi[n] * f.xl[n];
      j12 += s.dxi[n] * f.yl[n];
      j21 += s.deta[n] * f.xl[n];
      j22 += s.deta[n] * f.yl[n];
    }
    const double det = j11 * j22 - j12 * j21;
    if (!(det > 0.0)) return {0.0, true, false};
    double bx[4], by[4];
    for (int n = 0; n < 4; ++n) {
      bx[n] = (j22 * s.dxi[n] - j12 * s.deta[n]) / det;
      by[n] = (j11 * s.deta[n] - j21 * s.dxi[n]) / det;
    }
    // Assumed shear: the covariant rates interpolated from the tying points, then the
    // Cartesian ones, [g_xz; g_yz] = J^-1 [g_xi; g_eta].
    const ShearRow along_xi = blend(xi_low, 0.5 * (1.0 - eta), xi_high, 0.5 * (1.0 + eta));
    const ShearRow along_eta = blend(eta_low, 0.5 * (1.0 - xi), eta_high, 0.5 * (1.0 + xi));
    const ShearRow sx = blend(along_xi, j22 / det, along_eta, -j12 / det);
    const ShearRow sy = blend(along_xi, -j21 / det, along_eta, j11 / det);
    Rates r{};
    for (int n = 0; n < 4; ++n) {
      r.d[0] += bx[n] * vx[n];
      r.d[1] += by[n] * vy[n];
      r.d[2] += by[n] * vx[n] + bx[n] * vy[n];
      r.k[0] += bx[n] * ty[n];
      r.k[1] -= by[n] * tx[n];
      r.k[2] += by[n] * ty[n] - bx[n] * tx[n];
      r.g[0] += sx.vz[n] * vz[n] + sx.tx[n] * tx[n] + sx.ty[n] * ty[n];
      r.g[1] += sy.vz[n] * vz[n] + sy.tx[n] * tx[n] + sy.ty[n] * ty[n];
    }
    Resultants res;
    work += det * integrate_layers(c, model, e, first + p * layers, r, t, res, failed);
    thickness_strain += det * res.thickness_strain;
    area += det;
    // Internal forces: the transpose of the rates at this point, weighted by det J.
    for (int n = 0; n < 4; ++n) {
      fx[n] += det * (bx[n] * res.n[0] + by[n] * res.n[2]);
      fy[n] += det * (by[n] * res.n[1] + bx[n] * res.n[2]);
      fz[n] += det * kappa * (sx.vz[n] * res.q[0] + sy.vz[n] * res.q[1]);
      mx[n] += det * (-(by[n] * res.m[1] + bx[n] * res.m[2]) +
                      kappa * (sx.tx[n] * res.q[0] + sy.tx[n] * res.q[1]));
      my[n] += det * (bx[n] * res.m[0] + by[n] * res.m[2] +
                      kappa * (sx.ty[n] * res.q[0] + sy.ty[n] * res.q[1]));
    }
  }
  charge_work(c, e, work);
  if (c.block.thickness_update != ThicknessUpdate::none)
    sh.thickness[i] = t * (1.0 + thickness_strain / area);
  for (int n = 0; n < 4; ++n)
    add_corner(out, f, n, k.triangle, fx[n], fy[n], fz[n], mx[n], my[n]);
  return {shell_step(c, k.x, f.area, k.triangle), false, failed == 4 * layers,
          fe::runaway(f.area, c.sh.initial_area[static_cast<std::size_t>(e)])};
}

}  // namespace mcdyna::solver::shell_kernel
