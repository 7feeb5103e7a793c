// *DEFINE_CURVE, *DEFINE_VECTOR, *DEFINE_BOX, *SET_SEGMENT (the other sets: sets.cpp).
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
