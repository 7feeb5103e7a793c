// *CONTROL_TERMINATION, _TIMESTEP, _HOURGLASS, _CONTACT, _SOLID, _SHELL, _ENERGY,
// _BULK_VISCOSITY, _ACCURACY.
#include <fmt/format.h>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void control_termination(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::Termination t;
  t.end_time = c.real("ENDTIM");
  t.end_cycle = static_cast<int>(c.integer("ENDCYC"));
  t.min_step_factor = c.real("DTMIN");
  t.energy_change_percent = c.real("ENDENG");
  t.mass_change_percent = c.real("ENDMAS");
  t.no_solution = static_cast<int>(c.integer("NOSOL"));
  t.loc = c.loc();
  set_once(m.controls.termination, t, r);
}

void control_timestep(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::TimeStepControl t;
  t.initial_step = c.real("DTINIT");
  t.scale_factor = c.real("TSSFAC");
  t.shell_length_option = static_cast<int>(c.integer("ISDO"));
  t.shell_min_step = c.real("TSLIMT");
  t.mass_scaling_step = c.real("DT2MS");
  t.max_step_curve = c.integer("LCTM");
  t.erode = static_cast<int>(c.integer("ERODE"));
  t.mass_scaling_first_step = static_cast<int>(c.integer("MS1ST"));
  t.loc = c.loc();
  if (t.scale_factor < 0.0) {
    r.diags().error(c.loc("TSSFAC"),
                    "*CONTROL_TIMESTEP: TSSFAC < 0 (scale factor from a curve) "
                    "is not supported");
  } else if (t.scale_factor > 1.0) {
    r.diags().warning(c.loc("TSSFAC"),
                      "*CONTROL_TIMESTEP: TSSFAC = {} exceeds 1; the explicit "
                      "step will exceed the stable step",
                      t.scale_factor);
  }
  set_once(m.controls.time_step, t, r);
}

void control_hourglass(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  set_once(m.controls.hourglass,
           model::HourglassControl{static_cast<int>(c.integer("IHQ")), c.real("QH"), c.loc()}, r);
}

void control_contact(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  const Row& c4 = r.card("4");
  model::ContactControl c;
  c.penalty_scale = c1.real("SLSFAC");
  c.rigid_wall_penalty = c1.real("RWPNAL");
  c.initial_penetration_check = static_cast<int>(c1.integer("ISLCHK"));
  c.shell_thickness = static_cast<int>(c1.integer("SHLTHK"));
  c.penalty_option = static_cast<int>(c1.integer("PENOPT"));
  c.thickness_change = static_cast<int>(c1.integer("THKCHG"));
  c.orientation = static_cast<int>(c1.integer("ORIEN"));
  c.eroding_mass = static_cast<int>(c1.integer("ENMASS"));
  c.bucket_interval = static_cast<int>(c2.integer("NSBCS"));
  c.max_penetration_factor = c2.real("XPENE");
  c.single_surface_thickness = static_cast<int>(c2.integer("SSTHK"));
  c.default_static_friction = c3.real("SFRIC");
  c.default_dynamic_friction = c3.real("DFRIC");
  c.ignore_penetration = static_cast<int>(c4.integer("IGNORE"));
  c.friction_energy = static_cast<int>(c4.integer("FRCENG"));
  c.loc = c1.loc();
  set_once(m.controls.contact, c, r);
}

void damping_global(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::GlobalDamping g;
  g.curve = c.integer("LCID");
  g.value = c.real("VALDMP");
  const int first = c.index("STX");
  bool any = false;
  for (int k = 0; k < 6; ++k) {
    g.scale[static_cast<std::size_t>(k)] = c.real(first + k);
    any = any || g.scale[static_cast<std::size_t>(k)] != 0.0;
  }
  if (!any) g.scale.fill(1.0);  // all six zero: every direction damped
  g.loc = c.loc();
  g.curve_loc = c.loc("LCID");
  set_once(m.controls.damping, g, r);
}

void control_solid(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  set_once(m.controls.solid,
           model::SolidControl{static_cast<int>(c.integer("ESORT")),
                               static_cast<int>(c.integer("FMATRX")),
                               static_cast<int>(c.integer("NIPTETS")), c.loc()},
           r);
}

