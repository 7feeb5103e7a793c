// *MAT_ELASTIC, *MAT_PLASTIC_KINEMATIC, *MAT_JOHNSON_COOK, *MAT_RIGID,
// *MAT_PIECEWISE_LINEAR_PLASTICITY, *MAT_ADD_EROSION. Physical sanity that needs several
// fields (TM > TR, EPSO with C, …) is checked here, where the fields' locations are known.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

model::Material start(const KeywordRecord& r, const Row& c1, model::MaterialKind kind) {
  model::Material mat;
  mat.id = c1.integer("MID");
  mat.title = title_of(r);
  mat.kind = kind;
  mat.keyword = keyword_after(r, "MAT_");
  mat.density = c1.real("RO");
  mat.loc = c1.loc();
  return mat;
}

void require_positive(const KeywordRecord& r, const Row& row, const char* field, double value,
                      const char* what) {
  if (!(value > 0.0)) {
    r.diags().error(row.loc(field), "{} {}: {} = {} must be > 0 ({})", r.display_name(),
                    row.integer("MID"), field, value, what);
  }
}

void check_poisson(const KeywordRecord& r, const Row& row) {
  const double pr = row.real("PR");
  if (!(pr > -1.0 && pr < 0.5)) {
    r.diags().error(row.loc("PR"), "{} {}: Poisson's ratio PR = {} must lie in (-1, 0.5)",
                    r.display_name(), row.integer("MID"), pr);
  }
}

}  // namespace

void mat_elastic(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Material mat = start(r, c1, model::MaterialKind::elastic);
  mat.elastic.youngs_modulus = c1.real("E");
  mat.elastic.poisson_ratio = c1.real("PR");
  if (mat.elastic.youngs_modulus < 0.0) {
    r.diags().error(c1.loc("E"), "*MAT_ELASTIC {}: E < 0 (modulus from a curve) is not supported",
                    mat.id);
  } else {
    require_positive(r, c1, "E", mat.elastic.youngs_modulus, "Young's modulus");
  }
  check_poisson(r, c1);
  m.materials.push_back(std::move(mat));
}

void mat_null(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Material mat = start(r, c1, model::MaterialKind::null_material);
  mat.null_material.pressure_cutoff = c1.real("PC");
  mat.null_material.youngs_modulus = c1.real("YM");
  mat.null_material.poisson_ratio = c1.real("PR");
  m.materials.push_back(std::move(mat));
}

void mat_spotweld(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Material mat = start(r, c1, model::MaterialKind::spotweld);
  auto& w = mat.spotweld;
  w.youngs_modulus = c1.real("E");
  w.poisson_ratio = c1.real("PR");
  w.yield_stress = c1.real("SIGY");
  w.hardening_modulus = c1.real("EH");
  w.mass_scaling_step = c1.real("DT");
  w.failure_time = c1.real("TFAIL");
  w.failure_strain = c2.real("EFAIL");
  const int nrr = c2.index("NRR");
  for (int k = 0; k < 6; ++k)
    w.failure_resultants[static_cast<std::size_t>(k)] = c2.real(nrr + k);
  w.filter_vectors = c2.real("NF");
  check_poisson(r, c1);
  if (w.mass_scaling_step > 0.0) {
    r.diags().warning(c1.loc("DT"),
                      "*MAT_SPOTWELD {}: DT = {:g}: the welds' mass is not scaled; their own "
                      "step enters the run's",
                      mat.id, w.mass_scaling_step);
  }
  if (w.filter_vectors > 0.0) {
    r.diags().warning(c2.loc("NF"),
                      "*MAT_SPOTWELD {}: NF = {:g}: the resultants are not filtered (failure and "
                      "output read them as they are)",
                      mat.id, w.filter_vectors);
  }
  m.materials.push_back(std::move(mat));
}

