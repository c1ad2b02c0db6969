#include "tools/wire/framing.h"

#include <fmt/format.h>

#include <charconv>

#include "base/ascii.h"

namespace rs::wire {

namespace {

constexpr std::string_view kLengthHeader = "Content-Length";

// Where "Content-Length" (any case) next starts in `text` at or after `from`.
std::size_t findLengthHeader(std::string_view text, std::size_t from) {
  for (std::size_t i = from; i + kLengthHeader.size() <= text.size(); ++i)
    if (base::sameName(text.substr(i, kLengthHeader.size()), kLengthHeader)) return i;
  return std::string_view::npos;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// The end of the header block starting at `from` (just past its empty
// line), accepting CR LF or bare LF line ends; npos when not yet complete.
std::size_t headerEnd(std::string_view text, std::size_t from, std::size_t& blockEnd) {
  for (std::size_t i = from; i < text.size(); ++i) {
    if (text[i] != '\n') continue;
    const std::size_t next = i + 1;
    if (next < text.size() && text[next] == '\n') return blockEnd = i, next + 1;
    if (next + 1 < text.size() && text[next] == '\r' && text[next + 1] == '\n') return blockEnd = i, next + 2;
  }
  return std::string_view::npos;
}

}  // namespace

void FrameParser::feed(std::string_view bytes) {
  if (skip_ > 0) {
    const std::size_t dropped = std::min(skip_, bytes.size());
    skip_ -= dropped;
    bytes.remove_prefix(dropped);
  }
  buffer_.append(bytes);
}

void FrameParser::compact() {
  if (start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  } else if (start_ > (std::size_t{1} << 16) && start_ > buffer_.size() / 2) {
    buffer_.erase(0, start_);
    start_ = 0;
  }
}

// Drops bytes up to the next "Content-Length" (keeping a tail that may be
// the start of one still arriving).
void FrameParser::resync() {
  const std::size_t at = findLengthHeader(buffer_, start_);
  if (at != std::string::npos) {
    start_ = at;
    resyncing_ = false;
  } else if (buffer_.size() - start_ > kLengthHeader.size()) {
    start_ = buffer_.size() - kLengthHeader.size();
  }
  compact();
}

std::optional<Frame> FrameParser::next() {
  if (skip_ > 0) return std::nullopt;
  if (resyncing_) resync();
  if (resyncing_) return std::nullopt;
  // Blank lines between messages are tolerated.
  while (start_ < buffer_.size() && (buffer_[start_] == '\r' || buffer_[start_] == '\n')) ++start_;
  compact();
  return header();
}

std::optional<Frame> FrameParser::header() {
  const std::string_view text(buffer_);
  std::size_t blockEnd = 0;
  const std::size_t bodyStart = headerEnd(text, start_, blockEnd);
  if (bodyStart == std::string_view::npos || bodyStart - start_ > kMaxHeaderBytes) {
    if (buffer_.size() - start_ <= kMaxHeaderBytes) return std::nullopt;
    start_ += 1;
    resyncing_ = true;
    return Frame{Frame::Kind::BadHeader, {}, fmt::format("no header block within {} bytes", kMaxHeaderBytes)};
  }
  std::optional<std::size_t> length;
  std::string problem;
  for (std::size_t line = start_; line <= blockEnd && problem.empty();) {
    std::size_t end = text.find('\n', line);
    if (end == std::string_view::npos || end > blockEnd) end = blockEnd;
    const std::string_view field = text.substr(line, end - line);
    line = end + 1;
    const std::size_t colon = field.find(':');
    if (colon == std::string_view::npos) {
      problem = "a header line without ':'";
      break;
    }
    if (!base::sameName(trim(field.substr(0, colon)), kLengthHeader)) continue;
    const std::string_view value = trim(field.substr(colon + 1));
    std::size_t n = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (value.empty() || ec != std::errc() || ptr != value.data() + value.size())
      problem = fmt::format("Content-Length is not a number");
    else
      length = n;
  }
  if (problem.empty() && !length) problem = "a header block without Content-Length";
  if (!problem.empty()) {
    // The next header may start inside this block (a body cut short by a
    // Content-Length that was too small runs into it): look from here on.
    start_ += 1;
    resyncing_ = true;
    return Frame{Frame::Kind::BadHeader, {}, problem};
  }
  if (*length > maxBody_) {
    start_ = bodyStart;
    const std::size_t here = std::min(*length, buffer_.size() - start_);
    start_ += here;
    skip_ = *length - here;
    compact();
    return Frame{Frame::Kind::TooLarge, {},
                 fmt::format("a message of {} bytes; the limit is {} bytes", *length, maxBody_)};
  }
  if (buffer_.size() - bodyStart < *length) return std::nullopt;
  Frame frame{Frame::Kind::Message, buffer_.substr(bodyStart, *length), {}};
  start_ = bodyStart + *length;
  compact();
  return frame;
}

std::vector<Frame> parseFrames(std::string_view bytes, std::size_t maxBody) {
  FrameParser parser(maxBody);
  parser.feed(bytes);
  std::vector<Frame> frames;
  while (std::optional<Frame> f = parser.next()) frames.push_back(std::move(*f));
  return frames;
}

std::string frameHeader(std::size_t bodySize) { return fmt::format("Content-Length: {}\r\n\r\n", bodySize); }

std::string frameMessage(std::string_view body) { return frameHeader(body.size()).append(body); }

}  // namespace rs::wire
