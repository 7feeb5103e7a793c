// Deck materials (+ the part's EOS and *MAT_ADD_EROSION) -> solver Material.
#include "solver/material/compile_material.hpp"

#include <algorithm>
#include <utility>

namespace mcdyna::solver::detail {

namespace {

void elastic_moduli(Material& out, double e, double nu) {
  out.shear_modulus = e / (2.0 * (1.0 + nu));
  out.bulk_modulus = e / (3.0 * (1.0 - 2.0 * nu));
}

EosParams compile_eos(const model::Eos& e) {
  EosParams p;
  if (e.kind == model::EosKind::gruneisen) {
    p.kind = EosModel::gruneisen;
    p.sound_speed = e.sound_speed;
    p.s1 = e.s[0];
    p.s2 = e.s[1];
    p.s3 = e.s[2];
    p.gamma0 = e.gamma0;
    p.volume_correction = e.volume_correction;
  } else {
    p.kind = EosModel::linear_polynomial;
    p.c = e.c;
  }
  p.initial_energy = e.initial_energy;
  return p;
}

// MAT_024 hardening: LCSS curve (plastic strain -> yield stress), else the EPS/ES pairs, else
// bilinear from SIGY and ETAN.
void piecewise_hardening(const model::ModelDatabase& m, const model::Material& mat,
                         PiecewiseLinearModel& out, core::Diagnostics& d) {
  const auto& p = mat.piecewise_linear;
  if (p.stress_strain_curve != 0) {
    const model::Curve* curve = m.curve(p.stress_strain_curve);
    if (curve == nullptr) {
      d.error(mat.loc,
              "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: LCSS {} is not a *DEFINE_CURVE "
              "(tables are not supported)",
              mat.id, p.stress_strain_curve);
      return;
    }
    for (const auto& [a, o] : curve->points) {
      out.curve_strain.push_back(curve->abscissa_scale * a + curve->abscissa_offset);
      out.curve_stress.push_back(curve->ordinate_scale * o + curve->ordinate_offset);
    }
  } else if (!p.points.empty()) {
    for (const auto& [eps, sig] : p.points) {
      out.curve_strain.push_back(eps);
      out.curve_stress.push_back(sig);
    }
  } else {
    const double ep = p.tangent_modulus * p.youngs_modulus / (p.youngs_modulus - p.tangent_modulus);
    out.curve_strain = {0.0, 1.0};
    out.curve_stress = {p.yield_stress, p.yield_stress + ep};
  }
  if (out.curve_strain.size() < 1 ||
      !std::is_sorted(out.curve_strain.begin(), out.curve_strain.end())) {
    d.error(mat.loc,
            "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: the hardening curve needs increasing "
            "plastic strains",
            mat.id);
  }
  if (p.strain_rate_curve != 0) {
    d.error(mat.loc,
            "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: LCSR (strain-rate curve) is not "
            "supported; use SRC/SRP (Cowper-Symonds)",
            mat.id);
  }
}

void johnson_cook(const model::Material& mat, Material& out, core::Diagnostics& d) {
  const auto& j = mat.johnson_cook;
  JohnsonCookModel jc;
  jc.a = j.a;
  jc.b = j.b;
  jc.n = j.n;
  jc.c = j.c;
  jc.m = j.m;
  jc.melt_temperature = j.melt_temperature;
  jc.reference_rate = j.reference_strain_rate > 0.0 ? j.reference_strain_rate : 1.0;
  jc.damage = j.damage;
  jc.min_failure_strain = j.min_failure_strain;
  const bool any = std::any_of(j.damage.begin(), j.damage.end(), [](double x) { return x != 0.0; });
  jc.damage_active = any && j.erode_flag == 0.0;
  out.model = jc;
  out.shear_modulus = j.shear_modulus;
  out.bulk_modulus = 0.0;  // the EOS gives the pressure
  out.room_temperature = j.room_temperature;
  out.specific_heat = j.specific_heat;
  out.pressure_cutoff = j.pressure_cutoff;
  out.spall = j.spall_type == 1.0 ? Spall::hold_cutoff : Spall::no_tension;
  // The return mapping relies on a flow stress that does not fall with plastic strain.
  if (j.b < 0.0 || j.n <= 0.0) {
    d.error(mat.loc, "*MAT_JOHNSON_COOK {}: B = {} and N = {} must give hardening (B >= 0, N > 0)",
            mat.id, j.b, j.n);
  }
  if (j.viscoplastic != 0.0) {
    d.warning(mat.loc,
              "*MAT_JOHNSON_COOK {}: VP = {} (viscoplastic) runs as VP = 0 (scaled yield "
              "stress)",
              mat.id, j.viscoplastic);
  }
}

}  // namespace

Material compile_material(const model::ModelDatabase& m, const model::Part& part,
                          core::Diagnostics& d) {
  const model::Material& mat = *m.material(part.material);
  Material out;
  out.id = mat.id;
  out.density = mat.density;
  switch (mat.kind) {
    case model::MaterialKind::elastic:
      out.model = ElasticModel{};
      elastic_moduli(out, mat.elastic.youngs_modulus, mat.elastic.poisson_ratio);
      break;
    case model::MaterialKind::plastic_kinematic: {
      const auto& p = mat.plastic_kinematic;
      PlasticKinematicModel k;
      k.yield_stress = p.yield_stress;
      k.hardening_modulus =
          p.tangent_modulus * p.youngs_modulus / (p.youngs_modulus - p.tangent_modulus);
      k.isotropic_fraction = p.hardening_mix;
      k.cowper_symonds_c = p.cowper_symonds_c;
      k.cowper_symonds_p = p.cowper_symonds_p;
      out.model = k;
      elastic_moduli(out, p.youngs_modulus, p.poisson_ratio);
      out.failure_strain = p.failure_strain;
      if (p.viscoplastic != 0.0) {
        d.warning(mat.loc,
                  "*MAT_PLASTIC_KINEMATIC {}: VP = {} runs as VP = 0 (scaled yield "
                  "stress)",
                  mat.id, p.viscoplastic);
      }
      break;
    }
    case model::MaterialKind::piecewise_linear: {
      const auto& p = mat.piecewise_linear;
      PiecewiseLinearModel t;
      t.cowper_symonds_c = p.cowper_symonds_c;
      t.cowper_symonds_p = p.cowper_symonds_p;
      piecewise_hardening(m, mat, t, d);
      out.model = std::move(t);
      elastic_moduli(out, p.youngs_modulus, p.poisson_ratio);
      out.failure_strain =
          p.failure_strain < 1.0e20 && p.failure_strain > 0.0 ? p.failure_strain : 0.0;
      break;
    }
    case model::MaterialKind::johnson_cook:
      johnson_cook(mat, out, d);
      break;
    case model::MaterialKind::null_material:
      // No deviatoric strength (the elastic update with G = 0 leaves the deviator at zero); the
      // EOS gives the pressure, cut at PC in tension.
      out.model = ElasticModel{};
      out.shear_modulus = 0.0;
      out.bulk_modulus = 0.0;
      out.pressure_cutoff = mat.null_material.pressure_cutoff;
      out.spall = Spall::hold_cutoff;
      break;
    case model::MaterialKind::spotweld: {
      // Isotropic hardening with EH the plastic modulus (MAT_003 with BETA 1 and no rate); EFAIL
      // erodes a weld whose every fibre reached it, unless the resultants decide.
      const auto& w = mat.spotweld;
      PlasticKinematicModel k;
      k.yield_stress = w.yield_stress;
      k.hardening_modulus = w.hardening_modulus;
      k.isotropic_fraction = 1.0;
      out.model = k;
      elastic_moduli(out, w.youngs_modulus, w.poisson_ratio);
      out.failure_time = w.failure_time;
      out.failure_resultants = w.failure_resultants;
      const bool by_resultants =
          std::any_of(w.failure_resultants.begin(), w.failure_resultants.end(),
                      [](double f) { return f > 0.0; });
      out.failure_strain = by_resultants ? 0.0 : w.failure_strain;
      break;
    }
    case model::MaterialKind::rigid:
      break;  // rigid parts become rigid bodies, never elements
    case model::MaterialKind::spring_elastic:
    case model::MaterialKind::damper_viscous:
    case model::MaterialKind::spring_nonlinear_elastic:
      break;  // discrete elements' (discrete/), never reached: their parts have no solids
  }
  if (part.eos != 0) {
    const auto e = m.index.equations_of_state.find(part.eos);
    if (e != model::IdIndex::kNone) {
      out.eos = compile_eos(m.equations_of_state[static_cast<std::size_t>(e)]);
    }
  }
  for (const model::Erosion& er : m.erosions) {
    if (er.material != mat.id) continue;
    out.erosion_plastic_strain = er.effective_plastic_strain;
    const bool other =
        er.max_pressure != 0.0 || er.min_principal_strain != 0.0 || er.volumetric_strain != 0.0 ||
        er.min_pressure != 0.0 || er.max_principal_stress != 0.0 || er.equivalent_stress != 0.0 ||
        er.max_principal_strain != 0.0 || er.shear_strain != 0.0 || er.failure_time != 0.0;
    if (other) {
      d.error(er.loc,
              "*MAT_ADD_EROSION for material {}: only EPSP (effective plastic strain) is "
              "supported; remove the other criteria",
              mat.id);
    }
  }
  return out;
}

}  // namespace mcdyna::solver::detail
