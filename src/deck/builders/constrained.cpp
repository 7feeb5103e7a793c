// *CONSTRAINED_EXTRA_NODES_NODE / _SET, *CONSTRAINED_RIGID_BODIES, *CONSTRAINED_NODAL_RIGID_BODY:
// what joins nodes and parts into rigid bodies (compile_rigid.cpp builds the bodies).
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

}  // namespace mcdyna::deck::builders
