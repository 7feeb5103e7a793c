#include "deck/schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>

#include "deck/text_util.hpp"

namespace mcdyna::deck {

namespace {

constexpr std::array kDimensions{"-",
                                 "length",
                                 "time",
                                 "mass",
                                 "density",
                                 "stress",
                                 "velocity",
                                 "acceleration",
                                 "force",
                                 "energy",
                                 "temperature",
                                 "specific_heat",
                                 "strain_rate",
                                 "angular_velocity",
                                 "angle",
                                 "area",
                                 "energy_per_volume",
                                 "stiffness_per_length",
                                 "strain",
                                 "moment"};

struct LineCursor {
  std::string_view file;
  int line = 0;
  [[noreturn]] void fail(const std::string& what) const {
    throw SchemaError(fmt::format("keywords/{}:{}: {}", file, line, what));
  }
};

double parse_schema_number(const LineCursor& at, std::string_view token) {
  double value = 0.0;
  const auto* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end) at.fail(fmt::format("expected a number, got '{}'", token));
  return value;
}

// "{0,1,2,101..105}" -> closed ranges.
Constraint parse_set(const LineCursor& at, std::string_view token) {
  if (token.size() < 2 || token.front() != '{' || token.back() != '}') {
    at.fail(fmt::format("expected a value set like {{0,1,2}}, got '{}'", token));
  }
  Constraint c;
  c.kind = Constraint::Kind::one_of;
  for (std::string_view item : split(token.substr(1, token.size() - 2), ',')) {
    const auto dots = item.find("..");
    if (dots == std::string_view::npos) {
      const double v = parse_schema_number(at, item);
      c.ranges.emplace_back(v, v);
    } else {
      c.ranges.emplace_back(parse_schema_number(at, item.substr(0, dots)),
                            parse_schema_number(at, item.substr(dots + 2)));
    }
  }
  return c;
}

Constraint parse_constraint(const LineCursor& at, std::string_view token) {
  Constraint c;
  if (token == "-") return c;
  if (token.front() == '{') return parse_set(at, token);
  struct Op {
    std::string_view text;
    Constraint::Kind kind;
  };
  constexpr std::array ops{Op{">=", Constraint::Kind::greater_equal},
                           Op{"<=", Constraint::Kind::less_equal},
                           Op{"!=", Constraint::Kind::not_equal},
                           Op{">", Constraint::Kind::greater}, Op{"<", Constraint::Kind::less}};
  for (const Op& op : ops) {
    if (token.substr(0, op.text.size()) == op.text) {
      c.kind = op.kind;
      c.bound = parse_schema_number(at, token.substr(op.text.size()));
      return c;
    }
  }
  at.fail(fmt::format("unknown constraint '{}'", token));
}

ConditionTerm parse_term(const LineCursor& at, const std::vector<std::string_view>& tok,
                         std::size_t& i) {
  ConditionTerm t;
  auto need = [&](std::size_t k) {
    if (i + k >= tok.size()) at.fail("incomplete card condition");
  };
  need(1);
  if (tok[i] == "option") {
    t.kind = ConditionTerm::Kind::option;
    t.name = upper(tok[i + 1]);
    i += 2;
    return t;
  }
  if (tok[i] == "no-option") {
    t.kind = ConditionTerm::Kind::no_option;
    t.name = upper(tok[i + 1]);
    i += 2;
    return t;
  }
  if (tok[i] == "first-char") {
    t.kind = ConditionTerm::Kind::first_char;
    if (tok[i + 1].size() != 1) at.fail("first-char takes one character");
    t.character = tok[i + 1][0];
    i += 2;
    return t;
  }
  std::string_view field = tok[i];
  if (field.substr(0, 4) == "abs(" && field.back() == ')') {
    t.absolute = true;
    field = field.substr(4, field.size() - 5);
  }
  t.name = upper(field);
  need(2);
  if (tok[i + 1] == "in") {
    t.kind = ConditionTerm::Kind::in_set;
    t.set = parse_set(at, tok[i + 2]);
  } else {
    constexpr std::array ops{"<", "<=", ">", ">=", "==", "!="};
    if (std::find(ops.begin(), ops.end(), tok[i + 1]) == ops.end()) {
      at.fail(fmt::format("unknown comparison '{}'", tok[i + 1]));
    }
    t.kind = ConditionTerm::Kind::compare;
    t.op = std::string(tok[i + 1]);
    t.value = parse_schema_number(at, tok[i + 2]);
  }
  i += 3;
  return t;
}

Condition parse_condition(const LineCursor& at, const std::vector<std::string_view>& tok,
                          std::size_t i) {
  Condition c;
  for (std::size_t k = i; k < tok.size(); ++k) {
    if (!c.source_text.empty()) c.source_text += ' ';
    c.source_text += tok[k];
  }
  c.any_of.emplace_back();
  while (i < tok.size()) {
    c.any_of.back().push_back(parse_term(at, tok, i));
    if (i == tok.size()) break;
    if (tok[i] == "or") {
      c.any_of.emplace_back();
    } else if (tok[i] != "and") {
      at.fail(fmt::format("expected 'and' or 'or' in condition, got '{}'", tok[i]));
    }
    ++i;
  }
  return c;
}

FieldSpec parse_field(const LineCursor& at, std::string_view line) {
  const std::vector<std::string_view> tok = split_whitespace(line, 6);
  if (tok.size() < 7) {
    at.fail("field line needs: NAME TYPE WIDTH DEFAULT CONSTRAINT DIMENSION DESCRIPTION");
  }
  FieldSpec f;
  f.name = upper(tok[0]);
  if (tok[1] == "int") {
    f.type = FieldType::integer;
  } else if (tok[1] == "real") {
    f.type = FieldType::real;
  } else if (tok[1] == "text") {
    f.type = FieldType::text;
  } else {
    at.fail(fmt::format("unknown field type '{}' (int, real, text)", tok[1]));
  }
  f.width = static_cast<int>(parse_schema_number(at, tok[2]));
  if (f.width < 1 || f.width > 240) at.fail("field width out of range");
  std::string_view def = tok[3];
  if (def == "required") {
    f.default_kind = DefaultKind::required;
  } else if (def == "blank") {
    f.default_kind = DefaultKind::blank;
  } else {
    f.default_kind = DefaultKind::value;
    if (def.size() > 2 && def.substr(def.size() - 2) == "~0") {
      f.zero_means_default = true;
      def.remove_suffix(2);
    }
    if (f.type == FieldType::text) {
      f.default_text = std::string(def);
    } else {
      f.default_number = parse_schema_number(at, def);
    }
  }
  f.constraint = parse_constraint(at, tok[4]);
  f.dimension = std::string(tok[5]);
  if (!is_known_dimension(f.dimension)) at.fail(fmt::format("unknown dimension '{}'", tok[5]));
  f.description = std::string(trim(tok[6]));
  return f;
}

}  // namespace

