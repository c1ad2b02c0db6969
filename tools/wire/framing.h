// Messages over a byte stream, framed as the Language Server Protocol and
// the Debug Adapter Protocol both frame them: a header block
// ("Content-Length: N\r\n", optionally "Content-Type: ...\r\n", then an
// empty line) and N bytes of JSON. `robotsim lsp` and `robotsim dap` read
// and write their messages with this one code. The reader never trusts the stream: a
// header without a usable Content-Length is reported and skipped up to the
// next header block, a body over the size limit is reported and skipped as
// it arrives (never held), and a header block that never ends is cut off.
//
// parseFrames() is the pure function behind it (bytes in, frames out, no
// I/O): the fuzz target for the framing drives it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs::wire {

/// A message body larger than this is refused (and skipped).
inline constexpr std::size_t kMaxMessageBytes = std::size_t{64} << 20;
/// A header block longer than this is not a header block.
inline constexpr std::size_t kMaxHeaderBytes = std::size_t{8} << 10;

/// One thing found in the stream: a message body, or a problem with the
/// framing (what was wrong, as a sentence).
struct Frame {
  enum class Kind { Message, BadHeader, TooLarge };
  Kind kind = Kind::Message;
  std::string body;     ///< Message: the JSON text, unparsed
  std::string problem;  ///< BadHeader, TooLarge
};

/// Frames from bytes fed as they arrive.
class FrameParser {
 public:
  explicit FrameParser(std::size_t maxBody = kMaxMessageBytes) : maxBody_(maxBody) {}
  void feed(std::string_view bytes);
  /// The next frame the bytes fed so far hold, if any.
  std::optional<Frame> next();
  /// Bytes fed and not yet part of a frame (a message cut off at EOF).
  bool partial() const { return start_ < buffer_.size() || skip_ > 0; }

 private:
  std::optional<Frame> header();
  void resync();
  void compact();

  std::size_t maxBody_;
  std::string buffer_;
  std::size_t start_ = 0;    // where the unread bytes begin in buffer_
  std::size_t skip_ = 0;     // body bytes of a refused message still to drop
  bool resyncing_ = false;   // looking for the next "Content-Length"
};

/// Every frame in `bytes`, in order (the pure form of FrameParser, for
/// fuzzing and tests).
std::vector<Frame> parseFrames(std::string_view bytes, std::size_t maxBody = kMaxMessageBytes);

/// `body` framed for the wire.
std::string frameMessage(std::string_view body);
/// The header block before a body of this size (a large body can then be
/// written after it as it is, without a framed copy).
std::string frameHeader(std::size_t bodySize);

}  // namespace rs::wire
