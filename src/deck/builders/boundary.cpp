// *BOUNDARY_SPC_*, *BOUNDARY_PRESCRIBED_MOTION_*, *INITIAL_VELOCITY*, *RIGIDWALL_PLANAR.
#include <cmath>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void boundary_spc(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& id = r.card("id");
  const bool is_set = r.schema().name == "BOUNDARY_SPC_SET";
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::SpcConstraint s;
    s.id = id.integer("ID");
    s.is_set = is_set;
    s.target = row.integer("NID");
    s.coordinate_system = row.integer("CID");
    const int dx = row.index("DOFX");
    for (int k = 0; k < 6; ++k)
      s.fixed[k] = row.integer(dx + k) != 0;
    s.loc = row.loc();
    if (s.coordinate_system != 0) {
      r.diags().error(row.loc("CID"),
                      "{}: local coordinate system CID = {} is not supported "
                      "(global directions only)",
                      r.display_name(), s.coordinate_system);
    }
    m.spcs.push_back(s);
  }
}

void boundary_prescribed_motion(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& id = r.card("id");
  const std::string& name = r.schema().name;
  const model::MotionTarget target =
      name == "BOUNDARY_PRESCRIBED_MOTION_SET"     ? model::MotionTarget::node_set
      : name == "BOUNDARY_PRESCRIBED_MOTION_RIGID" ? model::MotionTarget::rigid_part
                                                   : model::MotionTarget::node;
  Group g;
  while (r.next_group(g)) {
    const Row& c1 = g.rows.front();
    model::PrescribedMotion p;
    p.id = id.integer("ID");
    p.heading = std::string(id.text("HEADING"));
    p.target_kind = target;
    p.target = c1.integer("NID");
    p.dof = static_cast<int>(c1.integer("DOF"));
    p.kind = static_cast<int>(c1.integer("VAD"));
    p.curve = c1.integer("LCID");
    p.scale = c1.real("SF");
    p.vector = c1.integer("VID");
    p.death = c1.real("DEATH");
    p.birth = c1.real("BIRTH");
    p.loc = c1.loc();
    p.curve_loc = c1.loc("LCID");
    p.vector_loc = c1.loc("VID");
    if (const Row* c2 = g.card("2")) {
      p.offset1 = c2->real("OFFSET1");
      p.offset2 = c2->real("OFFSET2");
      p.lead_rigid_body = c2->integer("LRB");
      p.node1 = c2->integer("NODE1");
      p.node2 = c2->integer("NODE2");
    }
    const int dof = std::abs(p.dof);
    if (target == model::MotionTarget::rigid_part && dof >= 9) {
      r.diags().error(c1.loc("DOF"), "{}: DOF {} applies to nodes only; rigid parts take 1-8",
                      r.display_name(), p.dof);
    }
    if ((dof == 4 || dof == 8) && p.vector <= 0) {
      r.diags().error(c1.loc("VID"), "{}: DOF {} needs a *DEFINE_VECTOR in VID", r.display_name(),
                      p.dof);
    }
    if (p.vector < 0) {
      r.diags().error(c1.loc("VID"), "{}: VID < 0 (local coordinate system) is not supported",
                      r.display_name());
    }
    if (p.kind == 3 || p.kind == 4) {
      r.diags().error(c1.loc("VAD"),
                      "{}: VAD = {} is not supported (0 velocity, 1 acceleration, "
                      "2 displacement)",
                      r.display_name(), p.kind);
    }
    if (p.death <= p.birth) {
      r.diags().error(c1.loc("DEATH"), "{}: DEATH = {} is not after BIRTH = {}", r.display_name(),
                      p.death, p.birth);
    }
    m.prescribed_motions.push_back(p);
  }
}

void load_body(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::BodyLoad b;
  const std::string& name = r.schema().name;
  b.axis = name.back() - 'X';
  b.curve = c.integer("LCID");
  b.scale = c.real("SF");
  b.loc = c.loc();
  b.curve_loc = c.loc("LCID");
  if (c.integer("CID") != 0) {
    r.diags().error(c.loc("CID"), "{}: local coordinate system CID = {} is not supported",
                    r.display_name(), c.integer("CID"));
  }
  if (c.integer("LCIDDR") != 0) {
    r.diags().note(c.loc("LCIDDR"),
                   "{}: LCIDDR = {}: mcdyna runs no dynamic relaxation; the curve is not used",
                   r.display_name(), c.integer("LCIDDR"));
  }
  m.body_loads.push_back(b);
}

void initial_velocity(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  model::InitialVelocity v;
  v.kind = model::InitialVelocityKind::by_set;
  v.target = c1.integer("NSID");
  v.exempted_set = c1.integer("NSIDEX");
  v.box = c1.integer("BOXID");
  v.irigid = static_cast<int>(c1.integer("IRIGID"));
  v.velocity = {c2.real("VX"), c2.real("VY"), c2.real("VZ")};
  v.angular_velocity = {c2.real("VXR"), c2.real("VYR"), c2.real("VZR")};
  v.exempted_velocity = {c3.real("VXE"), c3.real("VYE"), c3.real("VZE")};
  v.loc = c1.loc();
  if (c1.integer("ICID") != 0) {
    r.diags().error(c1.loc("ICID"), "*INITIAL_VELOCITY: local system ICID is not supported");
  }
  m.initial_velocities.push_back(v);
}

