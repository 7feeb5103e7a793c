#include "deck/build_model.hpp"

#include <stdexcept>
#include <unordered_map>

#include "deck/builders/builders.hpp"
#include "deck/record.hpp"

namespace mcdyna::deck {

BuildResult build_model(const Deck& deck, const Registry& registry, core::Diagnostics& diags) {
  BuildResult result;
  std::unordered_map<std::string_view, BuilderFn> builders;
  for (const BuilderEntry& e : builder_table())
    builders.emplace(e.keyword, e.build);
  for (const KeywordBlock& block : deck.blocks) {
    if (block.name.empty()) continue;  // already reported by the lexer
    Classification c = registry.classify(block.name);
    result.keywords.push_back(KeywordUse{block.name, c.support, c.reason, block.loc});
    if (c.support != Support::supported || c.schema->handler == "reader") continue;
    const auto it = builders.find(c.schema->name);
    if (it == builders.end()) {
      diags.error(block.loc, "internal error: no builder for *{}", c.schema->name);
      continue;
    }
    try {
      KeywordRecord record(deck, block, *c.schema, std::move(c.options), diags);
      it->second(record, result.model);
      record.finish();
    } catch (const std::logic_error& e) {
      diags.error(block.loc, "internal error while reading *{}: {}", block.name, e.what());
    }
  }
  builders::resolve_general_sets(result.model, diags);
  return result;
}

}  // namespace mcdyna::deck
