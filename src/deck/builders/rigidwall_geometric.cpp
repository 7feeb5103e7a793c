// *RIGIDWALL_GEOMETRIC_FLAT / _PRISM / _CYLINDER / _SPHERE (options ID, MOTION, DISPLAY): the
// shape, the tracked nodes and the wall's motion (solver/walls/ runs them).
#include <cmath>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

model::WallShape shape_of(const std::string& schema) {
  if (schema == "RIGIDWALL_GEOMETRIC_FLAT") return model::WallShape::flat;
  if (schema == "RIGIDWALL_GEOMETRIC_PRISM") return model::WallShape::prism;
  if (schema == "RIGIDWALL_GEOMETRIC_CYLINDER") return model::WallShape::cylinder;
  return model::WallShape::sphere;
}

// The shape card's fields into `w`.
void read_shape(const Row& c, model::RigidWall& w) {
  switch (w.shape) {
    case model::WallShape::flat:
    case model::WallShape::prism:
      w.edge_head = {c.real("XHEV"), c.real("YHEV"), c.real("ZHEV")};
      w.length_l = c.real("LENL");
      w.length_m = c.real("LENM");
      if (w.shape == model::WallShape::prism) w.length_p = c.real("LENP");
      w.finite = w.length_l > 0.0 || w.length_m > 0.0;
      break;
    case model::WallShape::cylinder:
      w.radius = c.real("RADCYL");
      w.cylinder_length = c.real("LENCYL");
      break;
    case model::WallShape::sphere:
    case model::WallShape::planar:
      w.radius = c.real("RADSPH");
      break;
  }
}

}  // namespace

void rigidwall_geometric(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& id = r.card("id");
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::RigidWall w;
  w.shape = shape_of(r.schema().name);
  w.id = id.integer("RWID");
  w.heading = std::string(id.text("TITLE"));
  w.node_set = c1.integer("NSID");
  w.exempted_set = c1.integer("NSIDEX");
  w.box = c1.integer("BOXID");
  w.birth = c1.real("BIRTH");
  w.death = c1.real("DEATH");
  w.tail = {c2.real("XT"), c2.real("YT"), c2.real("ZT")};
  w.head = {c2.real("XH"), c2.real("YH"), c2.real("ZH")};
  w.friction = c2.real("FRIC");
  w.loc = c1.loc();
  read_shape(r.card("shape"), w);
  if (const Row& mo = r.card("motion"); mo.present()) {
    w.motion_curve = mo.integer("LCID");
    w.motion_is_displacement = mo.integer("OPT") == 1;
    w.motion_direction = {mo.real("VX"), mo.real("VY"), mo.real("VZ")};
    w.motion_loc = mo.loc();
    const auto& v = w.motion_direction;
    if (std::hypot(v[0], v[1], v[2]) == 0.0)
      r.diags().error(mo.loc("VX"), "{}: the direction of the motion (VX VY VZ) is zero",
                      r.display_name());
  }
  const double nx = w.head[0] - w.tail[0], ny = w.head[1] - w.tail[1], nz = w.head[2] - w.tail[2];
  if (std::hypot(nx, ny, nz) == 0.0 && w.shape != model::WallShape::sphere)
    r.diags().error(c2.loc(), "{}: the normal (head - tail) is zero", r.display_name());
  m.rigid_walls.push_back(w);
}

}  // namespace mcdyna::deck::builders
