// Little-endian field writers and readers for robotsim's binary formats
// (the image, and the cell section inside it). The reader never trusts a
// length: after the first overrun every read yields 0 and `failed` stays
// set, so decoding code needs no check per field, and a hostile count
// cannot make it allocate.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rs::base {

inline constexpr std::size_t kMaxStoredString = 255;

class ByteWriter {
 public:
  /// Spills: a writer that hands its bytes to `spill` whenever it holds
  /// `chunk` bytes or more (and at flush()), so that a large output is never
  /// held whole. Without one, everything stays in `out`.
  using Spill = std::function<void(const std::vector<std::uint8_t>&)>;
  ByteWriter() = default;
  ByteWriter(Spill spill, std::size_t chunk) : spill_(std::move(spill)), spillAt_(chunk) { out.reserve(chunk + 512); }

  void u8(std::uint8_t v) {
    out.push_back(v);
    spillIfFull();
  }
  void u16(std::uint16_t v) { le(v, 2); }
  void u32(std::uint32_t v) { le(v, 4); }
  void i32(std::int32_t v) { le(static_cast<std::uint32_t>(v), 4); }
  void f64(double v) { le(std::bit_cast<std::uint64_t>(v), 8); }
  /// u16 length, then the bytes (cut at kMaxStoredString).
  void str(std::string_view s) {
    const std::size_t n = std::min(s.size(), kMaxStoredString);
    u16(static_cast<std::uint16_t>(n));
    out.insert(out.end(), s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n));
    spillIfFull();
  }
  void bytes(const std::vector<std::uint8_t>& b) { bytes(b.data(), b.size()); }
  void bytes(const std::uint8_t* data, std::size_t n) {
    out.insert(out.end(), data, data + n);
    spillIfFull();
  }
  /// Hands what is held to the spill, if there is one.
  void flush() {
    if (!spill_ || out.empty()) return;
    spill_(out);
    out.clear();
  }
  std::vector<std::uint8_t> out;

 private:
  void le(std::uint64_t v, int n) {
    // One resize and direct stores: a push_back per byte costs a capacity
    // check each (a fifth of a compile's image writing).
    const std::size_t at = out.size();
    out.resize(at + static_cast<std::size_t>(n));
    std::uint8_t* p = out.data() + at;
    for (int i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
    spillIfFull();
  }
  void spillIfFull() {
    if (out.size() >= spillAt_) flush();
  }

  Spill spill_;
  std::size_t spillAt_ = SIZE_MAX;  // never, without a spill
};

class ByteReader {
 public:
  /// `unit` names the data in messages: "unexpected end of file".
  explicit ByteReader(std::string_view bytes, std::string_view unit = "file") : data_(bytes), unit_(unit) {}
  std::uint8_t u8() { return static_cast<std::uint8_t>(le(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(le(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(le(4))); }
  double f64() { return std::bit_cast<double>(le(8)); }
  std::string str() {
    const std::size_t n = u16();
    if (n > kMaxStoredString || !need(n)) return fail("string of " + std::to_string(n) + " bytes"), std::string{};
    std::string s(data_.substr(pos_, n));
    pos_ += n;
    return s;
  }
  /// A count of records of at least `minBytes` each, refused (0, failed) if
  /// the rest of the data cannot hold them.
  std::size_t count(std::size_t minBytes, std::string_view what) {
    const std::size_t n = u32();
    if (failed) return 0;
    if (n > remaining() / std::max<std::size_t>(minBytes, 1))
      return fail(std::string(what) + " count " + std::to_string(n) + " larger than the " + std::string(unit_)), 0;
    return n;
  }
  std::size_t remaining() const { return data_.size() - pos_; }
  void fail(std::string why) {
    if (!failed) error = std::move(why);
    failed = true;
  }
  bool failed = false;
  std::string error;

 private:
  bool need(std::size_t n) { return !failed && n <= remaining(); }
  std::uint64_t le(int n) {
    if (!need(static_cast<std::size_t>(n))) return fail("unexpected end of " + std::string(unit_)), 0;
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t{static_cast<std::uint8_t>(data_[pos_ + static_cast<std::size_t>(i)])} << (8 * i);
    pos_ += static_cast<std::size_t>(n);
    return v;
  }
  std::string_view data_;
  std::string_view unit_;
  std::size_t pos_ = 0;
};

}  // namespace rs::base
