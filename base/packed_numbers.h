// A column of 32-bit numbers held in about a byte each: a source file's
// line starts, an image's line and column of every instruction. Held as
// plain vectors they were 12 bytes a line beside a 12-byte instruction,
// the largest holding of a compile after the code for programs of short
// lines (docs/performance.md). The image file keeps full 4-byte numbers;
// only memory is packed.
//
// Each number is one byte: its rise over the number before (Rises: lines,
// which only grow in a compiled program) or itself (Small: columns). A
// number that does not fit in 0..254 is byte 255 plus an exact entry in a
// list of exceptions sorted by position, so any sequence is held exactly
// (a forged image's too), at worst in 9 bytes a number. Rises keep the
// number before each block of kBlock, so reading one at random adds at
// most kBlock - 1 bytes; walking them in order is a byte a step.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <utility>
#include <vector>

namespace rs::base {

enum class Packing : std::uint8_t { Rises, Small };

template <Packing kPacking>
class PackedNumbers {
 public:
  static constexpr std::size_t kBlock = 16;

  PackedNumbers() = default;
  PackedNumbers(std::initializer_list<std::uint32_t> values) {
    reserve(values.size());
    for (std::uint32_t v : values) push_back(v);
  }

  std::size_t size() const { return bytes_.size(); }
  bool empty() const { return bytes_.empty(); }
  void reserve(std::size_t n) {
    bytes_.reserve(n);
    if constexpr (kPacking == Packing::Rises) blockStarts_.reserve(n / kBlock + 1);
  }
  void clear() { *this = PackedNumbers(); }

  void push_back(std::uint32_t value) {
    const std::size_t i = bytes_.size();
    std::uint64_t code = value;
    if constexpr (kPacking == Packing::Rises) {
      if (i % kBlock == 0) blockStarts_.push_back(last_);
      code = value >= last_ ? value - last_ : kEscape;
    }
    if (code < kEscape) {
      bytes_.push_back(static_cast<std::uint8_t>(code));
    } else {
      bytes_.push_back(kEscape);
      exceptions_.push_back({static_cast<std::uint32_t>(i), value});
    }
    last_ = value;
  }

  std::uint32_t operator[](std::size_t i) const {
    if constexpr (kPacking == Packing::Small) {
      return bytes_[i] != kEscape ? bytes_[i] : exception(i);
    } else {
      // Back to the block's start or the last exception in it, then add up.
      const std::size_t first = i - i % kBlock;
      std::size_t j = i + 1;
      while (j > first && bytes_[j - 1] != kEscape) --j;
      std::uint32_t value = j > first ? exception(j - 1) : blockStarts_[i / kBlock];
      for (; j <= i; ++j) value += bytes_[j];
      return value;
    }
  }

  /// Walks the numbers in order, a byte a step.
  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = std::uint32_t;
    using difference_type = std::ptrdiff_t;
    using pointer = const std::uint32_t*;
    using reference = std::uint32_t;

    const_iterator() = default;
    const_iterator(const PackedNumbers* table, std::size_t i) : table_(table), i_(i) { load(); }
    std::uint32_t operator*() const { return value_; }
    const_iterator& operator++() {
      ++i_;
      load();
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator was = *this;
      ++*this;
      return was;
    }
    bool operator==(const const_iterator& o) const { return i_ == o.i_; }

   private:
    void load() {
      if (!table_ || i_ >= table_->size()) return;
      const std::uint8_t byte = table_->bytes_[i_];
      if (byte == kEscape) {
        value_ = table_->exceptions_[nextException_++].second;
      } else if constexpr (kPacking == Packing::Rises) {
        value_ = (i_ == 0 ? 0 : value_) + byte;
      } else {
        value_ = byte;
      }
    }
    const PackedNumbers* table_ = nullptr;
    std::size_t i_ = 0;
    std::size_t nextException_ = 0;
    std::uint32_t value_ = 0;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {nullptr, size()}; }

  std::vector<std::uint32_t> toVector() const { return {begin(), end()}; }

  /// Equal numbers are equal bytes: the packing depends on the numbers only.
  bool operator==(const PackedNumbers& o) const { return bytes_ == o.bytes_ && exceptions_ == o.exceptions_; }

 private:
  static constexpr std::uint8_t kEscape = 255;

  std::uint32_t exception(std::size_t i) const {
    const auto it = std::lower_bound(exceptions_.begin(), exceptions_.end(), i,
                                     [](const std::pair<std::uint32_t, std::uint32_t>& e, std::size_t at) {
                                       return e.first < at;
                                     });
    return it->second;
  }

  std::vector<std::uint8_t> bytes_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> exceptions_;  // (position, number), by position
  std::vector<std::uint32_t> blockStarts_;  // Rises: the number before each block (0 before the first)
  std::uint32_t last_ = 0;
};

using RisingNumbers = PackedNumbers<Packing::Rises>;
using SmallNumbers = PackedNumbers<Packing::Small>;

}  // namespace rs::base
