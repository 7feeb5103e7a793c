#include "deck/record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck {

namespace {

std::string_view type_name(FieldType t) {
  switch (t) {
    case FieldType::integer:
      return "an integer";
    case FieldType::real:
      return "a real number";
    case FieldType::text:
      return "text";
  }
  return "a value";
}

// Values separated by blanks inside one fixed-width field: say how cards are laid out.
std::string blank_hint(std::string_view s) {
  return s.find(' ') != std::string_view::npos
             ? " (values separated by blanks: fixed-format fields sit in their columns; use "
               "commas for free format)"
             : "";
}

}  // namespace

core::SourceLoc Row::loc(int field) const {
  const FieldValue& v = values_[field];
  if (line_ == nullptr || v.col_begin == 0) return loc_;
  return loc_.with_columns(v.col_begin, v.col_end);
}

int Row::index(std::string_view name) const {
  const int i = spec_->field_index(name);
  if (i < 0) {
    throw std::logic_error(fmt::format("card '{}' has no field '{}'", spec_->name, name));
  }
  return i;
}

std::string Row::text_or_default(std::string_view name) const {
  const int i = index(name);
  return std::string(blank(i) ? std::string_view(spec_->fields[i].default_text) : text(i));
}

const Row* Group::card(std::string_view name) const {
  for (const Row& r : rows) {
    if (r.spec().name == name) return &r;
  }
  return nullptr;
}

KeywordRecord::KeywordRecord(const Deck& deck, const KeywordBlock& block,
                             const KeywordSchema& schema, std::vector<std::string> options,
                             core::Diagnostics& diags)
    : deck_(deck), block_(block), schema_(schema), options_(std::move(options)), diags_(diags) {
  display_ = "*" + block.name;
  pos_ = block.first_line;
  // Trailing blank lines carry nothing: a blank optional card equals its defaults, and they end a
  // repeated table. Blank lines before that are cards (all fields default).
  content_end_ = block.end_line;
  while (content_end_ > block.first_line && trim(deck_.lines[content_end_ - 1].text).empty()) {
    --content_end_;
  }
  choose_form();
  for (const CardSpec& spec : form_->head) {
    Row row;
    if (!condition_holds(spec.condition, nullptr,
                         pos_ < block_.end_line ? &deck_.lines[pos_] : nullptr)) {
      fill_defaults(spec, row);
    } else if (pos_ < block_.end_line) {
      parse_row(spec, &deck_.lines[pos_++], row, false);
    } else {
      if (!spec.optional) {
        diags_.error(block_.loc, "{}: card {} is missing (the keyword ends before it)", display_,
                     spec.name);
      }
      fill_defaults(spec, row);
    }
    head_.push_back(row);
  }
}

void KeywordRecord::choose_form() {
  const FormSpec* fallback = nullptr;
  for (const FormSpec& form : schema_.forms) {
    if (form.when_present_field.empty()) {
      if (fallback == nullptr) fallback = &form;
      continue;
    }
    const CardSpec& first = form.head.empty() ? form.repeat.front() : form.head.front();
    const int f = first.field_index(form.when_present_field);
    if (f < 0 || pos_ >= block_.end_line) continue;
    Row probe;
    parse_row(first, &deck_.lines[pos_], probe, true);
    if (!probe.blank(f)) {
      form_ = &form;
      return;
    }
  }
  form_ = fallback != nullptr ? fallback : &schema_.forms.front();
}

bool KeywordRecord::has_option(std::string_view option) const {
  return std::find(options_.begin(), options_.end(), option) != options_.end();
}

const Row& KeywordRecord::card(std::string_view name) const {
  for (const Row& r : head_) {
    if (r.spec().name == name) return r;
  }
  throw std::logic_error(fmt::format("{} has no head card '{}'", display_, name));
}

bool KeywordRecord::next_group(Group& group) {
  group.rows.clear();
  if (form_->repeat.empty() || pos_ >= content_end_) return false;
  for (const CardSpec& spec : form_->repeat) {
    const DataLine* candidate = pos_ < block_.end_line ? &deck_.lines[pos_] : nullptr;
    if (!condition_holds(spec.condition, &group, candidate)) continue;
    if (candidate == nullptr) {
      if (!spec.optional) {
        const DataLine& last = deck_.lines[pos_ - 1];
        diags_.error(last.loc(), "{}: card {} is missing after this line (the keyword ends)",
                     display_, spec.name);
      }
      break;
    }
    group.rows.emplace_back();
    parse_row(spec, candidate, group.rows.back(), false);
    ++pos_;
  }
  return true;
}