bool is_known_dimension(std::string_view dimension) {
  return std::find(kDimensions.begin(), kDimensions.end(), dimension) != kDimensions.end();
}

bool Constraint::allows(double v) const {
  switch (kind) {
    case Kind::none:
      return true;
    case Kind::greater:
      return v > bound;
    case Kind::greater_equal:
      return v >= bound;
    case Kind::less:
      return v < bound;
    case Kind::less_equal:
      return v <= bound;
    case Kind::not_equal:
      return v != bound;
    case Kind::one_of:
      return std::any_of(ranges.begin(), ranges.end(),
                         [v](const auto& r) { return v >= r.first && v <= r.second; });
  }
  return true;
}

std::string Constraint::describe() const {
  switch (kind) {
    case Kind::none:
      return "";
    case Kind::greater:
      return fmt::format("> {:g}", bound);
    case Kind::greater_equal:
      return fmt::format(">= {:g}", bound);
    case Kind::less:
      return fmt::format("< {:g}", bound);
    case Kind::less_equal:
      return fmt::format("<= {:g}", bound);
    case Kind::not_equal:
      return fmt::format("!= {:g}", bound);
    case Kind::one_of: {
      std::string s = "one of {";
      for (std::size_t i = 0; i < ranges.size(); ++i) {
        if (i) s += ", ";
        s += ranges[i].first == ranges[i].second
                 ? fmt::format("{:g}", ranges[i].first)
                 : fmt::format("{:g}..{:g}", ranges[i].first, ranges[i].second);
      }
      return s + "}";
    }
  }
  return "";
}

std::string Condition::text() const {
  return source_text;
}

