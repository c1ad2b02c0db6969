// The emulator on a pseudo-terminal: the engine behind a pty's master
// side, pumped by poll(), so a program opens the slave as a serial port.
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "runtime/rhino/emulator.h"
#include "runtime/rhino/serial_port.h"

namespace rs::rhino {

std::unique_ptr<PtyEmulator> PtyEmulator::open(EmulatorConfig config, std::string& error) {
  int master = -1;
  int slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    error = fmt::format("cannot create a pseudo-terminal: {}", std::strerror(errno));
    return nullptr;
  }
  char name[256] = {};
  if (::ttyname_r(slave, name, sizeof name) != 0) {
    error = fmt::format("cannot name the pseudo-terminal: {}", std::strerror(errno));
    ::close(master);
    ::close(slave);
    return nullptr;
  }
  if (std::string e = configureTerminal(slave, config.settings.line); !e.empty()) {
    error = fmt::format("cannot configure the pseudo-terminal: {}", e);
    ::close(master);
    ::close(slave);
    return nullptr;
  }
  ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
  ::fcntl(master, F_SETFD, FD_CLOEXEC);
  ::fcntl(slave, F_SETFD, FD_CLOEXEC);
  return std::unique_ptr<PtyEmulator>(new PtyEmulator(std::move(config), master, slave, name));
}

PtyEmulator::PtyEmulator(EmulatorConfig config, int master, int slave, std::string path)
    : engine_(std::move(config)), master_(master), slave_(slave), path_(std::move(path)) {}

PtyEmulator::~PtyEmulator() {
  stop();
  hangUp();
}

void PtyEmulator::hangUp() {
  if (master_ >= 0) ::close(master_);
  if (slave_ >= 0) ::close(slave_);
  master_ = slave_ = -1;
}

bool PtyEmulator::pump(Micros wait, int extraFd) {
  Micros timeout = std::max<Micros>(wait, 0);
  {
    std::lock_guard lock(mutex_);
    if (auto due = engine_.nextReplyAt()) timeout = std::clamp<Micros>(*due - clock_.now(), 0, timeout);
  }
  pollfd fds[2] = {{master_, POLLIN, 0}, {extraFd, POLLIN, 0}};
  const int n = ::poll(fds, 2, static_cast<int>((timeout + 999) / 1000));
  bool extra = false;
  if (n > 0) extra = extraFd >= 0 && (fds[1].revents & (POLLIN | POLLHUP)) != 0;
  std::lock_guard lock(mutex_);
  if (master_ >= 0 && n > 0 && (fds[0].revents & POLLIN)) {
    std::uint8_t buf[512];
    for (;;) {
      const ssize_t got = ::read(master_, buf, sizeof buf);
      if (got <= 0) break;
      engine_.receive({buf, static_cast<std::size_t>(got)}, clock_.now());
    }
  }
  engine_.advance(clock_.now());
  const std::vector<std::uint8_t> out = engine_.takeReplies(clock_.now());
  std::size_t done = 0;
  while (master_ >= 0 && done < out.size()) {
    const ssize_t w = ::write(master_, out.data() + done, out.size() - done);
    if (w > 0)
      done += static_cast<std::size_t>(w);
    else if (w < 0 && errno == EINTR)
      continue;
    else
      break;  // the host is not reading: the answer is lost, as on a real line
  }
  if (engine_.hungUp()) hangUp();
  return extra;
}

void PtyEmulator::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] {
    while (running_) pump(2'000);
  });
}

void PtyEmulator::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

bool PtyEmulator::hungUp() const {
  std::lock_guard lock(mutex_);
  return engine_.hungUp();
}

void PtyEmulator::setInput(int line, bool on) {
  std::lock_guard lock(mutex_);
  engine_.setInput(line, on);
}

void PtyEmulator::forceSwitch(char letter, std::optional<bool> closed) {
  std::lock_guard lock(mutex_);
  engine_.forceSwitch(letter, closed);
}

void PtyEmulator::setFault(FaultPlan plan) {
  std::lock_guard lock(mutex_);
  engine_.setFault(plan);
}

EmulatorSnapshot PtyEmulator::snapshot() {
  std::lock_guard lock(mutex_);
  engine_.advance(clock_.now());
  return engine_.snapshot();
}

std::vector<std::string> PtyEmulator::received() {
  std::lock_guard lock(mutex_);
  return {engine_.received().begin(), engine_.received().end()};
}

std::vector<std::string> PtyEmulator::receivedSince(std::uint64_t& seen) {
  std::lock_guard lock(mutex_);
  return engine_.receivedSince(seen);
}

std::vector<std::string> PtyEmulator::takeEvents() {
  std::lock_guard lock(mutex_);
  return engine_.takeEvents();
}

std::string PtyEmulator::statusLine() {
  std::lock_guard lock(mutex_);
  engine_.advance(clock_.now());
  return engine_.statusLine();
}

}  // namespace rs::rhino
