// The serial log (--log-serial FILE): every byte each way with a timestamp,
// plus a line for each timeout, error and stop, for debugging a lab robot.
// The format is in docs/serial.md ("Log format"); golden transcripts in the
// tests are this format on a manual clock.
#pragma once

#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "runtime/rhino/link.h"

namespace rs::rhino {

class SerialLog {
 public:
  /// Appends to nothing: the log writes into `out` (tests, stderr).
  explicit SerialLog(std::ostream& out) : out_(&out) {}
  /// Creates (truncates) `path`; null with `error` set when it cannot.
  static std::unique_ptr<SerialLog> create(const std::string& path, std::string& error);

  /// "# text" (a header or comment line, no timestamp).
  void comment(std::string_view text);
  /// "T > 45 2B 34 30 0D  "E+40\r"": bytes sent to the controller; with
  /// `failure`, the write did not complete and the reason follows.
  void sent(Micros t, std::span<const std::uint8_t> bytes, std::string_view failure = {});
  /// "T < 5F  "_"": bytes received from the controller.
  void received(Micros t, std::span<const std::uint8_t> bytes);
  /// "T ! text": a timeout, error, stop or interrupt.
  void event(Micros t, std::string_view text);

 private:
  explicit SerialLog(std::unique_ptr<std::ofstream> file) : file_(std::move(file)), out_(file_.get()) {}
  void bytesLine(Micros t, char direction, std::span<const std::uint8_t> bytes, std::string_view tail);
  std::unique_ptr<std::ofstream> file_;
  std::ostream* out_;
};

/// "12.345678": seconds with microseconds, for logs.
std::string logTime(Micros t);
/// Bytes as a C string literal body: printable ASCII as is, \r \n \\ \" and
/// \xHH for the rest ("E+40\r").
std::string escapeBytes(std::span<const std::uint8_t> bytes);

/// A Link that records everything that passes through it in a SerialLog,
/// timestamped by `clock`.
class LoggedLink final : public Link {
 public:
  LoggedLink(Link& inner, SerialLog& log, const Clock& clock) : inner_(inner), log_(log), clock_(clock) {}
  vm::Status write(std::span<const std::uint8_t> bytes, Micros timeout) override;
  vm::Status read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) override;
  std::string name() const override { return inner_.name(); }

 private:
  Link& inner_;
  SerialLog& log_;
  const Clock& clock_;
};

}  // namespace rs::rhino
