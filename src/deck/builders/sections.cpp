// *SECTION_SOLID, *SECTION_SOLID_SPG, *SECTION_SHELL, *SECTION_BEAM.
#include <fmt/format.h>

#include <cmath>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void section_solid(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Section s;
  s.id = c1.integer("SECID");
  s.title = title_of(r);
  s.element_formulation = static_cast<int>(c1.integer("ELFORM"));
  s.kind = s.element_formulation == 47 ? model::SectionKind::solid_spg : model::SectionKind::solid;
  s.loc = c1.loc();
  if (s.kind == model::SectionKind::solid_spg) {
    r.diags().error(c1.loc("ELFORM"),
                    "*SECTION_SOLID {}: ELFORM 47 (SPG) needs the SPG cards; "
                    "write it as *SECTION_SOLID_SPG",
                    s.id);
  }
  s.summary = fmt::format("solid ELFORM {}", s.element_formulation);
  m.sections.push_back(std::move(s));
}

void section_solid_spg(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  model::Section s;
  s.id = c1.integer("SECID");
  s.title = title_of(r);
  s.kind = model::SectionKind::solid_spg;
  s.element_formulation = static_cast<int>(c1.integer("ELFORM"));
  s.loc = c1.loc();
  model::SpgSettings& spg = s.spg;
  spg.kernel_function = static_cast<int>(c2.integer("ISPLINE"));
  spg.kernel_update = static_cast<int>(c2.integer("KERNEL"));
  if (spg.kernel_update == 3) {
    // R10 coding: 3 was pseudo-Lagrangian, which is 2 in R13+ (keywords.md §2.6).
    r.diags().note(c2.loc("KERNEL"),
                   "*SECTION_SOLID_SPG {}: KERNEL=3 (R10 pseudo-Lagrangian) "
                   "read as KERNEL=2",
                   s.id);
    spg.kernel_update = 2;
  }
  // Defaults that depend on KERNEL (keywords.md §2.6, R15 manifest).
  constexpr double kSupportDefault[3] = {1.6, 1.8, 1.5};
  constexpr int kSmstepDefault[3] = {15, 5, 30};
  const double dx =
      c2.blank("DX") || c2.real("DX") == 0.0 ? kSupportDefault[spg.kernel_update] : c2.real("DX");
  const double dy = c2.blank("DY") || c2.real("DY") == 0.0 ? dx : c2.real("DY");
  const double dz = c2.blank("DZ") || c2.real("DZ") == 0.0 ? dx : c2.real("DZ");
  spg.support_scale = {dx, dy, dz};
  for (const char* f : {"DX", "DY", "DZ"}) {
    if (!c2.blank(f) && c2.real(f) != 0.0 && c2.real(f) < 1.0) {
      r.diags().error(c2.loc(f),
                      "*SECTION_SOLID_SPG {}: {} = {} is below 1; the support must "
                      "cover at least the nodal spacing",
                      s.id, f, c2.real(f));
    }
  }
  spg.smoothing_interval = c2.integer("SMSTEP") > 0 ? static_cast<int>(c2.integer("SMSTEP"))
                                                    : kSmstepDefault[spg.kernel_update];
  spg.smoothing_scheme = c2.real("MSC");
  spg.damage_criterion = static_cast<int>(c3.integer("IDAM"));
  spg.failure_strain = c3.real("FS");
  spg.failure_stretch = c3.real("STRETCH");
  spg.stabilization = c3.blank("ITB") || c3.integer("ITB") == 0
                          ? (spg.kernel_update == 2 ? 2 : 1)
                          : static_cast<int>(c3.integer("ITB"));
  spg.surface_quadrature_factor = c3.real("MSFAC");
  spg.self_contact = c3.real("ISC") != 0.0 ? 1 : 0;  // a flag written as a real (any 1e30 too)
  spg.box = c3.integer("BOXID");
  spg.particle_damping = c3.real("PDAMP");
  if (spg.failure_stretch < 1.0) {
    r.diags().error(c3.loc("STRETCH"),
                    "*SECTION_SOLID_SPG {}: STRETCH = {} must be >= 1 (bonds "
                    "do not fail in compression)",
                    s.id, spg.failure_stretch);
  }
  s.summary = fmt::format("SPG ITB {} KERNEL {}", spg.stabilization, spg.kernel_update);
  m.sections.push_back(std::move(s));
}

