#pragma once
/// User ID -> position in an entity vector. Dense table when IDs are compact (typical meshes),
/// hash map otherwise.
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "model/entities.hpp"

namespace mcdyna::model {

class IdIndex {
 public:
  static constexpr std::int64_t kNone = -1;

  /// Builds from IDs in entity order; returns (first position, repeated position) for every ID
  /// seen more than once (the first occurrence stays indexed).
  template <typename Entity>
  std::vector<std::pair<std::size_t, std::size_t>> build(const std::vector<Entity>& entities) {
    std::vector<Id> ids;
    ids.reserve(entities.size());
    for (const Entity& e : entities)
      ids.push_back(e.id);
    return build_ids(ids);
  }
  std::vector<std::pair<std::size_t, std::size_t>> build_ids(const std::vector<Id>& ids);

  /// Position of `id`, or kNone.
  [[nodiscard]] std::int64_t find(Id id) const {
    if (dense_) {
      if (id < min_ || id - min_ >= static_cast<Id>(table_.size())) return kNone;
      return table_[static_cast<std::size_t>(id - min_)];
    }
    const auto it = map_.find(id);
    return it == map_.end() ? kNone : it->second;
  }
  [[nodiscard]] bool contains(Id id) const { return find(id) != kNone; }

 private:
  bool dense_ = true;
  Id min_ = 0;
  std::vector<std::int64_t> table_;
  std::unordered_map<Id, std::int64_t> map_;
};

}  // namespace mcdyna::model
