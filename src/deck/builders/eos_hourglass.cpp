// *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *HOURGLASS.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void eos_linear_polynomial(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Eos e;
  e.id = c1.integer("EOSID");
  e.title = title_of(r);
  e.kind = model::EosKind::linear_polynomial;
  const int c0 = c1.index("C0");
  for (int k = 0; k < 7; ++k)
    e.c[k] = c1.real(c0 + k);
  e.initial_energy = c2.real("E0");
  e.initial_relative_volume = c2.real("V0");
  e.loc = c1.loc();
  if (e.c[1] <= 0.0) {
    r.diags().error(c1.loc("C1"), "*EOS_LINEAR_POLYNOMIAL {}: C1 (bulk modulus) = {} must be > 0",
                    e.id, e.c[1]);
  }
  m.equations_of_state.push_back(std::move(e));
}

void eos_gruneisen(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::Eos e;
  e.id = c1.integer("EOSID");
  e.title = title_of(r);
  e.kind = model::EosKind::gruneisen;
  e.sound_speed = c1.real("C");
  e.s = {c1.real("S1"), c1.real("S2"), c1.real("S3")};
  e.gamma0 = c1.real("GAMAO");
  e.volume_correction = c1.real("A");
  e.initial_energy = c1.real("E0");
  e.initial_relative_volume = c2.real("V0");
  e.loc = c1.loc();
  if (c2.integer("LCID") != 0) {
    r.diags().error(c2.loc("LCID"),
                    "*EOS_GRUNEISEN {}: energy deposition curve LCID is not "
                    "supported",
                    e.id);
  }
  m.equations_of_state.push_back(std::move(e));
}

void hourglass(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Hourglass h;
  h.id = c1.integer("HGID");
  h.title = title_of(r);
  h.type = static_cast<int>(c1.integer("IHQ"));
  h.coefficient = c1.real("QM");
  h.quadratic_bulk_viscosity = c1.real("Q1");
  h.linear_bulk_viscosity = c1.real("Q2");
  h.qb = c1.blank("QB") || c1.real("QB") == 0.0 ? h.coefficient : c1.real("QB");
  h.qw = c1.blank("QW") || c1.real("QW") == 0.0 ? h.coefficient : c1.real("QW");
  h.loc = c1.loc();
  m.hourglasses.push_back(std::move(h));
}

}  // namespace mcdyna::deck::builders
