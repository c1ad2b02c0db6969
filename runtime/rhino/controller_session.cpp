#include "runtime/rhino/controller_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <utility>

#include "base/seconds.h"

namespace rs::rhino {
namespace {

std::span<const std::uint8_t> bytesOf(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace

vm::Status ControllerSession::checkInterrupt() const {
  if (interrupt_ && interrupt_->load()) return vm::Status::fault("interrupted (Ctrl-C)");
  return vm::Status::ok();
}

void ControllerSession::note(std::string_view text) {
  if (log_) log_->event(clock_.now(), text);
}

// A read that timed out because Ctrl-C cut the wait short is an
// interruption, not a silent controller.
vm::Status ControllerSession::ioFailure(const vm::Status& r, std::string_view command, bool writing) {
  std::string message;
  silent_ = false;
  switch (r.code) {
    case vm::Status::Code::Ok: return vm::Status::ok();
    case vm::Status::Code::Timeout:
      if (!writing)
        if (auto s = checkInterrupt(); !s) return s;
      message = writing ? fmt::format("the serial line to {} is blocked: \"{}\" could not be sent within {} s", device_,
                                      escapeBytes(bytesOf(command)), base::formatSeconds(settings_.timeout))
                        : fmt::format("no reply from the controller to \"{}\" within {} s (timeout)",
                                      escapeBytes(bytesOf(command)), base::formatSeconds(settings_.timeout));
      silent_ = !writing;
      break;
    case vm::Status::Code::Closed:
      gone_ = true;
      message = fmt::format("the serial port {} hung up at \"{}\" (the controller is gone)", device_,
                            escapeBytes(bytesOf(command)));
      note(r.message);
      break;
    case vm::Status::Code::Fault:
    case vm::Status::Code::Deadlock:  // no link answers these
    case vm::Status::Code::NotYet:
      message = fmt::format("serial I/O error at \"{}\": {}", escapeBytes(bytesOf(command)), r.message);
      break;
  }
  note(message);
  return vm::Status::fault(std::move(message));
}

vm::Status ControllerSession::garbage(std::string_view command, std::span<const std::uint8_t> reply, std::string_view expected) {
  std::string message = reply.empty()
                            ? fmt::format("garbage from the controller: \"{}\" was answered out of range (expected {})",
                                          escapeBytes(bytesOf(command)), expected)
                            : fmt::format("garbage from the controller: \"{}\" was answered with \"{}\" (expected {})",
                                          escapeBytes(bytesOf(command)), escapeBytes(reply), expected);
  note(message);
  return vm::Status::fault(std::move(message));
}

vm::Status ControllerSession::send(std::string_view command) {
  if (auto s = checkInterrupt(); !s) return s;
  const vm::Status st = sendUnchecked(command);
  if (!st)
    if (auto s = checkInterrupt(); !s) return s;  // Ctrl-C while the line was blocked
  return st;
}

// A link read ends early with nothing when a signal cuts its wait short
// (SerialPort): read again with the time left, unless it was Ctrl-C.
vm::Status ControllerSession::readBy(std::span<std::uint8_t> buffer, Micros deadline, std::size_t& count) {
  for (;;) {
    vm::Status r = link_.read(buffer, std::max<Micros>(deadline - clock_.now(), 0), count);
    if (r.code != vm::Status::Code::Timeout || clock_.now() >= deadline || !checkInterrupt()) return r;
  }
}

vm::Status ControllerSession::sendUnchecked(std::string_view command) {
  std::string line(command);
  line += lineEndBytes(settings_.lineEnd);
  const vm::Status r = link_.write(bytesOf(line), settings_.timeout);
  return ioFailure(r, command, true);
}

// Anything waiting before a question is an answer to nothing: the line is
// out of step with the controller. Mark IV may trail a LF after its CR.
vm::Status ControllerSession::expectQuiet(std::string_view command) {
  std::vector<std::uint8_t> got = std::exchange(unread_, {});
  std::array<std::uint8_t, 64> buf{};
  std::size_t count = 0;
  const vm::Status r = link_.read(buf, 0, count);
  if (!r && r.code != vm::Status::Code::Timeout) return ioFailure(r, command, false);
  if (r) got.insert(got.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(count));
  const bool whitespace = settings_.dialect == Dialect::Mark4 &&
                          std::all_of(got.begin(), got.end(), [](std::uint8_t b) { return b == '\r' || b == '\n'; });
  if (got.empty() || whitespace) return vm::Status::ok();
  std::string message = fmt::format("garbage from the controller: \"{}\" arrived unasked before \"{}\"",
                                    escapeBytes(got), escapeBytes(bytesOf(command)));
  note(message);
  return vm::Status::fault(std::move(message));
}

vm::Status ControllerSession::queryByte(std::string_view command, std::uint8_t& reply) {
  if (auto s = expectQuiet(command); !s) return s;
  if (auto s = send(command); !s) return s;
  std::array<std::uint8_t, 1> buf{};
  std::size_t count = 0;
  const vm::Status r = readBy(buf, clock_.now() + settings_.timeout, count);
  if (!r) return ioFailure(r, command, false);
  reply = buf[0];
  return vm::Status::ok();
}

vm::Status ControllerSession::queryNumber(std::string_view command, long& value) {
  if (auto s = expectQuiet(command); !s) return s;
  if (auto s = send(command); !s) return s;
  const Micros deadline = clock_.now() + settings_.timeout;
  std::vector<std::uint8_t> reply;
  for (;;) {
    std::array<std::uint8_t, 32> buf{};
    std::size_t count = 0;
    const vm::Status r = readBy(buf, deadline, count);
    if (!r) {
      if (r.code == vm::Status::Code::Timeout && !reply.empty() && checkInterrupt())
        return garbage(command, reply, "a decimal number ended by CR; the CR never came");
      return ioFailure(r, command, false);
    }
    reply.insert(reply.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(count));
    while (!reply.empty() && reply.front() == '\n') reply.erase(reply.begin());  // LF left from CR LF
    const auto cr = std::find(reply.begin(), reply.end(), '\r');
    if (cr != reply.end()) {
      unread_.assign(cr + 1, reply.end());
      reply.erase(cr, reply.end());
      break;
    }
    if (reply.size() > 12) return garbage(command, reply, "a decimal number ended by CR");
  }
  std::size_t i = 0;
  while (i < reply.size() && reply[i] == ' ') ++i;
  const bool negative = i < reply.size() && reply[i] == '-';
  if (negative || (i < reply.size() && reply[i] == '+')) ++i;
  if (i == reply.size() || reply.size() - i > 10) return garbage(command, reply, "a decimal number ended by CR");
  long v = 0;
  for (; i < reply.size(); ++i) {
    if (reply[i] < '0' || reply[i] > '9') return garbage(command, reply, "a decimal number ended by CR");
    v = v * 10 + (reply[i] - '0');
  }
  value = negative ? -v : v;
  return vm::Status::ok();
}

vm::Status ControllerSession::pause(Micros duration) {
  const Micros end = clock_.now() + std::max<Micros>(duration, 0);
  for (;;) {
    if (auto s = checkInterrupt(); !s) return s;
    const Micros left = end - clock_.now();
    if (left <= 0) return vm::Status::ok();
    clock_.sleepFor(std::min<Micros>(left, 20'000));  // Ctrl-C answered within 20 ms
  }
}

std::vector<std::string> stopCommands(Dialect d, const std::vector<vm::MotorSpec>& motors) {
  if (d == Dialect::Mark4) return {"MA"};
  std::vector<std::string> commands;
  for (const vm::MotorSpec& m : motors) commands.push_back(fmt::format("{}X", m.letter));
  return commands;
}

std::string sendStop(ControllerSession& session, const std::vector<std::string>& commands) {
  std::string list;
  std::string failure;
  for (const std::string& c : commands) {
    list += (list.empty() ? "" : " ") + c;
    if (vm::Status st = session.sendUnchecked(c); !st && failure.empty())
      failure = session.portGone() ? "the port is gone" : st.message;
  }
  if (failure.empty()) return fmt::format("stop sent to every motor ({})", list);
  return fmt::format("stop could NOT be sent to every motor ({}): {}; switch the controller off", list, failure);
}

std::string unsupportedMotor(Dialect d, const std::vector<vm::MotorSpec>& motors) {
  for (const vm::MotorSpec& m : motors)
    if (m.letter < 'A' || m.letter > 'H')
      return fmt::format("motor {}: a {} controller has motors A..H only", m.letter, dialectTitle(d));
  return {};
}

}  // namespace rs::rhino
