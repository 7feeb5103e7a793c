#include "model/id_index.hpp"

#include <algorithm>

namespace mcdyna::model {

std::vector<std::pair<std::size_t, std::size_t>> IdIndex::build_ids(const std::vector<Id>& ids) {
  std::vector<std::pair<std::size_t, std::size_t>> duplicates;
  table_.clear();
  map_.clear();
  if (ids.empty()) {
    dense_ = true;
    return duplicates;
  }
  const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
  min_ = *lo;
  // Dense when the ID range is at most a few times the count: one 8-byte slot per possible ID.
  const double range = static_cast<double>(*hi) - static_cast<double>(*lo) + 1.0;
  dense_ = range <= 4.0 * static_cast<double>(ids.size()) + 1024.0;
  if (dense_) {
    table_.assign(static_cast<std::size_t>(range), kNone);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      auto& slot = table_[static_cast<std::size_t>(ids[i] - min_)];
      if (slot == kNone) {
        slot = static_cast<std::int64_t>(i);
      } else {
        duplicates.emplace_back(static_cast<std::size_t>(slot), i);
      }
    }
  } else {
    map_.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const auto [it, inserted] = map_.emplace(ids[i], static_cast<std::int64_t>(i));
      if (!inserted) duplicates.emplace_back(static_cast<std::size_t>(it->second), i);
    }
  }
  return duplicates;
}

}  // namespace mcdyna::model
