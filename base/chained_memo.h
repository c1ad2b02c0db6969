// A memory of work under an exact key of 64-bit words (the sweep's moves,
// the robot's sight, the belts' plans) that also keeps which entry was
// asked for after which. A production loop asks in the same order every
// cycle, so the entry that followed the last one is tried first, by one
// comparison of keys, before the table is hashed and searched (that search
// was a tenth of a device cell's time, most of it waiting on memory).
// Bounded: when full it forgets everything at once (deterministic, and
// cheap to reason about). A pure cache: the order of asking never changes
// what an entry holds, only what finding it costs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/word_hash.h"

namespace rs::base {

template <class Value>
class ChainedMemo {
 public:
  using Key = std::vector<std::uint64_t>;

  explicit ChainedMemo(std::size_t capacity) : capacity_(capacity) {}

  /// The value under `key`, or null. Found, it is the last asked for.
  Value* find(const Key& key) {
    if (last_ && last_->next && *last_->nextKey == key) {
      last_ = last_->next;
      return &last_->value;
    }
    const auto it = table_.find(key);
    if (it == table_.end()) return nullptr;
    follow(it);
    return &it->second.value;
  }
  /// Puts `value` under `key` (in place of one there), the last asked for.
  Value& put(const Key& key, Value value) {
    if (table_.size() >= capacity_) clear();
    const auto it = table_.insert_or_assign(key, Node{std::move(value)}).first;
    follow(it);
    return it->second.value;
  }
  void clear() {
    table_.clear();
    last_ = nullptr;
  }
  std::size_t size() const { return table_.size(); }

 private:
  struct Node {
    Value value;
    const Key* nextKey = nullptr;  // the entry asked for after this one, last time
    Node* next = nullptr;
  };
  using Table = std::unordered_map<Key, Node, WordsHash>;
  // `it` is asked for now: it follows the last (node addresses hold until clear()).
  void follow(typename Table::iterator it) {
    if (last_) last_->nextKey = &it->first, last_->next = &it->second;
    last_ = &it->second;
  }

  Table table_;
  Node* last_ = nullptr;
  std::size_t capacity_;
};

}  // namespace rs::base
