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

/// Which stress components a structural point holds at zero, and so which strains are unknown.
enum class StressConstraint {
  /// Shell layer: sigma_zz = 0 with the thickness strain eps_zz unknown.
  plane_stress,
  /// Beam fibre: sigma_yy = sigma_zz = sigma_yz = 0 with eps_yy = eps_zz unknown (one unknown:
  /// under an isotropic model the two lateral stresses stay equal when their strains are, and
  /// sigma_yz stays 0 when eps_yz is).
  uniaxial,
};

/// Updates a point under the strain increments `eps_in` over dt (tensor shears) keeping the
/// components `constraint` names at zero; the unknown strains in eps_in are ignored. Elastic:
/// exact in one step. Plastic: the 3D update of the material's own model with the unknown strain
/// found by secant iteration (sigma is monotone in it).
template <class Model>
PlaneStressResult constrained_update(const Material& m, const Model& model, const double* eps_in,
                                     double dt, double temperature, int max_iterations,
                                     ShellPointState st, StressConstraint constraint) {
  PlaneStressResult r;
  const double g = m.shear_modulus, k = m.bulk_modulus;
  const double lambda = k - 2.0 * g / 3.0;
  const bool beam = constraint == StressConstraint::uniaxial;
  double eps[6] = {eps_in[0], beam ? 0.0 : eps_in[1], 0.0,
                   eps_in[3], beam ? 0.0 : eps_in[4], eps_in[5]};
  // The free strain(s) and the slope of the held stress in them: shell, lambda tr + 2 G e_zz;
  // beam, lambda tr + 2 G e_yy with e_yy = e_zz.
  const double tangent = beam ? 2.0 * lambda + 2.0 * g : lambda + 2.0 * g;
  auto set_free = [&](double x) {
    eps[2] = x;
    if (beam) eps[1] = x;
  };
  set_free(-lambda / tangent * (eps[0] + (beam ? 0.0 : eps[1])));  // the elastic answer
  auto clear_held = [&] {
    st.stress[2] = 0.0;
    if (beam) st.stress[1] = st.stress[4] = 0.0;
  };
  if constexpr (std::is_same_v<Model, ElasticModel>) {
    const double tr = eps[0] + eps[1] + eps[2];
    for (int i = 0; i < 6; ++i)
      st.stress[i] += 2.0 * g * eps[i] + (i < 3 ? lambda * tr : 0.0);
    clear_held();
    r.thickness_strain = eps[2];
    return r;
  } else {
    double out[6], alpha[6], ep = 0.0, dmg = 0.0;
    const int held = beam ? 1 : 2;  // sigma_yy (= sigma_zz) or sigma_zz
    auto held_stress = [&](double x, PointResult& pr) {
      set_free(x);
      const double mean = (eps[0] + eps[1] + eps[2]) / 3.0;
      const double dev[6] = {eps[0] - mean, eps[1] - mean, eps[2] - mean, eps[3], eps[4], eps[5]};
      const double rate = dt > 0.0 ? std::sqrt(2.0 / 3.0 * contract(dev, dev)) / dt : 0.0;
      pr = detail::trial_update(m, model, eps, rate, temperature, st.stress, st.back_stress,
                                st.plastic_strain, st.damage, out, alpha, ep, dmg);
      return out[held];
    };
    PointResult pr;
    double x0 = eps[2];
    double f0 = held_stress(x0, pr);
    // The stresses the point carries: in-plane (shell) or axial and transverse shear (beam).
    const double scale =
        std::max({std::abs(out[0]), std::abs(out[beam ? 5 : 1]), std::abs(out[3]), 1e-300});
    if (std::abs(f0) > 1e-10 * scale) {
      // Second guess from the elastic tangent, then secant steps.
      double x1 = x0 - f0 / tangent;
      double f1 = held_stress(x1, pr);
      for (int it = 0; it < max_iterations && std::abs(f1) > 1e-10 * scale && f1 != f0; ++it) {
        const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = held_stress(x1, pr);
      }
    }
    std::copy(out, out + 6, st.stress);
    clear_held();
    if (st.back_stress) std::copy(alpha, alpha + 6, st.back_stress);
    r.plastic_increment = ep - st.plastic_strain;
    st.plastic_strain = ep;
    st.damage = dmg;
    r.thickness_strain = eps[2];
    r.failed = pr.failed;
    return r;
  }
}

/// Updates a shell layer point under the in-plane and transverse-shear strain increments `eps`
/// (xx yy - xy yz zx, tensor shears; eps[2] is ignored) over dt, keeping sigma_zz = 0.
template <class Model>
PlaneStressResult plane_stress_update(const Material& m, const Model& model, const double* eps_in,
                                      double dt, double temperature, int max_iterations,
                                      ShellPointState st) {
  return constrained_update(m, model, eps_in, dt, temperature, max_iterations, st,
                            StressConstraint::plane_stress);
}

}  // namespace mcdyna::solver
