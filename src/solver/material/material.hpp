#pragma once
/// Compiled constitutive data of one deformable material (+ its EOS and erosion criteria) and the
/// integration-point state arrays. Stress is split as the hydrocodes do: each integration point
/// keeps its deviatoric stress; the pressure is an element quantity, from the EOS or from the
/// hypoelastic bulk response, because both element formulations share one volumetric strain rate
/// per element.
#include <Eigen/Core>

#include <array>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::solver {

enum class MaterialModel { elastic, plastic_kinematic, piecewise_linear, johnson_cook };
enum class EosModel { none, linear_polynomial, gruneisen };

/// *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN: p = a(mu) + b(mu) * E, affine in the internal
/// energy per initial volume E, which lets the energy equation be solved exactly each step.
struct EosParams {
  EosModel kind = EosModel::none;
  std::array<double, 7> c{};  ///< linear polynomial C0..C6
  double sound_speed = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0, gamma0 = 0.0, volume_correction = 0.0;
  double initial_energy = 0.0;  ///< E0, energy per initial volume
};

struct Material {
  model::Id id = 0;
  MaterialModel model = MaterialModel::elastic;
  double density = 0.0;        ///< initial, mass/length^3
  double shear_modulus = 0.0;  ///< G, stress
  double bulk_modulus = 0.0;   ///< K for the wave speed (and hypoelastic pressure without EOS)

  // MAT_003 / MAT_024
  double yield_stress = 0.0;
  double hardening_modulus = 0.0;   ///< Ep = ETAN * E / (E - ETAN)
  double isotropic_fraction = 1.0;  ///< BETA (MAT_003); 1 for MAT_024
  double cowper_symonds_c = 0.0, cowper_symonds_p = 0.0;
  double failure_strain = 0.0;  ///< FS / FAIL: erode at this plastic strain (0 none)
  std::vector<double> curve_strain, curve_stress;  ///< MAT_024 hardening table (plastic strain)

  // MAT_015
  double jc_a = 0.0, jc_b = 0.0, jc_n = 1.0, jc_c = 0.0, jc_m = 1.0;
  double melt_temperature = 0.0, room_temperature = 0.0, reference_rate = 1.0;
  double specific_heat = 0.0;    ///< CP; 0: no adiabatic heating
  double pressure_cutoff = 0.0;  ///< PC (< 0); 0: none
  int spall = 2;
  std::array<double, 5> damage{};      ///< D1..D5
  bool damage_active = false;          ///< any Di != 0 and EROD == 0
  double min_failure_strain = 1.0e-6;  ///< EFMIN

  EosParams eos;
  double erosion_plastic_strain = 0.0;  ///< *MAT_ADD_EROSION EPSP (0 none)

  [[nodiscard]] bool has_back_stress() const {
    return model == MaterialModel::plastic_kinematic && isotropic_fraction < 1.0;
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
