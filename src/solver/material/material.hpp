#pragma once
/// Compiled constitutive data of one deformable material (+ its EOS and erosion criteria) and the
/// integration-point state arrays. Stress is split as the hydrocodes do: each integration point
/// keeps its deviatoric stress; the pressure is an element quantity, from the EOS or from the
/// hypoelastic bulk response, because both element formulations share one volumetric strain rate
/// per element.
#include <Eigen/Core>

#include <array>
#include <variant>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::solver {

/// What a point does below the pressure cutoff (MAT_015 SPALL; *MAT_NULL holds): SPALL 1 holds
/// the pressure at the cutoff; SPALL 2 and 3 release it and the deviator (no tension once spalled).
enum class Spall { hold_cutoff, no_tension };

enum class EosModel { none, linear_polynomial, gruneisen };

/// *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN: p = a(mu) + b(mu) * E, affine in the internal
/// energy per initial volume E, which lets the energy equation be solved exactly each step.
struct EosParams {
  EosModel kind = EosModel::none;
  std::array<double, 7> c{};  ///< linear polynomial C0..C6
  double sound_speed = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0, gamma0 = 0.0, volume_correction = 0.0;
  double initial_energy = 0.0;  ///< E0, energy per initial volume
};

// The deviatoric models, one type each: a block visits its material's model once and runs its
// points with that type (design.md §7), never switching per point.

/// MAT_001: the deviator is 2 G times the deviatoric strain, nothing more.
struct ElasticModel {};

/// MAT_003: mixed hardening (BETA) with Cowper-Symonds scaling of the yield stress.
struct PlasticKinematicModel {
  double yield_stress = 0.0;
  double hardening_modulus = 0.0;   ///< Ep = ETAN * E / (E - ETAN)
  double isotropic_fraction = 1.0;  ///< BETA
  double cowper_symonds_c = 0.0, cowper_symonds_p = 0.0;
};

/// MAT_024: isotropic hardening from a table of flow stress against plastic strain.
struct PiecewiseLinearModel {
  double cowper_symonds_c = 0.0, cowper_symonds_p = 0.0;
  std::vector<double> curve_strain, curve_stress;  ///< hardening table (plastic strain)
};

/// MAT_015: (A + B ep^N)(1 + C ln rate*)(1 - T*^M), with the JC damage sum when active.
struct JohnsonCookModel {
  double a = 0.0, b = 0.0, n = 1.0, c = 0.0, m = 1.0;
  double melt_temperature = 0.0;
  double reference_rate = 1.0;
  std::array<double, 5> damage{};      ///< D1..D5
  bool damage_active = false;          ///< any Di != 0 and EROD == 0
  double min_failure_strain = 1.0e-6;  ///< EFMIN
};

using DeviatoricModel =
    std::variant<ElasticModel, PlasticKinematicModel, PiecewiseLinearModel, JohnsonCookModel>;

struct Material {
  model::Id id = 0;
  DeviatoricModel model = ElasticModel{};
  double density = 0.0;        ///< initial, mass/length^3
  double shear_modulus = 0.0;  ///< G, stress
  double bulk_modulus = 0.0;   ///< K for the wave speed (and hypoelastic pressure without EOS)

  // Adiabatic heating (MAT_015's CP and TR; CP = 0: none) and the pressure cutoff (MAT_015's PC
  // and SPALL; PC = 0: none): the volumetric update of every point reads them.
  double room_temperature = 0.0;
  double specific_heat = 0.0;
  double pressure_cutoff = 0.0;
  Spall spall = Spall::no_tension;

  double failure_strain = 0.0;  ///< MAT_003 FS / MAT_024 FAIL: erode at this plastic strain
  /// *MAT_SPOTWELD: TFAIL (0: none) and NRR NRS NRT MRR MSS MTT (0: term not considered), read
  /// by the spot-weld beam on its resultants.
  double failure_time = 0.0;
  std::array<double, 6> failure_resultants{};
  EosParams eos;
  double erosion_plastic_strain = 0.0;  ///< *MAT_ADD_EROSION EPSP (0 none)

  [[nodiscard]] bool has_back_stress() const {
    const auto* k = std::get_if<PlasticKinematicModel>(&model);
    return k != nullptr && k->isotropic_fraction < 1.0;
  }
  /// The flow stress at zero plastic strain and the reference rate (MAT_003 SIGY, MAT_024's
  /// first table point, MAT_015 A); 0 for an elastic material.
  [[nodiscard]] double initial_yield() const {
    if (const auto* k = std::get_if<PlasticKinematicModel>(&model)) return k->yield_stress;
    if (const auto* p = std::get_if<PiecewiseLinearModel>(&model))
      return p->curve_stress.empty() ? 0.0 : p->curve_stress.front();
    if (const auto* j = std::get_if<JohnsonCookModel>(&model)) return j->a;
    return 0.0;
  }
  /// The temperature points start at: TR for Johnson-Cook, else 0.
  [[nodiscard]] double initial_temperature() const {
    return std::holds_alternative<JohnsonCookModel>(model) ? room_temperature : 0.0;
  }
};

/// Integration-point state. Columns are points; rows of the 6-vectors are xx yy zz xy yz zx.
struct MaterialPoints {
  Eigen::Matrix<double, 6, Eigen::Dynamic> deviator;     ///< deviatoric Cauchy stress
  Eigen::Matrix<double, 6, Eigen::Dynamic> back_stress;  ///< MAT_003 kinematic part, or empty
  std::vector<double> plastic_strain;                    ///< effective plastic strain
  std::vector<double> damage;                            ///< JC damage sum (0..1)
};

}  // namespace mcdyna::solver