void KeywordRecord::finish() {
  Group g;
  while (next_group(g)) {
  }
  if (pos_ < content_end_) {
    diags_.warning(deck_.lines[pos_].loc(), "{}: {} more line(s) than the keyword's cards; ignored",
                   display_, content_end_ - pos_);
  }
  pos_ = block_.end_line;
}

void KeywordRecord::fill_defaults(const CardSpec& spec, Row& row) const {
  row.spec_ = &spec;
  row.line_ = nullptr;
  row.loc_ = block_.loc;
  row.count_ = static_cast<int>(spec.fields.size());
  for (int i = 0; i < row.count_; ++i) {
    const FieldSpec& f = spec.fields[i];
    FieldValue& v = row.values_[i];
    v = FieldValue{};
    v.real = f.default_number;
    // Real fields default to numbers such as 1e21 (MAT_024 FAIL) that no integer holds.
    v.integer =
        std::fabs(f.default_number) < 9.0e18 ? static_cast<std::int64_t>(f.default_number) : 0;
    v.text = f.default_text;
  }
}

void KeywordRecord::parse_row(const CardSpec& spec, const DataLine* line, Row& row,
                              bool quiet) const {
  fill_defaults(spec, row);
  row.line_ = line;
  row.loc_ = line->loc();
  const std::string_view text = line->text;
  const int n = row.count_;
  if (spec.is_text_line()) {
    const int w =
        block_.format == CardFormat::long_format ? 2 * spec.fields[0].width : spec.fields[0].width;
    parse_field(spec.fields[0], text.substr(0, std::min<std::size_t>(w, text.size())), 1, w, row, 0,
                quiet);
    return;
  }
  if (text.find(',') != std::string_view::npos) {
    // Free format: values by order, empty slots blank (keywords.md §1.4).
    std::size_t start = 0;
    int field = 0;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      const std::size_t end = comma == std::string_view::npos ? text.size() : comma;
      const std::string_view raw = text.substr(start, end - start);
      if (field < n) {
        parse_field(spec.fields[field], raw, static_cast<int>(start) + 1, 0, row, field, quiet);
      } else if (!trim(raw).empty() && !quiet) {
        diags_.error(line->loc().with_columns(static_cast<int>(start) + 1, static_cast<int>(end)),
                     "{} card {}: more values than its {} fields", display_, spec.name, n);
        break;
      }
      ++field;
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return;
  }
  if (!quiet && text.find('\t') != std::string_view::npos) {
    diags_.error(line->loc(),
                 "{} card {}: tab character in a fixed-column card; use spaces or commas", display_,
                 spec.name);
    return;
  }
  std::size_t offset = 0;
  for (int i = 0; i < n; ++i) {
    const int w = field_width(block_.format, spec.fields[i].width);
    if (offset >= text.size()) break;
    parse_field(spec.fields[i], text.substr(offset, w), static_cast<int>(offset) + 1, w, row, i,
                quiet);
    offset += static_cast<std::size_t>(w);
  }
  if (!quiet && offset < text.size() && !trim(text.substr(offset)).empty() && !warned_wide_) {
    warned_wide_ = true;
    diags_.warning(
        line->loc().with_columns(static_cast<int>(offset) + 1, static_cast<int>(text.size())),
        "{} card {}: text beyond column {} is ignored{}", display_, spec.name, offset,
        block_.format == CardFormat::standard ? " (long format needs *KEYWORD LONG=Y)" : "");
  }
}

