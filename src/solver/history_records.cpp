// The blocks' history lines, collected (history_records.hpp). The blocks add in their order;
// rcforc lists the interfaces as the deck does (the force transducers' blocks come after every
// contact's) and bndout the prescribed nodes before the rigid parts.
#include "solver/history_records.hpp"

#include <algorithm>

#include "solver/block.hpp"

namespace mcdyna::solver {

HistoryRecords history_records(const State& s) {
  HistoryRecords r;
  for (const auto& b : s.blocks)
    b->add_history_records(s, r);
  std::stable_sort(r.contacts.begin(), r.contacts.end(),
                   [](const ContactRecord& a, const ContactRecord& b) {
                     return a.deck_position < b.deck_position;
                   });
  std::stable_partition(r.boundaries.begin(), r.boundaries.end(), [](const BoundaryRecord& b) {
    return b.kind == BoundaryRecord::Kind::node;
  });
  return r;
}

}  // namespace mcdyna::solver
