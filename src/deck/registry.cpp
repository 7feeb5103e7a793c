#include "deck/registry.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "deck/text_util.hpp"

namespace mcdyna::deck {

const char* support_name(Support s) {
  switch (s) {
    case Support::supported:
      return "supported";
    case Support::no_effect:
      return "read, no effect";
    case Support::output_only:
      return "unsupported output";
    case Support::unsupported:
      return "unsupported";
  }
  return "unsupported";
}

Registry::Registry() : Registry(embedded_keyword_files()) {}

Registry::Registry(const std::vector<EmbeddedFile>& files) {
  load(files);
}

void Registry::load(const std::vector<EmbeddedFile>& files) {
  for (const EmbeddedFile& f : files) {
    const std::string_view name = f.name;
    if (name == "classification.txt") {
      classification_text_ = f.text;
      int line_no = 0;
      for (std::string_view line : split_lines(f.text)) {
        ++line_no;
        const std::string_view body = trim(line);
        if (body.empty() || body.front() == '#') continue;
        const auto tok = split_whitespace(body, 2);
        if (tok.size() < 3) {
          throw SchemaError(
              fmt::format("keywords/{}:{}: expected PATTERN CLASS REASON", name, line_no));
        }
        Support s = Support::unsupported;
        if (tok[1] == "no-effect") {
          s = Support::no_effect;
        } else if (tok[1] == "output-only") {
          s = Support::output_only;
        } else if (tok[1] != "physics") {
          throw SchemaError(
              fmt::format("keywords/{}:{}: unknown class '{}'", name, line_no, tok[1]));
        }
        rules_.push_back(Rule{upper(tok[0]), s, std::string(tok[2])});
      }
    } else if (name.size() > 3 && name.substr(name.size() - 3) == ".kw") {
      schemas_.push_back(parse_schema(name, f.text));
      texts_.emplace_back(f.text);
    }
  }
  resolve_cards_from();
  for (std::size_t i = 0; i < schemas_.size(); ++i) {
    for (std::size_t j = i + 1; j < schemas_.size(); ++j) {
      auto names = [](const KeywordSchema& s) {
        std::vector<std::string> n = s.aliases;
        n.push_back(s.name);
        return n;
      };
      for (const auto& a : names(schemas_[i])) {
        for (const auto& b : names(schemas_[j])) {
          if (a == b) {
            throw SchemaError(fmt::format("keyword name {} is declared by {} and {}", a,
                                          schemas_[i].file, schemas_[j].file));
          }
        }
      }
    }
  }
}

void Registry::resolve_cards_from() {
  for (KeywordSchema& s : schemas_) {
    if (s.cards_from.empty()) continue;
    const KeywordSchema* src = find(s.cards_from);
    if (src == nullptr || !src->cards_from.empty()) {
      throw SchemaError(fmt::format("keywords/{}: cards-from {} names no schema with its own cards",
                                    s.file, s.cards_from));
    }
    if (!s.forms.empty()) {
      throw SchemaError(fmt::format("keywords/{}: cards-from and own cards together", s.file));
    }
    s.forms = src->forms;
  }
}

const KeywordSchema* Registry::find(std::string_view name) const {
  for (const KeywordSchema& s : schemas_) {
    if (s.name == name) return &s;
    if (std::find(s.aliases.begin(), s.aliases.end(), name) != s.aliases.end()) return &s;
  }
  return nullptr;
}

std::string_view Registry::schema_text(std::string_view name) const {
  for (std::size_t i = 0; i < schemas_.size(); ++i) {
    if (schemas_[i].name == name) return texts_[i];
  }
  return {};
}

namespace {

// Splits "ID_MPP" into declared options, longest declared option first ("BIRTH_DEATH").
// Returns false and the first unknown token if the suffix is not made of declared options.
bool split_options(std::string_view suffix, const KeywordSchema& schema,
                   std::vector<std::string>& options, std::string& unknown) {
  while (!suffix.empty()) {
    std::string_view best;
    for (const std::string& o : schema.options) {
      const bool fits = suffix == o || (suffix.size() > o.size() &&
                                        suffix.substr(0, o.size()) == o && suffix[o.size()] == '_');
      if (fits && o.size() > best.size()) best = o;
    }
    if (best.empty()) {
      unknown = std::string(suffix.substr(0, suffix.find('_')));
      return false;
    }
    options.emplace_back(best);
    suffix.remove_prefix(std::min(suffix.size(), best.size() + 1));
  }
  return true;
}

bool matches(const std::string& pattern, std::string_view name) {
  if (!pattern.empty() && pattern.back() == '*') {
    const std::string_view stem(pattern.data(), pattern.size() - 1);
    return name.substr(0, stem.size()) == stem;
  }
  return name == pattern;
}

}  // namespace

Classification Registry::classify(std::string_view name) const {
  Classification c;
  // Longest base name first: SET_NODE_LIST_GENERATE before SET_NODE_LIST, SECTION_SOLID_SPG
  // before SECTION_SOLID.
  const KeywordSchema* base_with_bad_option = nullptr;
  std::string bad_option;
  std::size_t cut = name.size();
  for (;;) {
    const std::string_view base = name.substr(0, cut);
    if (const KeywordSchema* schema = find(base)) {
      std::vector<std::string> options;
      std::string unknown;
      const std::string_view suffix = cut < name.size() ? name.substr(cut + 1) : std::string_view{};
      if (split_options(suffix, *schema, options, unknown)) {
        c.support = Support::supported;
        c.schema = schema;
        c.options = std::move(options);
        return c;
      }
      if (base_with_bad_option == nullptr) {
        base_with_bad_option = schema;
        bad_option = unknown;
      }
    }
    const std::size_t previous = cut == 0 ? std::string_view::npos : name.rfind('_', cut - 1);
    if (previous == std::string_view::npos || previous == 0) break;
    cut = previous;
  }
  for (const Rule& r : rules_) {
    if (matches(r.pattern, name)) {
      c.support = r.support;
      c.reason = r.reason;
      return c;
    }
  }
  c.support = Support::unsupported;
  c.reason = base_with_bad_option != nullptr ? fmt::format("option _{} of *{} is not supported",
                                                           bad_option, base_with_bad_option->name)
                                             : "keyword not supported by mcdyna";
  return c;
}

}  // namespace mcdyna::deck
