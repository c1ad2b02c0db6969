// The bytes under the protocol: where messages come from and go to. A
// server (the language server, the debug adapter) reads stdin and writes stdout through file descriptors (so that a
// vanished client is EOF or EPIPE, never a signal or a hang); tests drive
// it through streams.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string_view>

namespace rs::wire {

class Input {
 public:
  virtual ~Input() = default;
  /// Waits for bytes and reads at most `n` of them; 0 at the end of input.
  virtual std::size_t read(char* into, std::size_t n) = 0;
  /// True when read() would return at once.
  virtual bool ready() = 0;
};

class Output {
 public:
  virtual ~Output() = default;
  /// Writes all of `bytes`; false when the other side is gone.
  virtual bool write(std::string_view bytes) = 0;
};

class FdInput final : public Input {
 public:
  explicit FdInput(int fd) : fd_(fd) {}
  std::size_t read(char* into, std::size_t n) override;
  bool ready() override;

 private:
  int fd_;
};

class FdOutput final : public Output {
 public:
  /// Ignores SIGPIPE for the process: a closed pipe is an error value.
  explicit FdOutput(int fd);
  bool write(std::string_view bytes) override;

 private:
  int fd_;
};

class StreamInput final : public Input {
 public:
  explicit StreamInput(std::istream& in) : in_(in) {}
  std::size_t read(char* into, std::size_t n) override;
  bool ready() override;

 private:
  std::istream& in_;
};

class StreamOutput final : public Output {
 public:
  explicit StreamOutput(std::ostream& out) : out_(out) {}
  bool write(std::string_view bytes) override;

 private:
  std::ostream& out_;
};

}  // namespace rs::wire
