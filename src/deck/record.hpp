#pragma once
/// Typed reading of one keyword block against its schema: cards are matched to data lines
/// (conditions, optional cards, repeated groups, forms), fields are parsed once into values with
/// their deck location, defaults applied and constraints checked. Builders read from here.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.hpp"
#include "deck/deck.hpp"
#include "deck/schema.hpp"

namespace mcdyna::deck {

inline constexpr int kMaxFieldsPerCard = 16;

struct FieldValue {
  enum class Kind : std::uint8_t { blank, integer, real, text };
  Kind kind = Kind::blank;  ///< blank: the deck left it empty (value holds the default)
  std::int64_t integer = 0;
  double real = 0.0;
  std::string_view text;
  std::uint16_t col_begin = 0;
  std::uint16_t col_end = 0;
};

/// One card as read: its spec, its data line (none if the card was absent) and field values.
class Row {
 public:
  Row() = default;
  [[nodiscard]] const CardSpec& spec() const { return *spec_; }
  [[nodiscard]] bool present() const { return line_ != nullptr; }  ///< false: all defaults
  [[nodiscard]] core::SourceLoc loc() const { return loc_; }
  [[nodiscard]] core::SourceLoc loc(int field) const;

  [[nodiscard]] std::int64_t integer(int field) const { return values_[field].integer; }
  [[nodiscard]] double real(int field) const { return values_[field].real; }
  [[nodiscard]] std::string_view text(int field) const { return values_[field].text; }
  [[nodiscard]] bool blank(int field) const {
    return values_[field].kind == FieldValue::Kind::blank;
  }
  [[nodiscard]] const FieldValue& value(int field) const { return values_[field]; }

  /// Field index by LS-DYNA name; throws std::logic_error if the card has no such field (a
  /// builder/schema mismatch, caught by the schema tests).
  [[nodiscard]] int index(std::string_view name) const;
  [[nodiscard]] std::int64_t integer(std::string_view name) const { return integer(index(name)); }
  [[nodiscard]] double real(std::string_view name) const { return real(index(name)); }
  [[nodiscard]] std::string_view text(std::string_view name) const { return text(index(name)); }
  [[nodiscard]] bool blank(std::string_view name) const { return blank(index(name)); }
  [[nodiscard]] core::SourceLoc loc(std::string_view name) const { return loc(index(name)); }
  [[nodiscard]] std::string text_or_default(std::string_view name) const;

 private:
  friend class KeywordRecord;
  const CardSpec* spec_ = nullptr;
  const DataLine* line_ = nullptr;
  core::SourceLoc loc_;
  int count_ = 0;
  std::array<FieldValue, kMaxFieldsPerCard> values_{};
};

/// Rows of one repetition of a keyword's repeated cards (one node, one element, one curve point).
struct Group {
  std::vector<Row> rows;
  /// Row by card name; nullptr if the card was skipped by its condition or missing at the end.
  [[nodiscard]] const Row* card(std::string_view name) const;
};

class KeywordRecord {
 public:
  /// `display_name` is the keyword as written (upper case, with options) for messages.
  KeywordRecord(const Deck& deck, const KeywordBlock& block, const KeywordSchema& schema,
                std::vector<std::string> options, core::Diagnostics& diags);

  [[nodiscard]] const KeywordBlock& block() const { return block_; }
  [[nodiscard]] const KeywordSchema& schema() const { return schema_; }
  [[nodiscard]] const FormSpec& form() const { return *form_; }
  [[nodiscard]] bool has_option(std::string_view option) const;
  [[nodiscard]] core::Diagnostics& diags() const { return diags_; }
  /// "*SECTION_SOLID_SPG_TITLE" as written, for messages.
  [[nodiscard]] const std::string& display_name() const { return display_; }

  /// A head card by name. Always returns a row: an absent card (optional, or skipped by its
  /// condition) reads as defaults with present() == false.
  [[nodiscard]] const Row& card(std::string_view name) const;

  /// Reads the next repetition of the repeated cards; false when the block is exhausted.
  bool next_group(Group& group);

  /// Reads and validates whatever the builder did not consume, and reports surplus lines.
  void finish();

 private:
  void parse_row(const CardSpec& spec, const DataLine* line, Row& row, bool quiet) const;
  void fill_defaults(const CardSpec& spec, Row& row) const;
  /// `width`: the field's columns in fixed format (the reported range), 0 in free format.
  bool parse_field(const FieldSpec& f, std::string_view raw, int col, int width, Row& row,
                   int index, bool quiet) const;
  [[nodiscard]] bool condition_holds(const Condition& c, const Group* group,
                                     const DataLine* candidate) const;
  [[nodiscard]] double field_number(const std::string& name, const Group* group) const;
  void choose_form();

  const Deck& deck_;
  const KeywordBlock& block_;
  const KeywordSchema& schema_;
  std::vector<std::string> options_;
  core::Diagnostics& diags_;
  std::string display_;
  const FormSpec* form_ = nullptr;
  std::vector<Row> head_;
  std::uint32_t pos_ = 0;
  std::uint32_t content_end_ = 0;  ///< end of the block without its trailing blank lines
  mutable bool warned_wide_ = false;
};

}  // namespace mcdyna::deck