bool KeywordRecord::parse_field(const FieldSpec& f, std::string_view raw, int col, int width,
                                Row& row, int index, bool quiet) const {
  FieldValue& v = row.values_[index];
  const std::size_t span =
      width > 0 ? static_cast<std::size_t>(width) : std::max<std::size_t>(raw.size(), 1);
  v.col_begin = static_cast<std::uint16_t>(std::min(col, 65535));
  v.col_end = static_cast<std::uint16_t>(std::min<std::size_t>(col + span - 1, 65535));
  const core::SourceLoc at = row.loc_.with_columns(v.col_begin, v.col_end);
  std::string_view s = trim(raw);
  auto report = [&](std::string message) {
    if (!quiet)
      diags_.error(at, "{} card {} field {}: {}", display_, row.spec_->name, f.name, message);
    return false;
  };
  if (s.empty()) {
    if (f.default_kind == DefaultKind::required) return report("a value is required");
    return true;
  }
  // Parameter reference: &name or -&name fills the field (keywords.md §1.10).
  double sign = 1.0;
  const ParameterValue* param = nullptr;
  std::string_view param_name;
  if (s[0] == '&' || (s.size() > 1 && s[0] == '-' && s[1] == '&')) {
    sign = s[0] == '-' ? -1.0 : 1.0;
    param_name = s.substr(s[0] == '-' ? 2 : 1);
    param = deck_.parameters.lookup(param_name, block_.scope);
    if (param == nullptr) return report(fmt::format("parameter &{} is not defined", param_name));
  }
  if (f.type == FieldType::text) {
    v.kind = FieldValue::Kind::text;
    v.text = param != nullptr && param->type == 'C' ? std::string_view(param->text) : s;
    return true;
  }
  double number = 0.0;
  if (param != nullptr) {
    if (param->type == 'C') {
      return report(fmt::format("parameter &{} is text (\"{}\"), expected {}", param_name,
                                param->text, type_name(f.type)));
    }
    number = sign * param->number;
    if (f.type == FieldType::integer && number != std::trunc(number)) {
      return report(fmt::format("parameter &{} = {} is not an integer", param_name, number));
    }
  } else if (f.type == FieldType::integer) {
    const auto i = parse_integer(s);
    if (!i)
      return report(
          fmt::format("expected an integer, got \"{}\"{}", core::excerpt(s), blank_hint(s)));
    number = static_cast<double>(*i);
  } else {
    const auto r = parse_real(s);
    if (!r)
      return report(
          fmt::format("expected a real number, got \"{}\"{}", core::excerpt(s), blank_hint(s)));
    number = *r;
  }
  if (f.zero_means_default && number == 0.0) return true;  // "EQ.0: default" fields stay default
  // A value outside the field's allowed set is reported and the field keeps its default: the
  // builders index tables by such codes (KERNEL 5 read past kSmstepDefault[3]).
  if (!f.constraint.allows(number)) {
    return report(fmt::format("value {} is not allowed (must be {})", core::excerpt(s),
                              f.constraint.describe()));
  }
  if (f.type == FieldType::integer) {
    if (std::fabs(number) > 9.0e18) return report("integer out of range");
    v.integer = static_cast<std::int64_t>(number);
    v.kind = FieldValue::Kind::integer;
    v.real = static_cast<double>(v.integer);
  } else {
    v.kind = FieldValue::Kind::real;
    v.real = number;
  }
  return true;
}

double KeywordRecord::field_number(const std::string& name, const Group* group) const {
  if (group != nullptr) {
    for (auto it = group->rows.rbegin(); it != group->rows.rend(); ++it) {
      const int i = it->spec().field_index(name);
      if (i >= 0) return it->real(i);
    }
  }
  for (const Row& r : head_) {
    const int i = r.spec().field_index(name);
    if (i >= 0) return r.real(i);
  }
  const FieldSpec* f = schema_.find_field(name);
  return f != nullptr ? f->default_number : 0.0;
}

bool KeywordRecord::condition_holds(const Condition& c, const Group* group,
                                    const DataLine* candidate) const {
  if (c.always()) return true;
  for (const auto& all_of : c.any_of) {
    bool ok = true;
    for (const ConditionTerm& t : all_of) {
      switch (t.kind) {
        case ConditionTerm::Kind::option:
          ok = has_option(t.name);
          break;
        case ConditionTerm::Kind::no_option:
          ok = !has_option(t.name);
          break;
        case ConditionTerm::Kind::first_char: {
          const std::string_view s = candidate != nullptr ? trim(candidate->text) : "";
          ok = !s.empty() && s[0] == t.character;
          break;
        }
        case ConditionTerm::Kind::in_set: {
          double v = field_number(t.name, group);
          if (t.absolute) v = std::fabs(v);
          ok = t.set.allows(v);
          break;
        }
        case ConditionTerm::Kind::compare: {
          double v = field_number(t.name, group);
          if (t.absolute) v = std::fabs(v);
          ok = t.op == "<"    ? v < t.value
               : t.op == "<=" ? v <= t.value
               : t.op == ">"  ? v > t.value
               : t.op == ">=" ? v >= t.value
               : t.op == "==" ? v == t.value
                              : v != t.value;
          break;
        }
      }
      if (!ok) break;
    }
    if (ok) return true;
  }
  return false;
}

}  // namespace mcdyna::deck