void mat_plastic_kinematic(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Material mat = start(r, c1, model::MaterialKind::plastic_kinematic);
  auto& p = mat.plastic_kinematic;
  p.youngs_modulus = c1.real("E");
  p.poisson_ratio = c1.real("PR");
  p.yield_stress = c1.real("SIGY");
  p.tangent_modulus = c1.real("ETAN");
  p.hardening_mix = c1.real("BETA");
  p.cowper_symonds_c = c2.real("SRC");
  p.cowper_symonds_p = c2.real("SRP");
  p.failure_strain = c2.real("FS");
  p.viscoplastic = c2.real("VP");
  check_poisson(r, c1);
  if (p.tangent_modulus >= p.youngs_modulus) {
    r.diags().error(c1.loc("ETAN"), "*MAT_PLASTIC_KINEMATIC {}: ETAN = {} must be below E = {}",
                    mat.id, p.tangent_modulus, p.youngs_modulus);
  }
  if (p.cowper_symonds_c > 0.0 && p.cowper_symonds_p <= 0.0) {
    r.diags().error(c2.loc("SRP"), "*MAT_PLASTIC_KINEMATIC {}: SRC > 0 needs SRP > 0", mat.id);
  }
  m.materials.push_back(std::move(mat));
}

void mat_johnson_cook(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  const Row& c4 = r.card("4");
  model::Material mat = start(r, c1, model::MaterialKind::johnson_cook);
  auto& jc = mat.johnson_cook;
  jc.shear_modulus = c1.real("G");
  jc.youngs_modulus = c1.real("E");
  jc.poisson_ratio = c1.real("PR");
  jc.min_shell_time_step = c1.real("DTF");
  jc.viscoplastic = c1.real("VP");
  jc.rate_option = static_cast<int>(c1.integer("RATEOP"));
  jc.a = c2.real("A");
  jc.b = c2.real("B");
  jc.n = c2.real("N");
  jc.c = c2.real("C");
  jc.m = c2.real("M");
  jc.melt_temperature = c2.real("TM");
  jc.room_temperature = c2.real("TR");
  jc.reference_strain_rate = c2.real("EPSO");
  jc.specific_heat = c3.real("CP");
  jc.pressure_cutoff = c3.real("PC");
  jc.spall_type = c3.real("SPALL");
  jc.iterate_plasticity = static_cast<int>(c3.integer("IT"));
  jc.damage = {c3.real("D1"), c3.real("D2"), c3.real("D3"), c3.real("D4"), c4.real("D5")};
  jc.c2 = c4.real("C2");
  jc.erode_flag = c4.real("EROD");
  jc.min_failure_strain = c4.real("EFMIN");
  jc.damage_model = static_cast<int>(c4.integer("DMODEL"));
  const bool thermal = jc.m != 0.0 || !c2.blank("TM");
  if (thermal && !(jc.melt_temperature > jc.room_temperature)) {
    r.diags().error(c2.loc("TM"),
                    "*MAT_JOHNSON_COOK {}: melt temperature TM = {} must exceed "
                    "room temperature TR = {}",
                    mat.id, jc.melt_temperature, jc.room_temperature);
  }
  if (jc.c != 0.0 && !(jc.reference_strain_rate > 0.0)) {
    r.diags().error(c2.loc("EPSO"),
                    "*MAT_JOHNSON_COOK {}: C = {} needs a reference strain rate "
                    "EPSO > 0 in the deck's time unit",
                    mat.id, jc.c);
  }
  if (jc.a < 0.0) {
    r.diags().error(c2.loc("A"),
                    "*MAT_JOHNSON_COOK {}: A < 0 (strain-hardening curve) is not "
                    "supported",
                    mat.id);
  }
  if (jc.rate_option != 0) {
    r.diags().error(c1.loc("RATEOP"),
                    "*MAT_JOHNSON_COOK {}: RATEOP = {} is not supported (only "
                    "0, the log-linear Johnson-Cook rate term)",
                    mat.id, jc.rate_option);
  }
  if (jc.damage_model != 0) {
    r.diags().error(c4.loc("DMODEL"),
                    "*MAT_JOHNSON_COOK {}: DMODEL = {} is not supported (only 0, "
                    "Johnson-Cook damage)",
                    mat.id, jc.damage_model);
  }
  m.materials.push_back(std::move(mat));
}

