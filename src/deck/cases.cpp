#include "deck/cases.hpp"

#include <algorithm>
#include <optional>

#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck {

namespace {

bool is_integer(std::string_view token, long& value) {
  const std::optional<std::int64_t> n = parse_integer(token);
  if (n) value = static_cast<long>(*n);
  return n.has_value();
}

// The tokens of a card split at commas and blanks.
std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  for (const std::string_view piece : split(line, ','))
    for (const std::string_view t : split_whitespace(piece))
      out.push_back(t);
  return out;
}

void keep_if(Deck& deck, const std::vector<long>& subcases) {
  std::erase_if(deck.blocks, [&](const KeywordBlock& b) {
    return std::any_of(b.subcases.begin(), b.subcases.end(), [&](long n) {
      return std::find(subcases.begin(), subcases.end(), n) == subcases.end();
    });
  });
}

}  // namespace

std::vector<Case> read_cases(const Deck& deck, core::Diagnostics& diags) {
  std::vector<Case> cases;
  for (const KeywordBlock& b : deck.blocks) {
    if (b.name.rfind("PARAMETER", 0) == 0 && !b.subcases.empty()) {
      diags.error(b.loc,
                  "*{} inside *CASE_BEGIN_{}: parameters are read for the whole deck; a "
                  "parameter per case is not supported",
                  b.name, b.subcases.front());
    }
    if (b.name != "CASE") continue;
    if (!b.subcases.empty()) diags.error(b.loc, "*CASE inside a *CASE_BEGIN_n block");
    if (b.line_count() == 0) {
      diags.error(b.loc, "*CASE: card 1 (CASEID, JOBID) is missing");
      continue;
    }
    Case c;
    c.loc = b.loc;
    // Card 1: CASEID (columns 1-10 or the first free-format field), JOBID the rest.
    const DataLine& first = deck.lines[b.first_line];
    const std::vector<std::string_view> head = split_whitespace(trim(first.text), 1);
    std::string_view id_text = head.empty() ? std::string_view{} : head[0];
    std::string_view job = head.size() > 1 ? trim(head[1]) : std::string_view{};
    if (const auto comma = id_text.find(','); comma != std::string_view::npos) {
      job = trim(trim(first.text).substr(comma + 1));
      id_text = id_text.substr(0, comma);
    }
    if (!is_integer(id_text, c.id) || c.id <= 0) {
      diags.error(first.loc(), "*CASE card 1 field CASEID: expected a positive integer, got \"{}\"",
                  id_text);
      continue;
    }
    c.job = job.empty() ? "case" + std::to_string(c.id) : std::string(job);
    // Then command-line cards and cards of subcase IDs (SCID1 ..): a card of integers lists
    // subcases, any other is a command line.
    for (std::uint32_t i = b.first_line + 1; i < b.end_line; ++i) {
      const std::vector<std::string_view> t = tokens(deck.lines[i].text);
      if (t.empty()) continue;
      std::vector<long> ids;
      long v = 0;
      for (const std::string_view token : t)
        if (is_integer(token, v)) ids.push_back(v);
      if (ids.size() == t.size()) {
        c.subcases.insert(c.subcases.end(), ids.begin(), ids.end());
      } else {
        c.commands.emplace_back(trim(deck.lines[i].text));
      }
    }
    const bool repeated = std::any_of(cases.begin(), cases.end(),
                                      [&](const Case& other) { return other.id == c.id; });
    if (repeated) {
      diags.error(b.loc, "*CASE {} is defined twice", c.id);
      continue;
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

void keep_case(Deck& deck, const Case& c) {
  keep_if(deck, c.subcases);
}

void keep_main_model(Deck& deck) {
  keep_if(deck, {});
}

}  // namespace mcdyna::deck