bool CardSpec::is_text_line() const {
  return fields.size() == 1 && fields[0].type == FieldType::text && fields[0].width > 20;
}

int CardSpec::field_index(std::string_view field_name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == field_name) return static_cast<int>(i);
  }
  return -1;
}

bool KeywordSchema::has_option(std::string_view option) const {
  return std::find(options.begin(), options.end(), option) != options.end();
}

const FieldSpec* KeywordSchema::find_field(std::string_view field_name) const {
  for (const FormSpec& form : forms) {
    for (const auto* cards : {&form.head, &form.repeat}) {
      for (const CardSpec& card : *cards) {
        const int i = card.field_index(field_name);
        if (i >= 0) return &card.fields[i];
      }
    }
  }
  return nullptr;
}

KeywordSchema parse_schema(std::string_view file_name, std::string_view text) {
  KeywordSchema s;
  s.file = std::string(file_name);
  LineCursor at{file_name, 0};
  bool in_repeat = false;
  CardSpec* card = nullptr;
  auto current_form = [&]() -> FormSpec& {
    if (s.forms.empty()) s.forms.push_back(FormSpec{"default", "", {}, {}});
    return s.forms.back();
  };
  for (std::string_view raw : split_lines(text)) {
    ++at.line;
    const std::string_view line = trim_right(raw);
    const std::string_view body = trim(line);
    if (body.empty() || body.front() == '#') continue;
    if (line.front() == ' ') {
      if (card == nullptr) at.fail("field line outside a card");
      card->fields.push_back(parse_field(at, body));
      continue;
    }
    const auto tok = split_whitespace(body);
    const std::string_view key = tok[0];
    const std::string_view rest = trim(body.substr(key.size()));
    if (key == "keyword") {
      s.name = upper(rest);
    } else if (key == "alias") {
      for (auto a : split_whitespace(rest))
        s.aliases.push_back(upper(a));
    } else if (key == "options") {
      for (auto o : split_whitespace(rest))
        s.options.push_back(upper(o));
    } else if (key == "group") {
      s.group = std::string(rest);
    } else if (key == "summary") {
      s.summary = std::string(rest);
    } else if (key == "source") {
      s.source = std::string(rest);
    } else if (key == "cards-from") {
      s.cards_from = upper(rest);
    } else if (key == "handler") {
      if (rest != "reader" && rest != "builder") at.fail("handler is 'reader' or 'builder'");
      s.handler = std::string(rest);
    } else if (key == "form") {
      if (tok.size() != 2 && !(tok.size() == 4 && tok[2] == "when")) {
        at.fail("form NAME [when FIELD]");
      }
      s.forms.push_back(
          FormSpec{std::string(tok[1]), tok.size() == 4 ? upper(tok[3]) : "", {}, {}});
      in_repeat = false;
      card = nullptr;
    } else if (key == "repeat") {
      in_repeat = true;
      card = nullptr;
    } else if (key == "card") {
      if (tok.size() < 2) at.fail("card needs a name");
      CardSpec c;
      c.name = std::string(tok[1]);
      std::size_t i = 2;
      if (i < tok.size() && tok[i] == "optional") {
        c.optional = true;
        ++i;
      }
      if (i < tok.size()) {
        if (tok[i] != "if") at.fail(fmt::format("expected 'optional' or 'if', got '{}'", tok[i]));
        c.condition = parse_condition(at, tok, i + 1);
      }
      FormSpec& form = current_form();
      auto& list = in_repeat ? form.repeat : form.head;
      list.push_back(std::move(c));
      card = &list.back();
    } else {
      at.fail(fmt::format("unknown directive '{}'", key));
    }
  }
  if (s.name.empty()) at.fail("schema has no 'keyword' line");
  if (s.summary.empty()) at.fail("schema has no 'summary' line");
  if (s.forms.empty() && s.cards_from.empty()) at.fail("schema declares no cards");
  for (const FormSpec& form : s.forms) {
    for (const auto* cards : {&form.head, &form.repeat}) {
      for (const CardSpec& c : *cards) {
        if (c.fields.empty()) at.fail(fmt::format("card '{}' has no fields", c.name));
        if (c.fields.size() > 16) at.fail(fmt::format("card '{}' has more than 16 fields", c.name));
      }
    }
  }
  return s;
}

}  // namespace mcdyna::deck
