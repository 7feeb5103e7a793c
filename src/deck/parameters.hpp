#pragma once
/// *PARAMETER, *PARAMETER_EXPRESSION and their _LOCAL variants: definitions, scopes, evaluation.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/diagnostics.hpp"

namespace mcdyna::deck {

/// A parameter's value once evaluated: R and I parameters are numbers, C parameters text.
struct ParameterValue {
  char type = 'R';  ///< 'R', 'I' or 'C'
  double number = 0.0;
  std::string text;
};

/// All parameters of a deck. Global parameters are visible everywhere (also before their
/// definition, as in LS-DYNA decks that define them in an include read later); local ones in the
/// file that defines them and the files it includes. Duplicates follow *PARAMETER_DUPLICATION.
class Parameters {
 public:
  /// Scope of one read file; `parent` is the including file's scope (root: none).
  std::uint32_t new_scope(std::optional<std::uint32_t> parent);

  struct Definition {
    std::string name;  ///< upper case, without type letter
    char type = 'R';
    std::string source;  ///< value text, or expression text
    bool expression = false;
    bool local = false;
    std::uint32_t scope = 0;
    core::SourceLoc loc;
  };
  /// Records a definition. `duplication_flag` is DFLAG of *PARAMETER_DUPLICATION (1 default).
  void define(Definition def, int duplication_flag, core::Diagnostics& diags);

  /// Evaluates every definition (expressions in dependency order), reporting errors once each.
  void evaluate_all(core::Diagnostics& diags);

  /// Value of `name` (case-insensitive, without '&') seen from `scope`; nullptr if undefined or
  /// its evaluation failed.
  [[nodiscard]] const ParameterValue* lookup(std::string_view name, std::uint32_t scope) const;

  [[nodiscard]] std::size_t size() const { return defs_.size(); }

 private:
  struct Entry {
    Definition def;
    enum class State { pending, evaluating, done, failed } state = State::pending;
    ParameterValue value;
  };
  [[nodiscard]] int find(std::string_view upper_name, std::uint32_t scope) const;
  /// The definitions an expression uses (indices into defs_), in the order it uses them.
  [[nodiscard]] std::vector<int> dependencies(int index) const;
  /// Evaluates `root` and everything it depends on that is still pending, in dependency order.
  void evaluate_from(int root, core::Diagnostics& diags);
  /// Evaluates one definition whose dependencies are all done or failed.
  void compute(int index, core::Diagnostics& diags);

  std::vector<Entry> defs_;
  std::vector<std::optional<std::uint32_t>> scope_parent_;
  std::unordered_map<std::string, int> global_;
  std::vector<std::unordered_map<std::string, int>> local_;  ///< per scope
};

/// Evaluates a *PARAMETER_EXPRESSION text. `resolve` maps a parameter name (upper case) to its
/// numeric value or nullopt. Returns nullopt and sets `error` on failure.
std::optional<double> evaluate_expression(
    std::string_view text, const std::function<std::optional<double>(const std::string&)>& resolve,
    std::string& error);

}  // namespace mcdyna::deck
