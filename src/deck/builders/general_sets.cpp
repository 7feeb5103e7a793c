// *SET_NODE_GENERAL: its rules, applied in order once the whole deck is read (the parts,
// elements, boxes and sets they name may come after it). The set's nodes are then in ascending
// ID order.
#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

// The nodes of the elements whose part is in `parts` or whose ID is in `elements` (of one kind).
template <class Element>
void nodes_of_elements(const std::vector<Element>& list, const std::unordered_set<model::Id>& parts,
                       const std::unordered_set<model::Id>& elements, std::set<model::Id>& out) {
  for (const Element& e : list) {
    if (!parts.count(e.part) && !elements.count(e.id)) continue;
    for (const model::Id n : e.nodes)
      if (n != 0) out.insert(n);
  }
}

struct Resolver {
  const model::ModelDatabase& m;
  core::Diagnostics& d;

  // The nodes one rule names; false for an option mcdyna does not have.
  bool nodes(const model::SetRule& rule, const std::string& option, std::set<model::Id>& out) {
    const std::unordered_set<model::Id> ids(rule.ids.begin(), rule.ids.end());
    const std::unordered_set<model::Id> none;
    if (option == "ALL") {
      for (const model::Node& n : m.nodes)
        out.insert(n.id);
    } else if (option == "NODE") {
      out.insert(rule.ids.begin(), rule.ids.end());
    } else if (option == "PART" || option == "SET_PART") {
      std::unordered_set<model::Id> parts;
      if (option == "PART") {
        parts = ids;
      } else {
        for (const model::PartSet& ps : m.part_sets)
          if (ids.count(ps.id)) parts.insert(ps.parts.begin(), ps.parts.end());
      }
      nodes_of_elements(m.solids, parts, none, out);
      nodes_of_elements(m.shells, parts, none, out);
      nodes_of_elements(m.beams, parts, none, out);
    } else if (option == "BOX") {
      for (const model::Box& b : m.boxes) {
        if (!ids.count(b.id)) continue;
        for (const model::Node& n : m.nodes) {
          bool inside = true;
          for (int k = 0; k < 3; ++k)
            inside = inside && n.position[k] >= b.min[k] && n.position[k] <= b.max[k];
          if (inside) out.insert(n.id);
        }
      }
    } else if (option == "SHELL" || option == "SOLID" || option == "BEAM") {
      element_nodes(option, ids, out);
    } else if (option == "SET_SHELL" || option == "SET_SOLID" || option == "SET_BEAM") {
      const model::ElementSetKind kind = option == "SET_SOLID"  ? model::ElementSetKind::solid
                                         : option == "SET_BEAM" ? model::ElementSetKind::beam
                                                                : model::ElementSetKind::shell;
      std::unordered_set<model::Id> elements;
      for (const model::ElementSet& es : m.element_sets)
        if (es.kind == kind && ids.count(es.id))
          elements.insert(es.elements.begin(), es.elements.end());
      element_nodes(option.substr(4), elements, out);
    } else {
      return false;
    }
    return true;
  }

  void element_nodes(const std::string& kind, const std::unordered_set<model::Id>& elements,
                     std::set<model::Id>& out) const {
    const std::unordered_set<model::Id> none;
    if (kind == "SHELL") nodes_of_elements(m.shells, none, elements, out);
    if (kind == "SOLID") nodes_of_elements(m.solids, none, elements, out);
    if (kind == "BEAM") nodes_of_elements(m.beams, none, elements, out);
  }

  void resolve(model::NodeSet& s) {
    std::set<model::Id> result;
    for (const model::SetRule& rule : s.rules) {
      std::string option = rule.option;
      std::transform(option.begin(), option.end(), option.begin(),
                     [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      // D-options remove what the option adds (DNODE, DPART, DBOX, DSHELL, ...).
      const bool remove = option.size() > 1 && option[0] == 'D' &&
                          (option.substr(1) == "NODE" || option.substr(1) == "PART" ||
                           option.substr(1) == "BOX" || option.substr(1) == "SHELL" ||
                           option.substr(1) == "SOLID" || option.substr(1) == "BEAM");
      std::set<model::Id> named;
      if (!nodes(rule, remove ? option.substr(1) : option, named)) {
        d.error(rule.loc,
                "*SET_NODE_GENERAL {}: option {} is not supported (ALL, NODE, PART, BOX, SHELL, "
                "SOLID, BEAM, SET_PART, SET_SHELL, SET_SOLID, SET_BEAM; DNODE, DPART, DBOX, "
                "DSHELL, DSOLID, DBEAM)",
                s.id, rule.option);
        continue;
      }
      if (named.empty() && option != "ALL")
        d.warning(rule.loc, "*SET_NODE_GENERAL {}: {} names no node", s.id, rule.option);
      for (const model::Id n : named) {
        if (remove)
          result.erase(n);
        else
          result.insert(n);
      }
    }
    s.nodes.assign(result.begin(), result.end());
  }
};

}  // namespace

void resolve_general_node_sets(model::ModelDatabase& m, core::Diagnostics& d) {
  Resolver r{m, d};
  for (model::NodeSet& s : m.node_sets)
    if (!s.rules.empty()) r.resolve(s);
}

}  // namespace mcdyna::deck::builders
