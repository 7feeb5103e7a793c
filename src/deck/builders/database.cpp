// *DATABASE_BINARY_D3PLOT, *DATABASE_BINARY_D3DUMP / _RUNRSF, the ASCII history databases,
// *DATABASE_HISTORY_NODE(_SET), *DATABASE_EXTENT_BINARY.
#include <algorithm>
#include <cmath>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void database_d3plot(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::D3plotRequest d;
  d.interval = c.real("DT");
  d.interval_curve = c.integer("LCDT");
  d.beam = static_cast<int>(c.integer("BEAM"));
  d.plots = static_cast<int>(c.integer("NPLTC"));
  d.excluded_parts = c.integer("PSETID");
  d.loc = c.loc();
  set_once(m.outputs.d3plot, d, r);
}

void database_restart_dump(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::RestartDumpRequest d;
  const double cycles = c.real("CYCL");
  d.cycles = std::lround(cycles);
  if (cycles > 0.0 && d.cycles < 1) d.cycles = 1;
  d.files = std::max(1, static_cast<int>(c.integer("NR")));
  d.loc = c.loc();
  const bool running = r.schema().name == "DATABASE_BINARY_RUNRSF";
  set_once(running ? m.outputs.runrsf : m.outputs.d3dump, d, r);
}

void database_ascii(KeywordRecord& r, model::ModelDatabase& m) {
  using D = model::AsciiDatabase;
  const std::string& name = r.schema().name;
  const D which = name == "DATABASE_GLSTAT"    ? D::glstat
                  : name == "DATABASE_MATSUM"  ? D::matsum
                  : name == "DATABASE_RCFORC"  ? D::rcforc
                  : name == "DATABASE_NODOUT"  ? D::nodout
                  : name == "DATABASE_SPCFORC" ? D::spcforc
                  : name == "DATABASE_BNDOUT"  ? D::bndout
                                               : D::rwforc;
  const Row& c = r.card("1");
  model::AsciiRequest a;
  a.database = which;
  a.interval = c.real("DT");
  a.binary = static_cast<int>(c.integer("BINARY"));
  a.interval_curve = c.integer("LCUR");
  a.ioopt = static_cast<int>(c.integer("IOOPT"));
  a.loc = c.loc();
  for (model::AsciiRequest& existing : m.outputs.ascii) {
    if (existing.database == which) {
      r.diags().warning(r.block().loc, "{} given again; this one replaces line {}",
                        r.display_name(), existing.loc.line);
      existing = a;
      return;
    }
  }
  m.outputs.ascii.push_back(a);
}

void database_history_node(KeywordRecord& r, model::ModelDatabase& m) {
  model::HistoryNodes h;
  h.is_set = r.schema().name == "DATABASE_HISTORY_NODE_SET";
  h.loc = r.block().loc;
  Group g;
  while (r.next_group(g)) {
    if (const Row* named = g.card("named")) {
      h.ids.push_back(named->integer("ID"));
      h.headings.emplace_back(named->text("HEADING"));
      continue;
    }
    const Row& row = g.rows.front();
    const int first = row.index("ID1");
    for (int k = 0; k < 8; ++k) {
      if (row.integer(first + k) != 0) {
        h.ids.push_back(row.integer(first + k));
        h.headings.emplace_back();
      }
    }
  }
  m.outputs.history_nodes.push_back(std::move(h));
}

void database_extent_binary(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::ExtentBinary e;
  e.shell_history_variables = static_cast<int>(c.integer("NEIPH"));
  e.solid_history_variables = static_cast<int>(c.integer("NEIPS"));
  e.max_integration_points = static_cast<int>(c.integer("MAXINT"));
  e.strain_flag = static_cast<int>(c.integer("STRFLG"));
  e.stress_flag = static_cast<int>(c.integer("SIGFLG"));
  e.plastic_strain_flag = static_cast<int>(c.integer("EPSFLG"));
  e.resultant_flag = static_cast<int>(c.integer("RLTFLG"));
  e.energy_flag = static_cast<int>(c.integer("ENGFLG"));
  e.loc = c.loc();
  set_once(m.outputs.extent, e, r);
}

}  // namespace mcdyna::deck::builders
