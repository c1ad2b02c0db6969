// A memory of work under an exact key of 64-bit words (the sweep's moves,
// the robot's sight, the belts' plans) that also keeps which entry was
// asked for after which. A production loop asks in the same order every
// cycle, so the entries that followed the last one (the latest two) are
// tried first, by a comparison of keys each, before the table is hashed and
// searched (that search was a tenth of a device cell's time, most of it
// waiting on memory: a division for the bucket, then the nodes).
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
    if (last_)
      for (int i = 0; i < kNexts; ++i)
        if (last_->next[i] && *last_->nextKey[i] == key) {
          last_ = last_->next[i];
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
  // Followers kept per entry: a loop's plans may go one of two ways (a
  // part on the belt or not yet), its moves and searches mostly one.
  static constexpr int kNexts = 2;
  struct Node {
    Value value;
    const Key* nextKey[kNexts] = {};  // the entries asked for after this one, the latest first
    Node* next[kNexts] = {};
  };
  using Table = std::unordered_map<Key, Node, WordsHash>;
  // `it` is asked for now: it follows the last (node addresses hold until clear()).
  void follow(typename Table::iterator it) {
    if (last_ && last_->next[0] != &it->second) {
      for (int i = kNexts - 1; i > 0; --i) last_->next[i] = last_->next[i - 1], last_->nextKey[i] = last_->nextKey[i - 1];
      last_->next[0] = &it->second, last_->nextKey[0] = &it->first;
    }
    last_ = &it->second;
  }

  Table table_;
  Node* last_ = nullptr;
  std::size_t capacity_;
};

}  // namespace rs::base
