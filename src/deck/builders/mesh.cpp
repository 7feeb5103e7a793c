// *TITLE, *NODE, *ELEMENT_SOLID, *ELEMENT_SHELL, *PART. These run over the largest tables of a
// deck, so field indices are resolved once per block and rows are read by index.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

std::string title_of(const KeywordRecord& r) {
  if (!r.has_option("TITLE")) return {};
  return std::string(r.card("title").text("TITLE"));
}

std::string keyword_after(const KeywordRecord& r, std::string_view prefix) {
  const std::string& name = r.schema().name;
  return name.starts_with(prefix) ? name.substr(prefix.size()) : name;
}

void title(KeywordRecord& r, model::ModelDatabase& m) {
  m.title = std::string(r.card("title").text("TITLE"));
}

void node(KeywordRecord& r, model::ModelDatabase& m) {
  m.nodes.reserve(m.nodes.size() + r.block().line_count());
  Group g;
  int nid = -1, x = -1, y = -1, z = -1, tc = -1, rc = -1;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    if (nid < 0) {
      nid = row.index("NID"), x = row.index("X"), y = row.index("Y"), z = row.index("Z");
      tc = row.index("TC"), rc = row.index("RC");
    }
    m.nodes.push_back(model::Node{row.integer(nid),
                                  {row.real(x), row.real(y), row.real(z)},
                                  static_cast<std::uint8_t>(row.integer(tc)),
                                  static_cast<std::uint8_t>(row.integer(rc)),
                                  row.loc()});
  }
}

void element_solid(KeywordRecord& r, model::ModelDatabase& m) {
  const bool one_line = r.form().name == "one_line";
  m.solids.reserve(m.solids.size() +
                   (one_line ? r.block().line_count() : r.block().line_count() / 2));
  Group g;
  int eid = -1, pid = -1, n1 = -1, n9 = -1;
  while (r.next_group(g)) {
    const Row& head = g.rows.front();
    const Row* nodes = one_line ? &head : g.card("nodes");
    if (nodes == nullptr) break;  // incomplete pair, already reported
    if (eid < 0) {
      eid = head.index("EID"), pid = head.index("PID"), n1 = nodes->index("N1");
      n9 = one_line ? -1 : nodes->index("N9");
    }
    model::SolidElement e;
    e.id = head.integer(eid);
    e.part = head.integer(pid);
    e.loc = nodes->loc();
    for (int k = 0; k < 8; ++k)
      e.nodes[k] = nodes->integer(n1 + k);
    if (n9 >= 0 && (nodes->integer(n9) != 0 || nodes->integer(n9 + 1) != 0)) {
      r.diags().error(nodes->loc(n9),
                      "{}: element {} has nodes 9-10 (10-node tetrahedron); only "
                      "8-node solids and degenerate hexahedra are supported",
                      r.display_name(), e.id);
    }
    m.solids.push_back(e);
  }
}

void element_shell(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::ShellElement s;
    s.id = row.integer("EID");
    s.part = row.integer("PID");
    s.loc = row.loc();
    const int n1 = row.index("N1");
    for (int k = 0; k < 4; ++k)
      s.nodes[k] = row.integer(n1 + k);
    if (s.nodes[3] == 0) s.nodes[3] = s.nodes[2];
    if (row.integer("N5") != 0) {
      r.diags().error(row.loc("N5"),
                      "{}: element {} has mid-side nodes; 8-node shells are not "
                      "supported",
                      r.display_name(), s.id);
    }
    if (const Row* t = g.card("thickness")) {
      const int t1 = t->index("THIC1");
      for (int k = 0; k < 4; ++k)
        s.thickness[k] = t->real(t1 + k);
    }
    m.shells.push_back(s);
  }
}

void element_beam(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::BeamElement b;
    b.id = row.integer("EID");
    b.part = row.integer("PID");
    b.loc = row.loc();
    b.nodes = {row.integer("N1"), row.integer("N2")};
    b.orientation_node = row.integer("N3");
    for (const char* f : {"RT1", "RR1", "RT2", "RR2"}) {
      if (row.integer(f) != 0) {
        r.diags().error(row.loc(f),
                        "{}: element {}: {} = {}: beam end releases are not supported (the "
                        "ends are rigidly joined to their nodes)",
                        r.display_name(), b.id, f, row.integer(f));
      }
    }
    if (b.nodes[0] == b.nodes[1]) {
      r.diags().error(row.loc("N2"), "{}: element {} has N1 = N2 = {} (zero length)",
                      r.display_name(), b.id, b.nodes[0]);
    }
    if (const Row* t = g.card("thickness")) {
      const int p1 = t->index("PARM1");
      for (int k = 0; k < 5; ++k)
        b.parameters[static_cast<std::size_t>(k)] = t->real(p1 + k);
    }
    if (const Row* o = g.card("orientation")) {
      b.orientation = {o->real("VX"), o->real("VY"), o->real("VZ")};
      if (b.orientation_node != 0) {
        r.diags().error(row.loc("N3"),
                        "{}: element {} gives both N3 and an orientation vector; give one",
                        r.display_name(), b.id);
      }
    }
    m.beams.push_back(b);
  }
}

namespace {

// The heading and card 1 that *PART and *PART_INERTIA share.
model::Part part_of(KeywordRecord& r, const Row* heading, const Row& card) {
  model::Part p;
  p.heading = heading != nullptr ? std::string(heading->text("HEADING")) : std::string();
  p.id = card.integer("PID");
  p.section = card.integer("SECID");
  p.material = card.integer("MID");
  p.eos = card.integer("EOSID");
  p.hourglass = card.integer("HGID");
  p.thermal_material = card.integer("TMID");
  p.loc = card.loc();
  p.section_loc = card.loc("SECID");
  p.material_loc = card.loc("MID");
  p.eos_loc = card.loc("EOSID");
  p.hourglass_loc = card.loc("HGID");
  if (p.thermal_material != 0) {
    r.diags().warning(card.loc("TMID"),
                      "*PART {}: thermal material TMID is ignored (no thermal "
                      "solver; Johnson-Cook heating uses CP)",
                      p.id);
  }
  return p;
}

}  // namespace

void part(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row* card = g.card("1");
    if (card == nullptr) break;
    m.parts.push_back(part_of(r, g.card("heading"), *card));
  }
}

void part_inertia(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row* card = g.card("1");
    const Row* c2 = g.card("2");
    const Row* c3 = g.card("3");
    const Row* c4 = g.card("4");
    if (card == nullptr) break;
    if (c2 == nullptr || c3 == nullptr || c4 == nullptr) {
      r.diags().error(card->loc(), "{}: part {} needs cards 2 to 4 (mass, inertia, velocity)",
                      r.display_name(), card->integer("PID"));
      break;
    }
    model::Part p = part_of(r, g.card("heading"), *card);
    model::PartInertia in;
    in.centre = {c2->real("XC"), c2->real("YC"), c2->real("ZC")};
    in.mass = c2->real("TM");
    in.node = c2->integer("NODEID");
    const int ixx = c3->index("IXX");
    for (int k = 0; k < 6; ++k)
      in.tensor[static_cast<std::size_t>(k)] = c3->real(ixx + k);
    in.velocity = {c4->real("VTX"), c4->real("VTY"), c4->real("VTZ")};
    in.angular_velocity = {c4->real("VRX"), c4->real("VRY"), c4->real("VRZ")};
    in.loc = c2->loc();
    p.inertia = in;
    m.parts.push_back(std::move(p));
  }
}

}  // namespace mcdyna::deck::builders
