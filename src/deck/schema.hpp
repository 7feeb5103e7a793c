#pragma once
/// Declarative keyword card layouts, loaded from keywords/*.kw (see keywords/README.md).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mcdyna::deck {

enum class FieldType { integer, real, text };

/// How a blank field is filled.
enum class DefaultKind {
  required,  ///< blank is an error
  blank,     ///< no default: numeric fields read as 0, the builder can ask whether it was blank
  value      ///< the documented default value
};

/// Allowed values of a numeric field: a comparison (> 0, >= 1 …) or a set of values and ranges.
struct Constraint {
  enum class Kind { none, greater, greater_equal, less, less_equal, not_equal, one_of };
  Kind kind = Kind::none;
  double bound = 0.0;
  std::vector<std::pair<double, double>> ranges;  ///< one_of: closed ranges (a value is a..a)

  [[nodiscard]] bool allows(double v) const;
  [[nodiscard]] std::string describe() const;  ///< "> 0", "one of {0, 1, 2}"
};

struct FieldSpec {
  std::string name;  ///< LS-DYNA field name, upper case (RO, TM, ITB)
  FieldType type = FieldType::real;
  int width = 10;  ///< columns in standard format
  DefaultKind default_kind = DefaultKind::blank;
  double default_number = 0.0;
  std::string default_text;
  bool zero_means_default = false;  ///< "EQ.0: default is …" fields
  Constraint constraint;
  std::string dimension;  ///< physical dimension (length, stress, …) or "-"
  std::string description;
};

/// One term of a card condition; a condition is an OR of AND-groups of terms.
struct ConditionTerm {
  enum class Kind { option, no_option, compare, in_set, first_char };
  Kind kind = Kind::option;
  std::string name;       ///< option name or field name
  bool absolute = false;  ///< abs(FIELD)
  std::string op;         ///< <, <=, >, >=, ==, !=
  double value = 0.0;
  Constraint set;      ///< in_set
  char character = 0;  ///< first_char: first non-blank character of the candidate line
};

struct Condition {
  std::vector<std::vector<ConditionTerm>> any_of;  ///< empty = always
  [[nodiscard]] bool always() const { return any_of.empty(); }
  [[nodiscard]] std::string text() const;  ///< as written in the schema
  std::string source_text;
};

struct CardSpec {
  std::string name;  ///< "1", "2", "A", "title", "node" …
  std::vector<FieldSpec> fields;
  Condition condition;
  bool optional = false;  ///< may be missing when the keyword ends
  /// A single text field wider than 20 columns (titles, file names): commas are data, not
  /// free-format separators, and long format does not change it.
  [[nodiscard]] bool is_text_line() const;
  [[nodiscard]] int field_index(std::string_view field_name) const;  ///< -1 if absent
};

/// One layout of a keyword. Most keywords have one form; *ELEMENT_SOLID has the two-line and the
/// legacy one-line form, chosen on the first data line.
struct FormSpec {
  std::string name;
  std::string when_present_field;  ///< chosen if this field of the first card is non-blank
  std::vector<CardSpec> head;      ///< cards read once
  std::vector<CardSpec> repeat;    ///< cards read as a group until the keyword ends
};

struct KeywordSchema {
  std::string name;  ///< canonical name without '*'
  std::vector<std::string> aliases;
  std::vector<std::string> options;  ///< accepted suffixes (TITLE, ID, MPP …)
  std::string group;                 ///< section of the keyword reference (material, control, …)
  std::string summary;               ///< one line
  std::string source;                ///< where the layout comes from
  std::string handler = "builder";   ///< "builder" (model builder) or "reader" (lexer handles it)
  std::vector<FormSpec> forms;
  std::string cards_from;  ///< "cards-from NAME": forms copied from that schema by the registry
  std::string file;        ///< schema file name, for messages

  [[nodiscard]] bool has_option(std::string_view option) const;
  /// Finds a field spec by name in any card of any form; nullptr if absent.
  [[nodiscard]] const FieldSpec* find_field(std::string_view field_name) const;
};

/// Parses one schema file. Throws SchemaError naming file:line on a malformed schema (a build
/// defect, caught by the schema test, never a user-facing deck error).
KeywordSchema parse_schema(std::string_view file_name, std::string_view text);

struct SchemaError : std::exception {
  std::string message;
  explicit SchemaError(std::string m) : message(std::move(m)) {}
  [[nodiscard]] const char* what() const noexcept override { return message.c_str(); }
};

/// Known physical dimensions; the schema loader rejects others so that units stay consistent.
bool is_known_dimension(std::string_view dimension);

}  // namespace mcdyna::deck
