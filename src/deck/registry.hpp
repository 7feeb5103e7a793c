#pragma once
/// All keyword schemas embedded at build time, name resolution (aliases and _OPTION suffixes) and
/// the classification of every keyword for the migration report.
#include <string>
#include <string_view>
#include <vector>

#include "deck/schema.hpp"

namespace mcdyna::deck {

enum class Support {
  supported,    ///< a schema exists; read into the model (or handled by the reader)
  no_effect,    ///< read; nothing in the run depends on it
  output_only,  ///< unsupported output request; the run is unaffected
  unsupported   ///< unsupported and it changes the physics
};

const char* support_name(Support s);

struct Classification {
  Support support = Support::unsupported;
  const KeywordSchema* schema = nullptr;  ///< for supported keywords
  std::vector<std::string> options;       ///< recognised option suffixes
  std::string reason;                     ///< why (no_effect, output_only, unsupported)
};

struct EmbeddedFile {
  const char* name;
  const char* text;
};

class Registry {
 public:
  /// Loads the schemas embedded in the binary. Throws SchemaError on a malformed schema.
  Registry();
  /// Loads from given files (tests).
  explicit Registry(const std::vector<EmbeddedFile>& files);

  [[nodiscard]] const std::vector<KeywordSchema>& schemas() const { return schemas_; }
  /// Schema by canonical name or alias (upper case, no options); nullptr if none.
  [[nodiscard]] const KeywordSchema* find(std::string_view name) const;
  /// Classifies a keyword name as written (upper case, without '*').
  [[nodiscard]] Classification classify(std::string_view name) const;
  /// The classification table file, for documentation.
  [[nodiscard]] const std::string& classification_text() const { return classification_text_; }
  /// Raw schema text by canonical name (for `mcdyna keywords NAME --raw`).
  [[nodiscard]] std::string_view schema_text(std::string_view name) const;

 private:
  struct Rule {
    std::string pattern;
    Support support;
    std::string reason;
  };
  void load(const std::vector<EmbeddedFile>& files);
  void resolve_cards_from();

  std::vector<KeywordSchema> schemas_;
  std::vector<std::string> texts_;
  std::vector<Rule> rules_;
  std::string classification_text_;
};

/// The files embedded by the build (keywords/*.kw and keywords/classification.txt).
const std::vector<EmbeddedFile>& embedded_keyword_files();

}  // namespace mcdyna::deck
