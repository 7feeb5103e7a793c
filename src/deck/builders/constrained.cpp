// *CONSTRAINED_EXTRA_NODES_NODE / _SET, *CONSTRAINED_RIGID_BODIES, *CONSTRAINED_NODAL_RIGID_BODY:
// what joins nodes and parts into rigid bodies (compile_rigid.cpp builds the bodies).
#include <utility>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

void constrained_extra_nodes(KeywordRecord& r, model::ModelDatabase& m) {
  const bool is_set = r.schema().name == "CONSTRAINED_EXTRA_NODES_SET";
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    m.extra_nodes.push_back(
        {row.integer("PID"), row.integer(is_set ? "NSID" : "NID"), is_set, row.loc()});
  }
}

void constrained_rigid_bodies(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    m.rigid_merges.push_back({row.integer("PIDL"), row.integer("PIDC"), row.loc()});
  }
}

void constrained_nodal_rigid_body(KeywordRecord& r, model::ModelDatabase& m) {
  const std::string title = title_of(r);
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    m.nodal_rigid_bodies.push_back(
        {row.integer("PID"), row.integer("NSID"), title, row.loc(), row.loc("NSID")});
  }
}

// *CONSTRAINED_SPOTWELD (one pair per line) and *CONSTRAINED_GENERALIZED_WELD_SPOT (a set).
void constrained_spotweld(KeywordRecord& r, model::ModelDatabase& m) {
  const bool generalized = r.schema().name == "CONSTRAINED_GENERALIZED_WELD_SPOT";
  Group g;
  while (r.next_group(g)) {
    const Row* head = g.card("1");
    if (head == nullptr) break;
    model::SpotWeld w;
    if (const Row* id = g.card("id")) w.id = id->integer("WID");
    w.loc = head->loc();
    const Row* fail = generalized ? g.card("2") : head;
    if (generalized) {
      w.node_set = head->integer("NSID");
      if (fail == nullptr) {
        r.diags().error(head->loc(), "{}: card 2 (the failure card) is missing", r.display_name());
        break;
      }
    } else {
      w.nodes = {head->integer("N1"), head->integer("N2")};
    }
    w.normal_force = fail->real("SN");
    w.shear_force = fail->real("SS");
    w.normal_exponent = fail->real("N");
    w.shear_exponent = fail->real("M");
    w.failure_time = fail->real(generalized ? "TFAIL" : "TF");
    w.plastic_strain = fail->real(generalized ? "EPSF" : "EP");
    for (const auto& [force, exponent] : {std::pair{"SN", "N"}, std::pair{"SS", "M"}}) {
      if (fail->real(force) > 0.0 && !(fail->real(exponent) > 0.0)) {
        r.diags().error(fail->loc(exponent),
                        "{}: {} = {:g} needs its exponent {} > 0 (LS-DYNA documents no default)",
                        r.display_name(), force, fail->real(force), exponent);
      }
    }
    m.spot_welds.push_back(w);
  }
}

void constrained_joint(KeywordRecord& r, model::ModelDatabase& m) {
  const std::string& name = r.schema().name;
  const model::JointKind kind =
      name == "CONSTRAINED_JOINT_REVOLUTE"        ? model::JointKind::revolute
      : name == "CONSTRAINED_JOINT_CYLINDRICAL"   ? model::JointKind::cylindrical
      : name == "CONSTRAINED_JOINT_TRANSLATIONAL" ? model::JointKind::translational
                                                  : model::JointKind::spherical;
  const Row& id = r.card("id");
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::Joint j;
    j.id = id.integer("JID");
    j.heading = std::string(id.text("HEADING"));
    j.kind = kind;
    const int first = row.index("N1");
    for (int k = 0; k < 6; ++k)
      j.nodes[static_cast<std::size_t>(k)] = row.integer(first + k);
    j.relative_stiffness = row.real("RPS");
    j.damping = row.real("DAMP");
    j.loc = row.loc();
    // The pairs each kind needs: 1 spherical, 2 revolute and cylindrical, 3 translational.
    const int pairs = kind == model::JointKind::spherical       ? 1
                      : kind == model::JointKind::translational ? 3
                                                                : 2;
    for (int k = 0; k < 2 * pairs; ++k) {
      if (j.nodes[static_cast<std::size_t>(k)] == 0) {
        r.diags().error(row.loc(first + k), "{}: N{} is not given (this joint takes {} node pairs)",
                        r.display_name(), k + 1, pairs);
      }
    }
    m.joints.push_back(j);
  }
}

void joint_stiffness_generalized(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  const Row& c3 = r.card("3");
  model::JointStiffness j;
  j.id = c1.integer("JSID");
  j.part_a = c1.integer("PIDA");
  j.part_b = c1.integer("PIDB");
  j.system_a = c1.integer("CIDA");
  j.system_b = c1.integer("CIDB") != 0 ? c1.integer("CIDB") : j.system_a;
  const int curve = c2.index("LCIDPH"), elastic = c3.index("ESPH");
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    j.curves[i] = c2.integer(curve + k);
    j.elastic[i] = c3.real(elastic + 2 * k);
    j.friction[i] = c3.real(elastic + 2 * k + 1);
  }
  j.loc = c1.loc();
  m.joint_stiffnesses.push_back(j);
}

void define_coordinate_node(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c = r.card("1");
  model::CoordinateSystem cs;
  cs.id = c.integer("CID");
  for (int k = 0; k < 3; ++k)
    cs.nodes[static_cast<std::size_t>(k)] = c.integer(c.index("N1") + k);
  cs.loc = c.loc();
  const std::string dir(c.text("DIR"));
  if (!dir.empty() && dir != "X" && dir != "x") {
    r.diags().error(c.loc("DIR"), "{}: DIR = {} is not supported (X: N1 -> N2 is the x axis)",
                    r.display_name(), dir);
  }
  m.coordinate_systems.push_back(cs);
}

}  // namespace mcdyna::deck::builders
