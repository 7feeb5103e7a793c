#include "deck/parameters.hpp"

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

bool Parameters::evaluate(int index, core::Diagnostics& diags) {
  Entry& e = defs_[index];  // stays valid: defs_ does not grow during evaluation
  if (e.state == Entry::State::done) return true;
  if (e.state == Entry::State::failed) return false;
  if (e.state == Entry::State::evaluating) {
    diags.error(e.def.loc, "parameter {} depends on itself", e.def.name);
    e.state = Entry::State::failed;
    return false;
  }
  e.state = Entry::State::evaluating;
  e.value.type = e.def.type;
  bool ok = true;
  const std::string_view src = trim(e.def.source);
  if (e.def.type == 'C') {
    e.value.text = std::string(src);
  } else if (e.def.expression) {
    std::string error;
    const std::uint32_t scope = e.def.scope;
    const std::function<std::optional<double>(const std::string&)> resolve =
        [&](const std::string& name) -> std::optional<double> {
      const int dep = find(name, scope);
      if (dep < 0 || !evaluate(dep, diags) || defs_[dep].value.type == 'C') return std::nullopt;
      return defs_[dep].value.number;
    };
    const auto v = evaluate_expression(src, resolve, error);
    if (!v) {
      if (e.state != Entry::State::failed) {
        diags.error(e.def.loc, "parameter {}: cannot evaluate '{}': {}", e.def.name, src, error);
      }
      ok = false;
    } else {
      e.value.number = *v;
    }
  } else {
    const auto v = parse_real(src);
    if (!v) {
      diags.error(e.def.loc, "parameter {}: expected a number, got \"{}\"", e.def.name, src);
      ok = false;
    } else {
      e.value.number = *v;
    }
  }
  if (ok && e.def.type == 'I') e.value.number = std::trunc(e.value.number);
  e.state = ok ? Entry::State::done : Entry::State::failed;
  return ok;
}

void Parameters::evaluate_all(core::Diagnostics& diags) {
  for (int i = 0; i < static_cast<int>(defs_.size()); ++i)
    evaluate(i, diags);
}

const ParameterValue* Parameters::lookup(std::string_view name, std::uint32_t scope) const {
  const int i = find(upper(name), scope);
  if (i < 0 || defs_[i].state != Entry::State::done) return nullptr;
  return &defs_[i].value;
}

}  // namespace mcdyna::deck
