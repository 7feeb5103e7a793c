// Node, part and element sets in every form LS-DYNA writes them: _LIST (8 IDs a line),
// _GENERATE (first-last ranges, 4 a line), _GENERATE_INCREMENT (first, last, step a line),
// _COLUMN (an ID a line with attributes, which nothing here uses), _GENERAL (rules resolved once
// the deck is read, general_sets.cpp); _COLLECT sets of one ID add up into one set.
#include <string_view>

#include "deck/builders/builders.hpp"

namespace mcdyna::deck::builders {

namespace {

// No real deck generates more members from one range.
constexpr model::Id kMaxGenerated = 10'000'000;

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

// Adds first, first + step, ... up to last; false (and nothing added) for a range that is not
// increasing or too long.
bool add_range(model::Id first, model::Id last, model::Id step, std::vector<model::Id>& ids) {
  if (last < first || step <= 0 || (last - first) / step > kMaxGenerated) return false;
  for (model::Id n = first; n <= last; n += step)
    ids.push_back(n);
  return true;
}

// Reads "four first-last ranges per line" groups into `ids` (_GENERATE).
void read_id_ranges(KeywordRecord& r, model::Id set, std::vector<model::Id>& ids) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    const int b1 = row.index("B1BEG");
    for (int k = 0; k < 4; ++k) {
      const model::Id begin = row.integer(b1 + 2 * k), end = row.integer(b1 + 2 * k + 1);
      if (begin == 0 && end == 0) continue;
      if (!add_range(begin, end, 1, ids)) {
        r.diags().error(row.loc(b1 + 2 * k), "{} {}: range {}..{} is not a valid increasing range",
                        r.display_name(), set, begin, end);
      }
    }
  }
}

// Reads "first, last, increment" lines into `ids` (_GENERATE_INCREMENT).
void read_id_increments(KeywordRecord& r, model::Id set, std::vector<model::Id>& ids) {
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    const model::Id begin = row.integer("BBEG"), end = row.integer("BEND");
    const model::Id step = row.integer("INCR");
    if (begin == 0 && end == 0) continue;
    if (!add_range(begin, end, step, ids)) {
      r.diags().error(row.loc("BBEG"), "{} {}: block {}..{} by {} is not a valid increasing range",
                      r.display_name(), set, begin, end, step);
    }
  }
}

// Reads one ID a line (_COLUMN); the attributes after it are not used.
void read_id_column(KeywordRecord& r, std::vector<model::Id>& ids) {
  Group g;
  while (r.next_group(g))
    if (const model::Id id = g.rows.front().integer("ID"); id != 0) ids.push_back(id);
}

// Reads the rule cards of a _GENERAL set: an option and up to 7 IDs.
std::vector<model::SetRule> read_rules(KeywordRecord& r) {
  std::vector<model::SetRule> rules;
  Group g;
  while (r.next_group(g)) {
    const Row& row = g.rows.front();
    model::SetRule rule;
    rule.option = std::string(row.text("OPTION"));
    rule.loc = row.loc("OPTION");
    const int e1 = row.index("E1");
    for (int k = 0; k < 7; ++k)
      if (row.integer(e1 + k) != 0) rule.ids.push_back(row.integer(e1 + k));
    rules.push_back(std::move(rule));
  }
  if (rules.empty()) r.diags().error(r.card("1").loc(), "{}: no rule card", r.display_name());
  return rules;
}

bool ends_with(std::string_view name, std::string_view tail) {
  return name.size() >= tail.size() && name.substr(name.size() - tail.size()) == tail;
}

// The members of a set keyword, by its form (the schema's name says which).
void read_members(KeywordRecord& r, model::Id set, std::vector<model::Id>& ids,
                  std::vector<model::SetRule>& rules, std::string_view list_field) {
  const std::string& name = r.schema().name;
  if (ends_with(name, "_GENERATE_INCREMENT")) {
    read_id_increments(r, set, ids);
  } else if (ends_with(name, "_GENERATE")) {
    read_id_ranges(r, set, ids);
  } else if (ends_with(name, "_COLUMN")) {
    read_id_column(r, ids);
  } else if (ends_with(name, "_GENERAL")) {
    std::vector<model::SetRule> read = read_rules(r);
    rules.insert(rules.end(), read.begin(), read.end());
  } else {
    read_id_lines(r, ids, list_field);
  }
}

// The set a keyword fills: a new one, or for _COLLECT the earlier _COLLECT set of its ID (and
// kind) when there is one. Two sets of one ID that are not both _COLLECT stay apart, for the
// duplicate-ID check to report.
template <class Set, class Same>
Set& target(std::vector<Set>& sets, KeywordRecord& r, Same same) {
  const Row& c1 = r.card("1");
  const bool collect = r.has_option("COLLECT");
  if (collect) {
    for (Set& s : sets)
      if (s.collect && s.id == c1.integer("SID") && same(s)) return s;
  }
  Set s;
  s.id = c1.integer("SID");
  s.collect = collect;
  s.loc = c1.loc();
  sets.push_back(std::move(s));
  return sets.back();
}

model::ElementSetKind element_set_kind(const std::string& name) {
  if (name.rfind("SET_SOLID", 0) == 0) return model::ElementSetKind::solid;
  if (name.rfind("SET_BEAM", 0) == 0) return model::ElementSetKind::beam;
  return model::ElementSetKind::shell;
}

}  // namespace

void set_node(KeywordRecord& r, model::ModelDatabase& m) {
  model::NodeSet& s = target(m.node_sets, r, [](const model::NodeSet&) { return true; });
  read_members(r, s.id, s.nodes, s.rules, "NID1");
}

void set_part(KeywordRecord& r, model::ModelDatabase& m) {
  model::PartSet& s = target(m.part_sets, r, [](const model::PartSet&) { return true; });
  std::vector<model::SetRule> no_rules;  // *SET_PART_GENERAL is not read
  read_members(r, s.id, s.parts, no_rules, "PID1");
}

void set_element(KeywordRecord& r, model::ModelDatabase& m) {
  const model::ElementSetKind kind = element_set_kind(r.schema().name);
  model::ElementSet& s =
      target(m.element_sets, r, [&](const model::ElementSet& e) { return e.kind == kind; });
  s.kind = kind;
  read_members(r, s.id, s.elements, s.rules, "K1");
}

}  // namespace mcdyna::deck::builders
