// A POSIX serial port (termios): raw mode, the Rhino line settings by
// default (9600 baud, 7 data bits, even parity, 2 stop bits, no flow
// control), every one of them a setting, reads and writes bounded by poll().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/rhino/link.h"

namespace rs::rhino {

enum class Parity : std::uint8_t { None, Even, Odd };
enum class FlowControl : std::uint8_t { None, RtsCts, XonXoff };

struct LineSettings {
  int baud = 9600;
  int dataBits = 7;  // 5..8
  Parity parity = Parity::Even;
  int stopBits = 2;  // 1 or 2
  FlowControl flow = FlowControl::None;
  bool operator==(const LineSettings&) const = default;
};

/// "9600 7E2, no flow control" (for logs and messages).
std::string describe(const LineSettings& s);

/// True when termios knows `baud` (50 ... 4000000).
bool supportedBaud(int baud);

class SerialPort final : public Link {
 public:
  /// Opens `path` (O_NOCTTY, exclusive), applies `settings` in raw mode and
  /// drops whatever was waiting. Null with `error` set on failure.
  static std::unique_ptr<SerialPort> open(const std::string& path, const LineSettings& settings, std::string& error);
  ~SerialPort() override;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  vm::Status write(std::span<const std::uint8_t> bytes, Micros timeout) override;
  vm::Status read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) override;
  std::string name() const override { return path_; }
  int fd() const { return fd_; }

 private:
  SerialPort(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
  std::string path_;
  int fd_ = -1;
};

/// Applies `settings` in raw mode to an open terminal; the error or "".
std::string configureTerminal(int fd, const LineSettings& settings);

/// A candidate serial device for `robotsim ports`.
struct PortInfo {
  std::string path;
  std::string note;    // "USB serial", "-> ../../ttyUSB0", "no UART detected", ...
  bool likely = true;  // false: a /dev/ttyS* node with no UART behind it
};

/// /dev/serial/by-id/*, /dev/ttyUSB*, /dev/ttyACM*, /dev/ttyS* (sorted
/// within each group). `root` replaces "/dev" (tests).
std::vector<PortInfo> listPorts(const std::string& root = "/dev");

}  // namespace rs::rhino
