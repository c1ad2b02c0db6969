#include "runtime/rhino/serial_log.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>

namespace rs::rhino {

std::string logTime(Micros t) {
  const char* sign = t < 0 ? "-" : "";
  const std::uint64_t u = t < 0 ? 0 - static_cast<std::uint64_t>(t) : static_cast<std::uint64_t>(t);
  return fmt::format("{}{}.{:06}", sign, u / 1'000'000, u % 1'000'000);
}

std::string escapeBytes(std::span<const std::uint8_t> bytes) {
  std::string s;
  for (const std::uint8_t b : bytes) {
    switch (b) {
      case '\r': s += "\\r"; break;
      case '\n': s += "\\n"; break;
      case '\\': s += "\\\\"; break;
      case '"': s += "\\\""; break;
      default:
        if (b >= 0x20 && b < 0x7F)
          s += static_cast<char>(b);
        else
          s += fmt::format("\\x{:02X}", b);
    }
  }
  return s;
}

std::unique_ptr<SerialLog> SerialLog::create(const std::string& path, std::string& error) {
  auto file = std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc);
  if (!*file) {
    error = fmt::format("cannot write the serial log {}: {}", path, std::strerror(errno));
    return nullptr;
  }
  return std::unique_ptr<SerialLog>(new SerialLog(std::move(file)));
}

void SerialLog::comment(std::string_view text) {
  *out_ << "# " << text << '\n';
  out_->flush();
}

void SerialLog::bytesLine(Micros t, char direction, std::span<const std::uint8_t> bytes, std::string_view tail) {
  std::string hex;
  for (const std::uint8_t b : bytes) {
    if (!hex.empty()) hex += ' ';
    hex += fmt::format("{:02X}", b);
  }
  *out_ << fmt::format("{:>11} {} {}  \"{}\"{}\n", logTime(t), direction, hex, escapeBytes(bytes), tail);
  out_->flush();  // a crash or Ctrl-C must not lose the last lines
}

void SerialLog::sent(Micros t, std::span<const std::uint8_t> bytes, std::string_view failure) {
  bytesLine(t, '>', bytes, failure.empty() ? std::string() : fmt::format("  (not sent: {})", failure));
}

void SerialLog::received(Micros t, std::span<const std::uint8_t> bytes) { bytesLine(t, '<', bytes, {}); }

void SerialLog::event(Micros t, std::string_view text) {
  *out_ << fmt::format("{:>11} ! {}\n", logTime(t), text);
  out_->flush();
}

vm::Status LoggedLink::write(std::span<const std::uint8_t> bytes, Micros timeout) {
  const Micros t = clock_.now();
  vm::Status r = inner_.write(bytes, timeout);
  if (r)
    log_.sent(t, bytes);
  else
    log_.sent(t, bytes, r.code == vm::Status::Code::Timeout ? "write timed out" : r.message);
  return r;
}

vm::Status LoggedLink::read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) {
  vm::Status r = inner_.read(buffer, timeout, count);
  if (r)
    log_.received(clock_.now(), buffer.first(count));
  else if (r.code == vm::Status::Code::Closed || r.code == vm::Status::Code::Fault)
    log_.event(clock_.now(), r.message);
  return r;
}

}  // namespace rs::rhino
