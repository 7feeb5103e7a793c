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

}  // namespace mcdyna::deck::builders
