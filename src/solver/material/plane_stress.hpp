#pragma once
/// The plane-stress update of a shell layer point: the strain increment in the element's
/// corotational frame with the thickness strain unknown, found so that sigma_zz = 0 after the
/// material's own (3D) update. Elastic: exact in one step. Plastic: the 3D radial return of
/// constitutive.hpp with the thickness strain found by secant iteration, to a residual of 1e-10
/// times the stress or `max_iterations` secant steps (*CONTROL_SHELL MITER 1, LS-DYNA's default:
/// 3; MITER 2, full iteration: 30).
#include <algorithm>
#include <cmath>

#include "solver/material/constitutive.hpp"

namespace mcdyna::solver {

/// One layer point's state, by reference into the shell point arrays.
struct ShellPointState {
  double* stress;       ///< xx yy zz xy yz zx, tensor shears, zz = 0
  double* back_stress;  ///< nullptr unless the material has kinematic hardening
  double& plastic_strain;
  double& damage;
};

struct PlaneStressResult {
  double thickness_strain = 0.0;  ///< d_zz dt the point took
  double plastic_increment = 0.0;
  bool failed = false;
};

namespace detail {

// The 3D update of one point for a trial thickness strain: the pressure by the bulk modulus, the
// deviator by the material's model. Writes the new stress (and state) into `out`.
template <class Model>
PointResult trial_update(const Material& m, const Model& model, const double* eps, double rate,
                         double temperature, const double* sigma, const double* alpha, double ep,
                         double dmg, double* out, double* alpha_out, double& ep_out,
                         double& dmg_out) {
  const double p_old = -(sigma[0] + sigma[1] + sigma[2]) / 3.0;
  const double trace = eps[0] + eps[1] + eps[2];
  double s[6] = {sigma[0] + p_old, sigma[1] + p_old, sigma[2] + p_old,
                 sigma[3],         sigma[4],         sigma[5]};
  double de[6] = {
      eps[0] - trace / 3.0, eps[1] - trace / 3.0, eps[2] - trace / 3.0, eps[3], eps[4], eps[5]};
  if (alpha) std::copy(alpha, alpha + 6, alpha_out);
  ep_out = ep;
  dmg_out = dmg;
  const PointResult r =
      update_deviator(m, model, PointInput{de, rate, temperature, p_old},
                      PointState{s, alpha ? alpha_out : nullptr, ep_out, dmg_out});
  const double p = p_old - m.bulk_modulus * trace;
  for (int k = 0; k < 6; ++k)
    out[k] = s[k] - (k < 3 ? p : 0.0);
  return r;
}

}  // namespace detail

/// Updates a point under the in-plane and transverse-shear strain increments `eps` (xx yy - xy
/// yz zx, tensor shears; eps[2] is ignored) over dt, keeping sigma_zz = 0.
template <class Model>
PlaneStressResult plane_stress_update(const Material& m, const Model& model, const double* eps_in,
                                      double dt, double temperature, int max_iterations,
                                      ShellPointState st) {
  PlaneStressResult r;
  const double g = m.shear_modulus, k = m.bulk_modulus;
  const double lambda = k - 2.0 * g / 3.0;
  double eps[6] = {eps_in[0], eps_in[1], 0.0, eps_in[3], eps_in[4], eps_in[5]};
  // The elastic thickness strain: sigma_zz stays 0 under lambda tr + 2 G e_zz.
  eps[2] = -lambda / (lambda + 2.0 * g) * (eps[0] + eps[1]);
  if constexpr (std::is_same_v<Model, ElasticModel>) {
    const double tr = eps[0] + eps[1] + eps[2];
    for (int i = 0; i < 6; ++i)
      st.stress[i] += 2.0 * g * eps[i] + (i < 3 ? lambda * tr : 0.0);
    st.stress[2] = 0.0;
    r.thickness_strain = eps[2];
    return r;
  } else {
    double out[6], alpha[6], ep = 0.0, dmg = 0.0;
    auto sigma_zz = [&](double ezz, PointResult& pr) {
      eps[2] = ezz;
      const double mean = (eps[0] + eps[1] + eps[2]) / 3.0;
      const double dev[6] = {eps[0] - mean, eps[1] - mean, eps[2] - mean, eps[3], eps[4], eps[5]};
      const double rate = dt > 0.0 ? std::sqrt(2.0 / 3.0 * contract(dev, dev)) / dt : 0.0;
      pr = detail::trial_update(m, model, eps, rate, temperature, st.stress, st.back_stress,
                                st.plastic_strain, st.damage, out, alpha, ep, dmg);
      return out[2];
    };
    PointResult pr;
    double x0 = eps[2];
    double f0 = sigma_zz(x0, pr);
    const double scale = std::max({std::abs(out[0]), std::abs(out[1]), std::abs(out[3]), 1e-300});
    if (std::abs(f0) > 1e-10 * scale) {
      // Second guess from the elastic tangent, then secant steps (sigma_zz is monotone in e_zz).
      double x1 = x0 - f0 / (lambda + 2.0 * g);
      double f1 = sigma_zz(x1, pr);
      for (int it = 0; it < max_iterations && std::abs(f1) > 1e-10 * scale && f1 != f0; ++it) {
        const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = sigma_zz(x1, pr);
      }
    }
    std::copy(out, out + 6, st.stress);
    st.stress[2] = 0.0;
    if (st.back_stress) std::copy(alpha, alpha + 6, st.back_stress);
    r.plastic_increment = ep - st.plastic_strain;
    st.plastic_strain = ep;
    st.damage = dmg;
    r.thickness_strain = eps[2];
    r.failed = pr.failed;
    return r;
  }
}

}  // namespace mcdyna::solver
