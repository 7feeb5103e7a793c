// *ELEMENT_DISCRETE, *SECTION_DISCRETE and the discrete elements' materials (*MAT_SPRING_ELASTIC,
// *MAT_DAMPER_VISCOUS, *MAT_SPRING_NONLINEAR_ELASTIC). The fields the solver does not model
// (torsional springs, KD, V0, CL, FD, CDL, TDL, VID) are limited to 0 by their schemas: the
// section says only that the part's elements are translational discrete elements.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void element_discrete(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::DiscreteElement e;
    e.id = row.integer("EID");
    e.part = row.integer("PID");
    e.nodes = {row.integer("N1"), row.integer("N2")};
    e.scale = row.real("S");
    e.offset = row.real("OFFSET");
    e.loc = row.loc();
    if (e.nodes[0] == e.nodes[1]) {
      r.diags().error(row.loc("N2"),
                      "{}: element {} has N1 = N2 = {}: a translational spring needs two nodes "
                      "(its direction is N1 -> N2)",
                      r.display_name(), e.id, e.nodes[0]);
    }
    m.discretes.push_back(e);
  }
}

void section_discrete(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Section s;
  s.id = c1.integer("SECID");
  s.title = title_of(r);
  s.kind = model::SectionKind::discrete;
  s.element_formulation = 0;
  s.summary = "discrete";
  s.loc = c1.loc();
  m.sections.push_back(std::move(s));
}

void mat_spring(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Material mat;
  mat.id = c1.integer("MID");
  mat.title = title_of(r);
  mat.keyword = keyword_after(r, "MAT_");
  mat.loc = c1.loc();
  const std::string_view name = r.schema().name;
  if (name == "MAT_SPRING_ELASTIC") {
    mat.kind = model::MaterialKind::spring_elastic;
    mat.discrete.stiffness = c1.real("K");
  } else if (name == "MAT_DAMPER_VISCOUS") {
    mat.kind = model::MaterialKind::damper_viscous;
    mat.discrete.damping = c1.real("DC");
  } else {
    mat.kind = model::MaterialKind::spring_nonlinear_elastic;
    mat.discrete.force_curve = c1.integer("LCD");
    mat.discrete.rate_curve = c1.integer("LCR");
    mat.discrete.force_curve_loc = c1.loc("LCD");
    mat.discrete.rate_curve_loc = c1.loc("LCR");
  }
  m.materials.push_back(std::move(mat));
}

}  // namespace mcdyna::deck::builders
