// *SET_NODE_GENERAL and *SET_SHELL/SOLID/BEAM_GENERAL: their rules, applied in order once the
// whole deck is read (the parts, elements, boxes and sets they name may come after it). The
// set's members are then in ascending ID order, after the members a _COLLECT list of the same
// ID gave it.
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

// A rule's option in upper case.
std::string upper_option(const model::SetRule& rule) {
  std::string option = rule.option;
  std::transform(option.begin(), option.end(), option.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return option;
}

// What one rule names goes into the set, or out of it for a D-option.
void apply_rule(std::set<model::Id>& result, const std::set<model::Id>& named, bool remove) {
  for (const model::Id id : named) {
    if (remove)
      result.erase(id);
    else
      result.insert(id);
  }
}

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
    std::set<model::Id> result(s.nodes.begin(), s.nodes.end());
    for (const model::SetRule& rule : s.rules) {
      const std::string option = upper_option(rule);
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
      apply_rule(result, named, remove);
    }
    s.nodes.assign(result.begin(), result.end());
  }
};

const char* kind_name(model::ElementSetKind k) {
  switch (k) {
    case model::ElementSetKind::shell:
      return "SHELL";
    case model::ElementSetKind::solid:
      return "SOLID";
    case model::ElementSetKind::beam:
      return "BEAM";
  }
  return "?";
}

// Element sets: ALL, ELEM, PART, BOX (the element's centroid, the mean of its nodes, inside),
// SET (element sets of the same kind, resolved first when they are _GENERAL too), and DELEM,
// DPART, DBOX, DSET.
struct ElementResolver {
  model::ModelDatabase& m;
  core::Diagnostics& d;
  std::unordered_map<model::Id, model::Vec3> positions;
  std::vector<int> state;  // per element set: 0 to do, 1 being resolved, 2 done

  template <class Element>
  void members(const std::vector<Element>& list, const std::string& option,
               const std::unordered_set<model::Id>& ids, std::set<model::Id>& out) {
    for (const Element& e : list) {
      bool in = false;
      if (option == "ALL") {
        in = true;
      } else if (option == "ELEM") {
        in = ids.count(e.id) > 0;
      } else if (option == "PART") {
        in = ids.count(e.part) > 0;
      } else if (option == "BOX") {
        in = centroid_in_boxes(e.nodes, ids);
      }
      if (in) out.insert(e.id);
    }
  }

  template <std::size_t N>
  bool centroid_in_boxes(const std::array<model::Id, N>& nodes,
                         const std::unordered_set<model::Id>& boxes) {
    if (positions.empty())
      for (const model::Node& n : m.nodes)
        positions.emplace(n.id, n.position);
    model::Vec3 c{};
    std::size_t count = 0;
    for (const model::Id n : nodes) {
      const auto it = positions.find(n);
      if (n == 0 || it == positions.end()) continue;
      for (int k = 0; k < 3; ++k)
        c[static_cast<std::size_t>(k)] += it->second[static_cast<std::size_t>(k)];
      ++count;
    }
    if (count == 0) return false;
    for (const model::Box& b : m.boxes) {
      if (!boxes.count(b.id)) continue;
      bool inside = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const double x = c[k] / static_cast<double>(count);
        inside = inside && x >= b.min[k] && x <= b.max[k];
      }
      if (inside) return true;
    }
    return false;
  }

  void resolve(std::size_t index) {
    if (state[index] != 0) return;
    state[index] = 1;
    model::ElementSet& s = m.element_sets[index];
    std::set<model::Id> result(s.elements.begin(), s.elements.end());
    const std::string name = fmt::format("*SET_{}_GENERAL {}", kind_name(s.kind), s.id);
    for (const model::SetRule& rule : s.rules) {
      std::string option = upper_option(rule);
      const bool remove =
          option == "DELEM" || option == "DPART" || option == "DBOX" || option == "DSET";
      if (remove) option = option.substr(1);
      const std::unordered_set<model::Id> ids(rule.ids.begin(), rule.ids.end());
      std::set<model::Id> named;
      if (option == "SET") {
        for (std::size_t k = 0; k < m.element_sets.size(); ++k) {
          const model::ElementSet& other = m.element_sets[k];
          if (other.kind != s.kind || !ids.count(other.id) || k == index) continue;
          if (state[k] == 1) {
            d.error(rule.loc, "{}: SET {} refers back to this set", name, other.id);
            continue;
          }
          resolve(k);
          named.insert(other.elements.begin(), other.elements.end());
        }
      } else if (option == "ALL" || option == "ELEM" || option == "PART" || option == "BOX") {
        if (s.kind == model::ElementSetKind::shell) members(m.shells, option, ids, named);
        if (s.kind == model::ElementSetKind::solid) members(m.solids, option, ids, named);
        if (s.kind == model::ElementSetKind::beam) members(m.beams, option, ids, named);
      } else {
        d.error(rule.loc,
                "{}: option {} is not supported (ALL, ELEM, PART, BOX, SET; DELEM, DPART, DBOX, "
                "DSET)",
                name, rule.option);
        continue;
      }
      if (named.empty() && option != "ALL")
        d.warning(rule.loc, "{}: {} names no element", name, rule.option);
      apply_rule(result, named, remove);
    }
    s.elements.assign(result.begin(), result.end());
    state[index] = 2;
  }
};

}  // namespace

void resolve_general_sets(model::ModelDatabase& m, core::Diagnostics& d) {
  // Element sets first: a node set's SET_SHELL / SET_SOLID / SET_BEAM rules read them.
  ElementResolver e{m, d, {}, std::vector<int>(m.element_sets.size(), 0)};
  for (std::size_t k = 0; k < m.element_sets.size(); ++k)
    if (!m.element_sets[k].rules.empty()) e.resolve(k);
  Resolver r{m, d};
  for (model::NodeSet& s : m.node_sets)
    if (!s.rules.empty()) r.resolve(s);
}

}  // namespace mcdyna::deck::builders
