// The *CONTACT_ keywords share one card layout (keywords.md §2.15) and one builder.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

model::ContactKind kind_of(std::string_view schema_name) {
  using K = model::ContactKind;
  if (schema_name == "CONTACT_AUTOMATIC_NODES_TO_SURFACE") return K::automatic_nodes_to_surface;
  if (schema_name == "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE") return K::automatic_surface_to_surface;
  if (schema_name == "CONTACT_AUTOMATIC_SINGLE_SURFACE") return K::automatic_single_surface;
  if (schema_name == "CONTACT_NODES_TO_SURFACE") return K::nodes_to_surface;
  if (schema_name == "CONTACT_FORCE_TRANSDUCER_PENALTY") return K::force_transducer;
  if (schema_name == "CONTACT_TIED_NODES_TO_SURFACE" ||
      schema_name == "CONTACT_TIED_SURFACE_TO_SURFACE")
    return K::tied;
  return K::surface_to_surface;
}

}  // namespace

void contact(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& id = r.card("id");
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  const Row& ca = r.card("A");
  const Row& cc = r.card("C");
  model::Contact c;
  c.kind = kind_of(r.schema().name);
  c.keyword = keyword_after(r, "CONTACT_");
  c.id = id.integer("CID");
  c.heading = std::string(id.text("HEADING"));
  c.a = {c1.integer("SURFA"), static_cast<int>(c1.integer("SURFATYP")), c1.integer("SABOXID")};
  c.b = {c1.integer("SURFB"), static_cast<int>(c1.integer("SURFBTYP")), c1.integer("SBBOXID")};
  c.static_friction = c2.real("FS");
  c.dynamic_friction = c2.real("FD");
  c.decay = c2.real("DC");
  c.viscous_friction = c2.real("VC");
  c.viscous_damping = c2.real("VDC");
  c.birth = c2.real("BT");
  c.death = c2.real("DT");
  c.penalty_scale_a = c3.real("SFSA");
  c.penalty_scale_b = c3.real("SFSB");
  c.thickness_a = c3.real("SAST");
  c.thickness_b = c3.real("SBST");
  c.friction_scale = c3.real("FSF");
  c.viscous_friction_scale = c3.real("VSF");
  c.soft = static_cast<int>(ca.integer("SOFT"));
  c.soft_scale = ca.real("SOFSCL");
  c.depth = static_cast<double>(ca.integer("DEPTH"));
  c.ignore_penetration = static_cast<int>(cc.integer("IGNORE"));
  c.loc = c1.loc();
  const bool single = c.kind == model::ContactKind::automatic_single_surface;
  // A transducer's side B is optional: without it every other contact's force on side A counts.
  const bool transducer = c.kind == model::ContactKind::force_transducer;
  if (c.a.type == 7 || c.b.type == 7) {
    r.diags().error(c1.loc(c.a.type == 7 ? "SURFATYP" : "SURFBTYP"),
                    "{}: type 7 (*SET_PART_TREE "
                    "branch) is not supported",
                    r.display_name());
  }
  if (!single && !transducer && c.b.type == 4) {
    r.diags().error(c1.loc("SURFBTYP"),
                    "{}: side B must be a surface (segment set, shell set, "
                    "part or part set), not a node set",
                    r.display_name());
  }
  if (c.static_friction == -1.0) {
    r.diags().error(c2.loc("FS"), "{}: FS = -1 (*PART_CONTACT friction) is not supported",
                    r.display_name());
  } else if (c.static_friction < 0.0) {
    r.diags().error(c2.loc("FS"), "{}: static friction FS = {} must be >= 0", r.display_name(),
                    c.static_friction);
  }
  if (c.soft == 4 || c.soft == 6) {
    r.diags().error(ca.loc("SOFT"),
                    "{}: SOFT = {} is not supported (0 standard penalty, 1 soft "
                    "constraint, 2 segment-based)",
                    r.display_name(), c.soft);
  }
  if (!single && !transducer && c.b.type != 5 && c.b.id == 0) {
    r.diags().error(c1.loc("SURFB"), "{}: side B (SURFB) is not given", r.display_name());
  }
  if (c.a.type != 5 && c.a.id == 0 && !single) {
    r.diags().error(c1.loc("SURFA"), "{}: side A (SURFA) is not given", r.display_name());
  }
  m.contacts.push_back(std::move(c));
}

}  // namespace mcdyna::deck::builders
