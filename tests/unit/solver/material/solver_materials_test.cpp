// Integration-point material updates against closed-form answers: MAT_003 (isotropic and
// kinematic hardening, Cowper-Symonds, FS), MAT_024 (curve, failure), MAT_015 Johnson-Cook (flow
// stress, rate and thermal factors, damage) and the MAT_ADD_EROSION plastic-strain criterion.
// The point is driven in simple shear, where the return direction never changes, so radial
// return is exact and the answers are closed-form.
#include <doctest/doctest.h>

#include <cmath>
#include <variant>

#include "solver/material/constitutive.hpp"

namespace mcdyna::solver {

namespace {

struct ShearPoint {
  double s[6] = {};
  double alpha[6] = {};
  double ep = 0.0, damage = 0.0;
  bool failed = false;

  // Shear increment d (tensor component, de_xy = d) at strain rate `rate`; returns dp.
  double shear(const Material& m, double d, double rate = 0.0, double temperature = 0.0,
               double pressure = 0.0) {
    const double de[6] = {0, 0, 0, d, 0, 0};
    const PointResult r = std::visit(
        [&](const auto& model) {
          return update_deviator(m, model, PointInput{de, rate, temperature, pressure},
                                 PointState{s, m.has_back_stress() ? alpha : nullptr, ep, damage});
        },
        m.model);
    failed = failed || r.failed;
    return r.plastic_increment;
  }
  // Signed equivalent stress sqrt(3) s_xy.
  [[nodiscard]] double q() const { return std::sqrt(3.0) * s[3]; }
};

// Equivalent strain of a total shear strain (tensor) g: 2 g / sqrt(3).
double equivalent(double g) {
  return 2.0 * g / std::sqrt(3.0);
}

PlasticKinematicModel kinematic_model(double beta) {
  PlasticKinematicModel k;
  k.yield_stress = 200.0;
  k.hardening_modulus = 2.0e3;
  k.isotropic_fraction = beta;
  return k;
}

Material kinematic_material(double beta) {
  Material m;
  m.model = kinematic_model(beta);
  m.shear_modulus = 80.0e3;
  return m;
}

}  // namespace

TEST_CASE("MAT_003: linear hardening in shear follows q = sy + Ep ep exactly") {
  const Material m = kinematic_material(1.0);
  const PlasticKinematicModel& k = std::get<PlasticKinematicModel>(m.model);
  ShearPoint p;
  const double step = 1.0e-4;
  for (int i = 1; i <= 60; ++i) {
    p.shear(m, step);
    const double eq = equivalent(i * step);
    const double g = m.shear_modulus;
    if (3.0 * g * eq <= k.yield_stress) {
      CHECK(p.ep == 0.0);
      CHECK(p.q() == doctest::Approx(3.0 * g * eq).epsilon(1e-12));
    } else {
      // q = 3G (eq - ep) = sy + Ep ep
      const double ep = (3.0 * g * eq - k.yield_stress) / (3.0 * g + k.hardening_modulus);
      CHECK(p.ep == doctest::Approx(ep).epsilon(1e-10));
      CHECK(p.q() == doctest::Approx(k.yield_stress + k.hardening_modulus * ep).epsilon(1e-10));
    }
  }
  CHECK(p.ep > 0.005);  // the loading went well into the plastic range
}

TEST_CASE("MAT_003: reverse yield at -q_max (isotropic) and at q_max - 2 sy (kinematic)") {
  auto reverse_yield = [](double beta) {
    const Material m = kinematic_material(beta);
    ShearPoint p;
    for (int i = 0; i < 60; ++i)
      p.shear(m, 1.0e-4);
    const double q_max = p.q();
    for (int i = 0; i < 100000; ++i) {
      const double before = p.q();
      if (p.shear(m, -1.0e-6) > 0.0) return std::pair{q_max, before};
    }
    return std::pair{q_max, 0.0};
  };
  const auto [q_iso, rev_iso] = reverse_yield(1.0);
  CHECK(rev_iso == doctest::Approx(-q_iso).epsilon(1e-3));
  const auto [q_kin, rev_kin] = reverse_yield(0.0);
  CHECK(rev_kin == doctest::Approx(q_kin - 2.0 * 200.0).epsilon(1e-3));
}

TEST_CASE("MAT_003: Cowper-Symonds scales the yield stress, FS erodes") {
  Material m = kinematic_material(1.0);
  PlasticKinematicModel k = kinematic_model(1.0);
  k.hardening_modulus = 0.0;
  k.cowper_symonds_c = 40.0;
  k.cowper_symonds_p = 5.0;
  m.model = k;
  m.failure_strain = 0.02;
  ShearPoint p;
  const double rate = 1000.0;
  for (int i = 0; i < 10; ++i)
    p.shear(m, 1.0e-3, rate);
  // Perfectly plastic: q sits on sy (1 + (rate / C)^(1/P)).
  CHECK(p.q() == doctest::Approx(200.0 * (1.0 + std::pow(rate / 40.0, 0.2))).epsilon(1e-10));
  CHECK_FALSE(p.failed);
  for (int i = 0; i < 40 && !p.failed; ++i)
    p.shear(m, 1.0e-3, rate);
  CHECK(p.failed);
  CHECK(p.ep >= 0.02);
  CHECK(p.ep < 0.02 + equivalent(1.0e-3));  // failed on the increment that crossed FS
}

TEST_CASE("MAT_024: the flow stress follows the hardening curve, FAIL erodes") {
  Material m;
  PiecewiseLinearModel t;
  t.curve_strain = {0.0, 0.05, 0.2};
  t.curve_stress = {100.0, 150.0, 180.0};
  m.model = t;
  m.shear_modulus = 26.0e3;
  m.erosion_plastic_strain = 0.15;  // as *MAT_ADD_EROSION EPSP / MAT_024 FAIL
  ShearPoint p;
  auto curve = [&](double ep) {
    return ep <= 0.05 ? 100.0 + 1000.0 * ep : 150.0 + 200.0 * (ep - 0.05);
  };
  bool saw_both_segments = false;
  for (int i = 0; i < 400 && !p.failed; ++i) {
    p.shear(m, 5.0e-4);
    if (p.ep > 0.0) CHECK(p.q() == doctest::Approx(curve(p.ep)).epsilon(1e-9));
    saw_both_segments = saw_both_segments || p.ep > 0.06;
  }
  CHECK(saw_both_segments);
  CHECK(p.failed);
  CHECK(p.ep >= 0.15);
}

TEST_CASE("MAT_015 Johnson-Cook: flow stress with rate and thermal factors, damage sum") {
  Material m;
  JohnsonCookModel jc;
  jc.a = 324.0;
  jc.b = 114.0;
  jc.n = 0.42;
  jc.c = 0.002;
  jc.m = 1.34;
  jc.melt_temperature = 925.0;
  jc.reference_rate = 1.0;
  jc.damage = {-0.77, 1.45, -0.47, 0.0, 1.6};
  jc.damage_active = true;
  m.model = jc;
  m.shear_modulus = 26.0e3;  // MPa
  m.room_temperature = 293.0;
  ShearPoint p;
  const double rate = 1.0e4, temperature = 500.0, pressure = -100.0;
  const double ts = (temperature - 293.0) / (925.0 - 293.0);
  const double factor = (1.0 + 0.002 * std::log(rate)) * (1.0 - std::pow(ts, 1.34));
  double expected_damage = 0.0;
  for (int i = 0; i < 30 && !p.failed; ++i) {
    const double dp = p.shear(m, 1.0e-3, rate, temperature, pressure);
    if (p.ep > 0.0) {
      CHECK(p.q() ==
            doctest::Approx(factor * (324.0 + 114.0 * std::pow(p.ep, 0.42))).epsilon(1e-9));
      const double triax = -pressure / p.q();
      const double ef = (-0.77 + 1.45 * std::exp(-0.47 * triax)) * (1.0 + 1.6 * ts);
      expected_damage += dp / ef;
    }
  }
  CHECK(p.ep > 0.01);
  CHECK(p.damage == doctest::Approx(std::min(1.0, expected_damage)).epsilon(1e-9));

  // Molten (T >= TM): no deviatoric strength.
  ShearPoint hot;
  hot.shear(m, 1.0e-3, rate, 930.0);
  CHECK(hot.q() == 0.0);
}

TEST_CASE("MAT_015 Johnson-Cook: the damage sum reaching 1 erodes the point") {
  Material m;
  JohnsonCookModel jc;
  jc.a = 300.0;
  jc.b = 100.0;
  jc.n = 0.5;
  jc.damage = {0.1, 0.0, 0.0, 0.0, 0.0};  // constant failure strain 0.1
  jc.damage_active = true;
  m.model = jc;
  m.shear_modulus = 26.0e3;
  ShearPoint p;
  for (int i = 0; i < 200 && !p.failed; ++i)
    p.shear(m, 1.0e-3);
  CHECK(p.failed);
  CHECK(p.damage == 1.0);
  CHECK(p.ep == doctest::Approx(0.1).epsilon(0.02));
}

}  // namespace mcdyna::solver
