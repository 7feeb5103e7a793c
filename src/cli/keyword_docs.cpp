#include "cli/keyword_docs.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <fstream>
#include <ostream>

#include "deck/text_util.hpp"

namespace mcdyna::cli {

namespace {

std::string type_name(deck::FieldType t) {
  switch (t) {
    case deck::FieldType::integer:
      return "I";
    case deck::FieldType::real:
      return "F";
    case deck::FieldType::text:
      return "A";
  }
  return "?";
}

std::string default_text(const deck::FieldSpec& f) {
  switch (f.default_kind) {
    case deck::DefaultKind::required:
      return "required";
    case deck::DefaultKind::blank:
      return "blank";
    case deck::DefaultKind::value: {
      std::string v =
          f.type == deck::FieldType::text ? f.default_text : fmt::format("{:g}", f.default_number);
      return f.zero_means_default ? v + " (0 too)" : v;
    }
  }
  return "";
}

std::vector<const deck::KeywordSchema*> sorted(const deck::Registry& registry) {
  std::vector<const deck::KeywordSchema*> v;
  for (const auto& s : registry.schemas())
    v.push_back(&s);
  std::sort(v.begin(), v.end(), [](auto* a, auto* b) { return a->name < b->name; });
  return v;
}

std::string names_line(const deck::KeywordSchema& s) {
  std::string line;
  if (!s.aliases.empty()) {
    line += "aliases:";
    for (const auto& a : s.aliases)
      line += " *" + a;
  }
  if (!s.options.empty()) {
    line += line.empty() ? "options:" : "; options:";
    for (const auto& o : s.options)
      line += " _" + o;
  }
  return line;
}

void print_card(std::ostream& out, const deck::CardSpec& card, bool repeated, bool markdown) {
  std::string head = fmt::format("Card {}", card.name);
  if (repeated) head += " (repeats)";
  if (card.optional) head += " (optional)";
  if (!card.condition.always()) head += fmt::format(" (if {})", card.condition.text());
  if (markdown) {
    fmt::print(out,
               "\n**{}**\n\n| columns | field | type | default | allowed | dimension | "
               "description |\n|---|---|---|---|---|---|---|\n",
               head);
  } else {
    fmt::print(out, "\n  {}\n  {:<9} {:<10} {:<4} {:<16} {:<18} {:<13} {}\n", head, "columns",
               "field", "type", "default", "allowed", "dimension", "description");
  }
  int col = 1;
  for (const deck::FieldSpec& f : card.fields) {
    const std::string cols = fmt::format("{}-{}", col, col + f.width - 1);
    col += f.width;
    const std::string allowed = f.constraint.describe();
    if (markdown) {
      fmt::print(out, "| {} | {} | {} | {} | {} | {} | {} |\n", cols, f.name, type_name(f.type),
                 default_text(f), allowed.empty() ? "" : allowed,
                 f.dimension == "-" ? "" : f.dimension, f.description);
    } else {
      fmt::print(out, "  {:<9} {:<10} {:<4} {:<16} {:<18} {:<13} {}\n", cols, f.name,
                 type_name(f.type), default_text(f), allowed.empty() ? "-" : allowed, f.dimension,
                 f.description);
    }
  }
}

}  // namespace

void print_keyword_list(std::ostream& out, const deck::Registry& registry) {
  for (const deck::KeywordSchema* s : sorted(registry)) {
    std::string name = "*" + s->name;
    for (const auto& a : s->aliases)
      name += " *" + a;
    fmt::print(out, "{:<48} {:<18} {}\n", name, s->group, s->summary);
  }
}

void print_keyword_layout(std::ostream& out, const deck::KeywordSchema& s, bool markdown) {
  const std::string names = names_line(s);
  if (markdown) {
    fmt::print(out, "# *{}\n\n{}\n\n", s.name, s.summary);
    if (!names.empty()) fmt::print(out, "{}\n\n", names);
    fmt::print(out, "Group: {}. Source: {}.{}\n", s.group, s.source,
               s.handler == "reader" ? " Handled by the deck reader." : "");
  } else {
    fmt::print(out, "*{}{}\n  {}\n  group {}; source {}\n", s.name,
               names.empty() ? "" : "  (" + names + ")", s.summary, s.group, s.source);
  }
  for (const deck::FormSpec& form : s.forms) {
    if (s.forms.size() > 1) {
      const std::string when = form.when_present_field.empty()
                                   ? "otherwise"
                                   : "when " + form.when_present_field + " is on the first line";
      fmt::print(out, fmt::runtime(markdown ? "\n## Layout {} ({})\n" : "\n  Layout {} ({})\n"),
                 form.name, when);
    }
    for (const auto& card : form.head)
      print_card(out, card, false, markdown);
    for (const auto& card : form.repeat)
      print_card(out, card, true, markdown);
  }
}

bool write_keyword_pages(const std::filesystem::path& dir, const deck::Registry& registry) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::ofstream index(dir / "README.md");
  if (!index) return false;
  fmt::print(
      index,
      "# Keyword reference\n\nGenerated from `keywords/*.kw` by `mcdyna keywords "
      "--markdown`; do not edit. Keywords not listed here are classified in "
      "[classification](classification.md).\n\n| keyword | group | summary |\n|---|---|---|\n");
  for (const deck::KeywordSchema* s : sorted(registry)) {
    const std::string file = deck::upper(s->name) + ".md";
    fmt::print(index, "| [*{}]({}) | {} | {} |\n", s->name, file, s->group, s->summary);
    std::ofstream page(dir / file);
    if (!page) return false;
    print_keyword_layout(page, *s, true);
  }
  std::ofstream cls(dir / "classification.md");
  if (!cls) return false;
  fmt::print(cls,
             "# Keywords read without effect or not supported\n\nFrom "
             "`keywords/classification.txt`. Any keyword neither here nor in the reference is "
             "unsupported and assumed to change the physics.\n\n```\n{}```\n",
             registry.classification_text());
  return static_cast<bool>(index);
}

}  // namespace mcdyna::cli
