#include "deck/parameters.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck {

std::uint32_t Parameters::new_scope(std::optional<std::uint32_t> parent) {
  scope_parent_.push_back(parent);
  local_.emplace_back();
  return static_cast<std::uint32_t>(scope_parent_.size() - 1);
}

void Parameters::define(Definition def, int duplication_flag, core::Diagnostics& diags) {
  auto& table = def.local ? local_.at(def.scope) : global_;
  const auto it = table.find(def.name);
  const int index = static_cast<int>(defs_.size());
  if (it == table.end()) {
    table.emplace(def.name, index);
    defs_.push_back(Entry{std::move(def), Entry::State::pending, {}});
    return;
  }
  // *PARAMETER_DUPLICATION DFLAG: 1 warn + keep first (default), 2 warn + accept new,
  // 3 error, 4 accept silently, 5 keep first silently.
  const std::uint32_t first_file_line = defs_[it->second].def.loc.line;
  switch (duplication_flag) {
    case 2:
      diags.warning(def.loc,
                    "parameter {} redefined (first defined at line {}); the new value is used",
                    def.name, first_file_line);
      [[fallthrough]];
    case 4:
      it->second = index;
      defs_.push_back(Entry{std::move(def), Entry::State::pending, {}});
      return;
    case 3:
      diags.error(def.loc, "parameter {} is defined twice (first at line {})", def.name,
                  first_file_line);
      return;
    case 5:
      return;
    default:
      diags.warning(def.loc,
                    "parameter {} redefined (first defined at line {}); the first value is kept "
                    "(*PARAMETER_DUPLICATION DFLAG=1)",
                    def.name, first_file_line);
      return;
  }
}

int Parameters::find(std::string_view upper_name, std::uint32_t scope) const {
  const std::string key(upper_name);
  std::optional<std::uint32_t> s = scope;
  while (s && *s < local_.size()) {
    if (auto it = local_[*s].find(key); it != local_[*s].end()) return it->second;
    s = scope_parent_[*s];
  }
  if (auto it = global_.find(key); it != global_.end()) return it->second;
  return -1;
}

namespace {

// The names an expression uses, in the order the evaluator resolves them. Where the parse goes
// does not depend on the values it reads, so a pass that records each name and answers 1 finds
// exactly the dependencies of the real evaluation.
std::vector<std::string> referenced_names(std::string_view text) {
  std::vector<std::string> names;
  std::string ignored;
  evaluate_expression(
      text,
      [&](const std::string& name) -> std::optional<double> {
        names.push_back(name);
        return 1.0;
      },
      ignored);
  return names;
}

}  // namespace

std::vector<int> Parameters::dependencies(int index) const {
  const Definition& def = defs_[static_cast<std::size_t>(index)].def;
  std::vector<int> deps;
  if (!def.expression || def.type == 'C') return deps;
  for (const std::string& name : referenced_names(trim(def.source))) {
    const int dep = find(name, def.scope);
    if (dep >= 0) deps.push_back(dep);
  }
  return deps;
}

void Parameters::compute(int index, core::Diagnostics& diags) {
  Entry& e = defs_[static_cast<std::size_t>(index)];
  e.value.type = e.def.type;
  bool ok = true;
  const std::string_view src = trim(e.def.source);
  if (e.def.type == 'C') {
    e.value.text = std::string(src);
  } else if (e.def.expression) {
    std::string error, blocked_by;  // blocked_by: a dependency that has an error of its own
    const auto v = evaluate_expression(
        src,
        [&](const std::string& name) -> std::optional<double> {
          const int dep = find(name, e.def.scope);
          if (dep < 0) return std::nullopt;  // the parser says "unknown parameter"
          const Entry& d = defs_[static_cast<std::size_t>(dep)];
          if (d.state != Entry::State::done || d.value.type == 'C') {
            if (blocked_by.empty()) blocked_by = name;
            return std::nullopt;
          }
          return d.value.number;
        },
        error);
    if (!v) {
      ok = false;
      if (!blocked_by.empty()) {
        const Entry& d = defs_[static_cast<std::size_t>(find(blocked_by, e.def.scope))];
        diags.error(e.def.loc, "parameter {}: cannot evaluate '{}': {} (line {}) {}", e.def.name,
                    core::excerpt(src), blocked_by, d.def.loc.line,
                    d.value.type == 'C' && d.state == Entry::State::done
                        ? "is a character parameter, not a number"
                        : "has an error");
      } else {
        diags.error(e.def.loc, "parameter {}: cannot evaluate '{}': {}", e.def.name,
                    core::excerpt(src), error);
      }
    } else {
      e.value.number = *v;
    }
  } else {
    const auto v = parse_real(src);
    if (!v) {
      diags.error(e.def.loc, "parameter {}: expected a number, got \"{}\"", e.def.name,
                  core::excerpt(src));
      ok = false;
    } else {
      e.value.number = *v;
    }
  }
  if (ok && e.def.type == 'I') e.value.number = std::trunc(e.value.number);
  e.state = ok ? Entry::State::done : Entry::State::failed;
}

// Depth first over the dependencies with an explicit stack: a chain of 10,000 parameters
// written in reverse order is 10,000 deep, far beyond what recursion on the call stack takes.
void Parameters::evaluate_from(int root, core::Diagnostics& diags) {
  struct Frame {
    int index;
    std::vector<int> deps;
    std::size_t next = 0;
  };
  std::vector<Frame> stack;
  auto enter = [&](int i) {
    defs_[static_cast<std::size_t>(i)].state = Entry::State::evaluating;
    stack.push_back(Frame{i, dependencies(i)});
  };
  enter(root);
  while (!stack.empty()) {
    Frame& top = stack.back();
    if (top.next == top.deps.size()) {
      if (defs_[static_cast<std::size_t>(top.index)].state == Entry::State::evaluating)
        compute(top.index, diags);
      stack.pop_back();
      continue;
    }
    const int dep = top.deps[top.next++];
    Entry& d = defs_[static_cast<std::size_t>(dep)];
    if (d.state == Entry::State::pending) {
      enter(dep);  // `top` is not used after this
    } else if (d.state == Entry::State::evaluating) {
      // A cycle: `dep` is on the stack. Name it from `dep` to the top and back, at most a dozen.
      std::vector<std::string> path;
      bool in_cycle = false;
      for (const Frame& f : stack) {
        in_cycle = in_cycle || f.index == dep;
        if (in_cycle) path.push_back(defs_[static_cast<std::size_t>(f.index)].def.name);
      }
      if (path.size() > 12) {
        path.erase(path.begin() + 6, path.end() - 5);
        path.insert(path.begin() + 6, "...");
      }
      path.push_back(d.def.name);
      diags.error(d.def.loc, "parameter {} depends on itself: {}", d.def.name,
                  fmt::format("{}", fmt::join(path, " -> ")));
      d.state = Entry::State::failed;  // the others on the cycle fail as users of it
    }
  }
}

void Parameters::evaluate_all(core::Diagnostics& diags) {
  for (int i = 0; i < static_cast<int>(defs_.size()); ++i)
    if (defs_[static_cast<std::size_t>(i)].state == Entry::State::pending) evaluate_from(i, diags);
}

const ParameterValue* Parameters::lookup(std::string_view name, std::uint32_t scope) const {
  const int i = find(upper(name), scope);
  if (i < 0 || defs_[i].state != Entry::State::done) return nullptr;
  return &defs_[i].value;
}

}  // namespace mcdyna::deck
