// *DEFINE_CURVE, *DEFINE_VECTOR, *DEFINE_BOX, *SET_NODE_LIST(_GENERATE), *SET_PART_LIST,
// *SET_SEGMENT.
#include <cmath>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void define_curve(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::Curve c;
  c.id = c1.integer("LCID");
  c.title = title_of(r);
  c.dynamic_relaxation = static_cast<int>(c1.integer("SIDR"));
  c.abscissa_scale = c1.real("SFA");
  c.ordinate_scale = c1.real("SFO");
  c.abscissa_offset = c1.real("OFFA");
  c.ordinate_offset = c1.real("OFFO");
  c.loc = c1.loc();
  if (c1.integer("DATTYP") != 0 && c1.integer("DATTYP") != -2) {
    r.diags().error(c1.loc("DATTYP"), "*DEFINE_CURVE {}: DATTYP = {} is not supported", c.id,
                    c1.integer("DATTYP"));
  }
  Group g;
  core::SourceLoc previous;
  while (r.next_group(g)) {
    const Row& p = g.rows.front();
    const double a = p.real("A");
    if (!c.points.empty() && a < c.points.back().first) {  // equal abscissas make a step
      r.diags().error(p.loc("A"),
                      "*DEFINE_CURVE {}: abscissa {} decreases (previous {} at "
                      "line {})",
                      c.id, a, c.points.back().first, previous.line);
    }
    c.points.emplace_back(a, p.real("O"));
    previous = p.loc();
  }
  if (c.points.empty()) {
    r.diags().error(c1.loc(), "*DEFINE_CURVE {}: the curve has no points", c.id);
  }
  m.curves.push_back(std::move(c));
}

void define_vector(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::Vector v;
  v.id = c.integer("VID");
  v.tail = {c.real("XT"), c.real("YT"), c.real("ZT")};
  v.head = {c.real("XH"), c.real("YH"), c.real("ZH")};
  v.coordinate_system = c.integer("CID");
  v.loc = c.loc();
  if (std::hypot(v.head[0] - v.tail[0], v.head[1] - v.tail[1], v.head[2] - v.tail[2]) == 0.0) {
    r.diags().error(c.loc(), "*DEFINE_VECTOR {}: head equals tail (zero vector)", v.id);
  }
  if (v.coordinate_system != 0) {
    r.diags().error(c.loc("CID"), "*DEFINE_VECTOR {}: local system CID is not supported", v.id);
  }
  m.vectors.push_back(v);
}

void define_box(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::Box b;
  b.id = c.integer("BOXID");
  b.min = {c.real("XMN"), c.real("YMN"), c.real("ZMN")};
  b.max = {c.real("XMX"), c.real("YMX"), c.real("ZMX")};
  b.loc = c.loc();
  for (int k = 0; k < 3; ++k) {
    if (b.max[k] < b.min[k]) {
      r.diags().error(c.loc(), "*DEFINE_BOX {}: maximum below minimum in {}", b.id, "xyz"[k]);
    }
  }
  m.boxes.push_back(b);
}

namespace {

// Reads "8 IDs per line" groups into `ids`, skipping blanks and zeros.
void read_id_lines(KeywordRecord& r, std::vector<model::Id>& ids, std::string_view first_field) {
  Group g;
  int first = -1;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    if (first < 0) first = row.index(first_field);
    for (int k = 0; k < 8; ++k) {
      const model::Id id = row.integer(first + k);
      if (id != 0) ids.push_back(id);
    }
  }
}

}  // namespace

void set_node_list(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::NodeSet s;
  s.id = c1.integer("SID");
  s.loc = c1.loc();
  read_id_lines(r, s.nodes, "NID1");
  m.node_sets.push_back(std::move(s));
}

namespace {

// Reads "four first-last ranges per line" groups into `ids` (*SET_..._GENERATE).
void read_id_ranges(KeywordRecord& r, model::Id set, std::vector<model::Id>& ids) {
  Group g;
  constexpr model::Id kMaxGenerated = 10'000'000;  // no real deck generates more
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    const int b1 = row.index("B1BEG");
    for (int k = 0; k < 4; ++k) {
      const model::Id begin = row.integer(b1 + 2 * k), end = row.integer(b1 + 2 * k + 1);
      if (begin == 0 && end == 0) continue;
      if (end < begin || end - begin > kMaxGenerated) {
        r.diags().error(row.loc(b1 + 2 * k), "{} {}: range {}..{} is not a valid increasing range",
                        r.display_name(), set, begin, end);
        continue;
      }
      for (model::Id n = begin; n <= end; ++n)
        ids.push_back(n);
    }
  }
}

model::ElementSetKind element_set_kind(const std::string& name) {
  if (name.rfind("SET_SOLID", 0) == 0) return model::ElementSetKind::solid;
  if (name.rfind("SET_BEAM", 0) == 0) return model::ElementSetKind::beam;
  return model::ElementSetKind::shell;
}

}  // namespace

void set_node_list_generate(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::NodeSet s;
  s.id = c1.integer("SID");
  s.loc = c1.loc();
  read_id_ranges(r, s.id, s.nodes);
  m.node_sets.push_back(std::move(s));
}

void set_element_generate(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::ElementSet s;
  s.id = c1.integer("SID");
  s.kind = element_set_kind(r.schema().name);
  s.loc = c1.loc();
  read_id_ranges(r, s.id, s.elements);
  m.element_sets.push_back(std::move(s));
}

void set_element_list(KeywordRecord& r, model::ModelDatabase& m) {
  const std::string& name = r.schema().name;
  const Row& c1 = r.card("1");
  model::ElementSet s;
  s.id = c1.integer("SID");
  s.kind = element_set_kind(name);
  s.loc = c1.loc();
  read_id_lines(r, s.elements, "K1");
  m.element_sets.push_back(std::move(s));
}

void set_node_general(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::NodeSet s;
  s.id = c1.integer("SID");
  s.loc = c1.loc();
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::SetRule rule;
    rule.option = std::string(row.text("OPTION"));
    rule.loc = row.loc("OPTION");
    const int e1 = row.index("E1");
    for (int k = 0; k < 7; ++k)
      if (row.integer(e1 + k) != 0) rule.ids.push_back(row.integer(e1 + k));
    s.rules.push_back(std::move(rule));
  }
  if (s.rules.empty()) r.diags().error(c1.loc(), "*SET_NODE_GENERAL {}: no rule card", s.id);
  m.node_sets.push_back(std::move(s));
}

void set_part_list(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::PartSet s;
  s.id = c1.integer("SID");
  s.loc = c1.loc();
  read_id_lines(r, s.parts, "PID1");
  m.part_sets.push_back(std::move(s));
}

void set_segment(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  model::SegmentSet s;
  s.id = c1.integer("SID");
  s.loc = c1.loc();
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    std::array<model::Id, 4> seg{row.integer("N1"), row.integer("N2"), row.integer("N3"),
                                 row.integer("N4")};
    if (seg[3] == 0) seg[3] = seg[2];
    s.segments.push_back(seg);
  }
  m.segment_sets.push_back(std::move(s));
}

}  // namespace mcdyna::deck::builders