void section_shell(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Section s;
  s.id = c1.integer("SECID");
  s.title = title_of(r);
  s.kind = model::SectionKind::shell;
  s.element_formulation = static_cast<int>(c1.integer("ELFORM"));
  s.shell.shear_factor = c1.real("SHRF");
  s.shell.integration_points = static_cast<int>(c1.integer("NIP"));
  s.shell.quadrature = c1.real("QR");
  s.shell.composite = static_cast<int>(c1.integer("ICOMP"));
  const int t1 = c2.index("T1");
  for (int k = 0; k < 4; ++k)
    s.shell.thickness[k] = c2.real(t1 + k);
  s.shell.reference_surface = c2.real("NLOC");
  s.shell.nonstructural_mass = c2.real("MAREA");
  s.shell.formulation_loc = c1.loc("ELFORM");
  s.shell.points_loc = c1.loc("NIP");
  s.shell.quadrature_loc = c1.loc("QR");
  s.shell.composite_loc = c1.loc("ICOMP");
  s.shell.thickness_loc = c2.loc("T1");
  s.shell.reference_loc = c2.loc("NLOC");
  s.loc = c1.loc();
  s.summary = fmt::format("shell ELFORM {}", s.element_formulation);
  m.sections.push_back(std::move(s));
}

void section_beam(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Section s;
  s.id = c1.integer("SECID");
  s.title = title_of(r);
  s.kind = model::SectionKind::beam;
  s.element_formulation = static_cast<int>(c1.integer("ELFORM"));
  s.loc = c1.loc();
  model::BeamSettings& b = s.beam;
  b.shear_factor = c1.real("SHRF");
  b.quadrature = c1.real("QR");
  b.cross_section = static_cast<int>(c1.integer("CST"));
  b.nonstructural_mass = c1.real("NSM");
  b.formulation_loc = c1.loc("ELFORM");
  b.quadrature_loc = c1.loc("QR");
  b.cross_section_loc = c1.loc("CST");
  if (const Row& c = r.card("integrated"); c.present()) {
    const int ts1 = c.index("TS1");
    for (int k = 0; k < 4; ++k)
      b.thickness[static_cast<std::size_t>(k)] = c.real(ts1 + k);
    b.reference_s = c.real("NSLOC");
    b.reference_t = c.real("NTLOC");
    b.dimensions_loc = c.loc();
    if (b.reference_s != 0.0 || b.reference_t != 0.0) {
      r.diags().error(c.loc("NSLOC"),
                      "*SECTION_BEAM {}: NSLOC / NTLOC (reference line off the centroid) are not "
                      "supported",
                      s.id);
    }
  }
  if (const Row& c = r.card("resultant"); c.present()) {
    b.area = c.real("A");
    b.iss = c.real("ISS");
    b.itt = c.real("ITT");
    b.torsion = c.real("J");
    b.shear_area = c.real("SA");
    b.product_of_inertia = c.real("IST");
    b.dimensions_loc = c.loc();
    if (b.product_of_inertia != 0.0) {
      r.diags().error(c.loc("IST"),
                      "*SECTION_BEAM {}: IST (product of inertia, unsymmetric section) is not "
                      "supported",
                      s.id);
    }
  }
  s.summary = fmt::format("beam ELFORM {}", s.element_formulation);
  m.sections.push_back(std::move(s));
}

}  // namespace mcdyna::deck::builders