void mat_rigid(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  model::Material mat = start(r, c1, model::MaterialKind::rigid);
  auto& rb = mat.rigid;
  rb.youngs_modulus = c1.real("E");
  rb.poisson_ratio = c1.real("PR");
  rb.constraint_option = static_cast<int>(c2.integer("CMO"));
  rb.translation_constraint = static_cast<int>(c2.integer("CON1"));
  rb.rotation_constraint = static_cast<int>(c2.integer("CON2"));
  rb.constraint_node = c2.integer("SPCNID");
  rb.constraint_point = {c2.real("XSPC"), c2.real("YSPC"), c2.real("ZSPC")};
  rb.local_output = static_cast<int>(c3.integer("BNDLCO"));
  check_poisson(r, c1);
  if (rb.constraint_option > 0) {
    for (const char* f : {"CON1", "CON2"}) {
      const auto code = c2.integer(f);
      if (code < 0 || code > 7) {
        r.diags().error(c2.loc(f),
                        "*MAT_RIGID {}: {} = {} must be a constraint code 0..7 when "
                        "CMO > 0",
                        mat.id, f, code);
      }
    }
  } else if (rb.constraint_option < 0) {
    r.diags().error(c2.loc("CMO"),
                    "*MAT_RIGID {}: CMO < 0 (local SPC constraints) is not "
                    "supported; use CMO = 1 with global codes",
                    mat.id);
  }
  m.materials.push_back(std::move(mat));
}

void mat_piecewise_linear_plasticity(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  const Row& c4 = r.card("4");
  model::Material mat = start(r, c1, model::MaterialKind::piecewise_linear);
  auto& p = mat.piecewise_linear;
  p.youngs_modulus = c1.real("E");
  p.poisson_ratio = c1.real("PR");
  p.yield_stress = c1.real("SIGY");
  p.tangent_modulus = c1.real("ETAN");
  p.failure_strain = c1.real("FAIL") == 0.0 ? 1.0e21 : c1.real("FAIL");
  p.min_time_step_delete = c1.real("TDEL");
  p.cowper_symonds_c = c2.real("C");
  p.cowper_symonds_p = c2.real("P");
  p.stress_strain_curve = c2.integer("LCSS");
  p.strain_rate_curve = c2.integer("LCSR");
  p.viscoplastic = c2.real("VP");
  check_poisson(r, c1);
  // EPS/ES pairs up to the last non-zero stress: decks pad unused slots with zeros, and all-zero
  // rows mean "use SIGY/ETAN".
  const int e1 = c3.index("EPS1"), s1 = c4.index("ES1");
  int used = 0;
  for (int k = 0; k < 8; ++k) {
    if (c4.real(s1 + k) != 0.0) used = k + 1;
  }
  for (int k = 0; k < used; ++k)
    p.points.emplace_back(c3.real(e1 + k), c4.real(s1 + k));
  for (std::size_t k = 1; k < p.points.size(); ++k) {
    if (p.points[k].first <= p.points[k - 1].first) {
      r.diags().error(c3.loc(e1 + static_cast<int>(k)),
                      "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: "
                      "EPS values must increase",
                      mat.id);
      break;
    }
  }
  if (p.stress_strain_curve == 0 && p.points.empty() && p.yield_stress <= 0.0) {
    r.diags().error(c1.loc("SIGY"),
                    "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: no hardening given "
                    "(SIGY, EPS/ES points or LCSS)",
                    mat.id);
  }
  if (p.failure_strain < 0.0) {
    r.diags().error(c1.loc("FAIL"),
                    "*MAT_PIECEWISE_LINEAR_PLASTICITY {}: FAIL < 0 (user failure "
                    "subroutine) is not supported",
                    mat.id);
  }
  m.materials.push_back(std::move(mat));
}

void mat_add_erosion(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Erosion e;
  e.material = c1.integer("MID");
  e.exclusion = c1.real("EXCL");
  e.max_pressure = c1.real("MXPRES");
  e.min_principal_strain = c1.real("MNEPS");
  e.effective_plastic_strain = c1.real("EFFEPS");
  e.volumetric_strain = c1.real("VOLEPS");
  e.failed_points = c1.real("NUMFIP");
  e.conditions_to_fail = c1.real("NCS");
  e.min_pressure = c2.real("MNPRES");
  e.max_principal_stress = c2.real("SIGP1");
  e.equivalent_stress = c2.real("SIGVM");
  e.max_principal_strain = c2.real("MXEPS");
  e.shear_strain = c2.real("EPSSH");
  e.failure_time = c2.real("FAILTM");
  e.loc = c1.loc();
  m.erosions.push_back(e);
}

}  // namespace mcdyna::deck::builders