void control_shell(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  const Row& c4 = r.card("4");
  model::ShellControl s;
  s.sort_triangles = static_cast<int>(c1.integer("ESORT"));
  s.thickness_update = static_cast<int>(c1.integer("ISTUPD"));
  s.theory = static_cast<int>(c1.integer("THEORY"));
  s.warping = static_cast<int>(c1.integer("BWC"));
  s.plasticity_iterations = static_cast<int>(c1.integer("MITER"));
  s.rotary_scale = c2.real("ROTASCL");
  s.lobatto = static_cast<int>(c2.integer("INTGRD"));
  s.thickness_parts = c3.integer("PSSTUPD");
  s.contact_offset = static_cast<int>(c3.integer("CNTCO"));
  // Fields whose non-default value asks for something mcdyna does not do.
  auto inactive = [&](const char* name, double value, double fallback) {
    if (value != fallback) s.inactive.push_back(fmt::format("{} = {:g}", name, value));
  };
  inactive("IRNXX", static_cast<double>(c1.integer("IRNXX")), -1);
  inactive("PROJ", static_cast<double>(c1.integer("PROJ")), 0);
  for (const char* f : {"LAMSHT", "THSHEL"})
    inactive(f, static_cast<double>(c2.integer(f)), 0);
  for (const char* f : {"SIDT4TU", "ITSFLG", "IRQUAD", "ICRQ"})
    inactive(f, static_cast<double>(c3.integer(f)), 0);
  for (const char* f : {"W-MODE", "STRETCH"})
    inactive(f, c3.real(f), 0.0);
  for (const char* f : {"NFAIL1", "NFAIL4", "PSNFAIL", "KEEPCS", "DELFR", "DRCPSID", "INTPERR"})
    inactive(f, static_cast<double>(c4.integer(f)), 0);
  s.loc = c1.loc();
  set_once(m.controls.shell, s, r);
}

void control_energy(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::EnergyControl e;
  e.hourglass = static_cast<int>(c.integer("HGEN"));
  e.rigid_wall = static_cast<int>(c.integer("RWEN"));
  e.sliding = static_cast<int>(c.integer("SLNTEN"));
  e.rayleigh = static_cast<int>(c.integer("RYLEN"));
  e.initial_reference_geometry = static_cast<int>(c.integer("IRGEN"));
  e.material_split = static_cast<int>(c.integer("MATEN"));
  e.loc = c.loc();
  set_once(m.controls.energy, e, r);
}

void control_bulk_viscosity(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::BulkViscosityControl b;
  b.quadratic = c.real("Q1");
  b.linear = c.real("Q2");
  b.type = static_cast<int>(c.integer("TYPE"));
  b.beam_type = static_cast<int>(c.integer("BTYPE"));
  b.time_step_type = static_cast<int>(c.integer("TSTYPE"));
  b.loc = c.loc();
  set_once(m.controls.bulk_viscosity, b, r);
}

void control_accuracy(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::AccuracyControl a;
  a.objective = static_cast<int>(c.integer("OSU"));
  a.invariant = static_cast<int>(c.integer("INN"));
  a.objective_parts = c.integer("PIDOSU");
  a.implicit = static_cast<int>(c.integer("IACC"));
  a.explicit_accuracy = c.real("EXACC");
  a.loc = c.loc();
  set_once(m.controls.accuracy, a, r);
}

// *CONTROL_RIGID: nothing in the run reads it; the fields that would change the answer in
// LS-DYNA are said at the field (the schema refuses the added joint stiffness and damping).
void control_rigid(KeywordRecord& r, model::ModelDatabase& /*m*/) {
  const Row& c1 = r.card("1");
  if (c1.integer("LMF") == 1) {
    r.diags().warning(c1.loc("LMF"),
                      "*CONTROL_RIGID: LMF 1 (Lagrange-multiplier joints) runs as LMF 0: mcdyna's "
                      "joints are penalty springs");
  }
  if (c1.integer("JNTF") == 0 && !c1.blank("JNTF")) {
    r.diags().note(c1.loc("JNTF"),
                   "*CONTROL_RIGID: JNTF 0 (incremental): mcdyna's generalized joint stiffness "
                   "always takes the total angles (JNTF 1)");
  }
  if (c1.integer("METALF") == 1) {
    r.diags().note(c1.loc("METALF"),
                   "*CONTROL_RIGID: METALF 1: the rigid bodies get their full treatment "
                   "(rotations included)");
  }
  if (c1.integer("PLOTEL") != 0) {
    r.diags().note(
        c1.loc("PLOTEL"),
        "*CONTROL_RIGID: PLOTEL {}: no *ELEMENT_PLOTEL is written for nodal rigid bodies",
        c1.integer("PLOTEL"));
  }
}

}  // namespace mcdyna::deck::builders