void initial_velocity_node(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& c = g.rows.front();
    model::InitialVelocity v;
    v.kind = model::InitialVelocityKind::per_node;
    v.target = c.integer("NID");
    v.velocity = {c.real("VX"), c.real("VY"), c.real("VZ")};
    v.angular_velocity = {c.real("VXR"), c.real("VYR"), c.real("VZR")};
    v.loc = c.loc();
    if (c.integer("ICID") != 0) {
      r.diags().error(c.loc("ICID"), "*INITIAL_VELOCITY_NODE: local system ICID is not supported");
    }
    m.initial_velocities.push_back(v);
  }
}

void initial_velocity_generation(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row* c1 = g.card("1");
    const Row* c2 = g.card("2");
    if (c1 == nullptr || c2 == nullptr) break;
    model::InitialVelocity v;
    v.kind = model::InitialVelocityKind::generation;
    v.target = c1->integer("ID");
    v.target_type = static_cast<int>(c1->integer("STYP"));
    v.omega = c1->real("OMEGA");
    v.velocity = {c1->real("VX"), c1->real("VY"), c1->real("VZ")};
    v.axis_point = {c2->real("XC"), c2->real("YC"), c2->real("ZC")};
    v.axis_direction = {c2->real("NX"), c2->real("NY"), c2->real("NZ")};
    v.irigid = static_cast<int>(c2->integer("IRIGID"));
    v.loc = c1->loc();
    const double len = std::hypot(v.axis_direction[0], v.axis_direction[1], v.axis_direction[2]);
    if (v.axis_direction[0] == -999.0) {
      r.diags().error(c2->loc("NX"),
                      "*INITIAL_VELOCITY_GENERATION: NX = -999 (axis by two nodes) "
                      "is not supported");
    } else if (v.omega != 0.0 && len == 0.0) {
      r.diags().error(c2->loc("NX"),
                      "*INITIAL_VELOCITY_GENERATION: OMEGA = {} needs a rotation "
                      "axis (NX, NY, NZ)",
                      v.omega);
    }
    if (c1->integer("ICID") != 0) {
      r.diags().error(c1->loc("ICID"),
                      "*INITIAL_VELOCITY_GENERATION: local system ICID is not "
                      "supported");
    }
    if (c2->integer("PHASE") != 0) {
      r.diags().error(c2->loc("PHASE"),
                      "*INITIAL_VELOCITY_GENERATION: PHASE = 1 (after dynamic "
                      "relaxation) is not supported");
    }
    m.initial_velocities.push_back(v);
  }
}

void rigidwall_planar(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& id = r.card("id");
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& fin = r.card("finite");
  const Row& mov = r.card("moving");
  model::RigidWall w;
  w.id = id.integer("RWID");
  w.heading = std::string(id.text("TITLE"));
  w.node_set = c1.integer("NSID");
  w.exempted_set = c1.integer("NSIDEX");
  w.box = c1.integer("BOXID");
  w.offset = c1.real("OFFSET");
  w.birth = c1.real("BIRTH");
  w.death = c1.real("DEATH");
  w.penalty_scale = c1.real("RWKSF");
  w.tail = {c2.real("XT"), c2.real("YT"), c2.real("ZT")};
  w.head = {c2.real("XH"), c2.real("YH"), c2.real("ZH")};
  w.friction = c2.real("FRIC");
  w.weld_velocity = c2.real("WVEL");
  w.finite = r.has_option("FINITE");
  w.edge_head = {fin.real("XHEV"), fin.real("YHEV"), fin.real("ZHEV")};
  w.length_l = fin.real("LENL");
  w.length_m = fin.real("LENM");
  w.moving = r.has_option("MOVING");
  w.mass = mov.real("MASS");
  w.initial_velocity = mov.real("V0");
  w.loc = c1.loc();
  const double nx = w.head[0] - w.tail[0], ny = w.head[1] - w.tail[1], nz = w.head[2] - w.tail[2];
  if (std::hypot(nx, ny, nz) == 0.0) {
    r.diags().error(c2.loc(), "{}: the wall normal is zero (head equals tail)", r.display_name());
  }
  if (w.friction >= 2.0) {
    r.diags().error(c2.loc("FRIC"), "{}: FRIC = {} (weld on impact) is not supported",
                    r.display_name(), w.friction);
  }
  m.rigid_walls.push_back(w);
}

}  // namespace mcdyna::deck::builders

namespace mcdyna::deck::builders {

void load_point(KeywordRecord& r, model::ModelDatabase& m) {
  const std::string& name = r.schema().name;
  const model::LoadTarget target = name == "LOAD_NODE_SET"     ? model::LoadTarget::node_set
                                   : name == "LOAD_RIGID_BODY" ? model::LoadTarget::rigid_part
                                                               : model::LoadTarget::node;
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::PointLoad p;
    p.target_kind = target;
    p.target = row.integer("NID");
    p.dof = static_cast<int>(row.integer("DOF"));
    p.curve = row.integer("LCID");
    p.scale = row.real("SF");
    p.loc = row.loc();
    p.curve_loc = row.loc("LCID");
    m.point_loads.push_back(p);
  }
}

void load_segment(KeywordRecord& r, model::ModelDatabase& m) {
  const bool is_set = r.schema().name == "LOAD_SEGMENT_SET";
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::SegmentLoad l;
    l.is_set = is_set;
    if (is_set) {
      l.set = row.integer("SSID");
    } else {
      const int first = row.index("N1");
      for (int k = 0; k < 4; ++k)
        l.nodes[static_cast<std::size_t>(k)] = row.integer(first + k);
      if (l.nodes[3] == 0) l.nodes[3] = l.nodes[2];
    }
    l.curve = row.integer("LCID");
    l.scale = row.real("SF");
    l.arrival = row.real("AT");
    l.loc = row.loc();
    l.curve_loc = row.loc("LCID");
    m.segment_loads.push_back(l);
  }
}

}  // namespace mcdyna::deck::builders
