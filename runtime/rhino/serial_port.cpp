#include "runtime/rhino/serial_port.h"

#include <dirent.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <linux/serial.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace rs::rhino {
namespace {

struct BaudEntry {
  int baud;
  speed_t code;
};

constexpr BaudEntry kBauds[] = {
    {50, B50},           {75, B75},           {110, B110},         {134, B134},         {150, B150},
    {200, B200},         {300, B300},         {600, B600},         {1200, B1200},       {1800, B1800},
    {2400, B2400},       {4800, B4800},       {9600, B9600},       {19200, B19200},     {38400, B38400},
    {57600, B57600},     {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
    {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000}, {4000000, B4000000},
};

const BaudEntry* findBaud(int baud) {
  for (const BaudEntry& e : kBauds)
    if (e.baud == baud) return &e;
  return nullptr;
}

// Waits until `fd` is ready for `events` or `timeout` (us) passes. Returns
// the revents, 0 on a timeout or when a signal interrupted the wait (Ctrl-C:
// the interrupt guard installs its handler without SA_RESTART so that the
// caller gets to look at the flag now, not at the timeout), -1 on error
// (errno set).
int waitFor(int fd, short events, Micros timeout) {
  pollfd p{fd, events, 0};
  const int ms = static_cast<int>(std::min<std::int64_t>((std::max<Micros>(timeout, 0) + 999) / 1000, 1'000'000));
  const int n = ::poll(&p, 1, ms);
  if (n > 0) return p.revents;
  if (n == 0 || errno == EINTR) return 0;
  return -1;
}

// POSIX lets tcsetattr() fail (or succeed) with only some changes made, and
// Linux pseudo-terminals refuse some flag changes with EINVAL even when the
// flags are already so: what counts is what reads back.
bool sameSettings(const termios& a, const termios& b) {
  const tcflag_t c = CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS | CLOCAL | CREAD;
  const tcflag_t i = IXON | IXOFF | IXANY | INPCK | ISTRIP | ICRNL | INLCR | IGNCR | PARMRK | IGNPAR;
  const tcflag_t l = ICANON | ECHO | ECHONL | ISIG | IEXTEN;
  return (a.c_cflag & c) == (b.c_cflag & c) && (a.c_iflag & i) == (b.c_iflag & i) &&
         (a.c_lflag & l) == (b.c_lflag & l) && (a.c_oflag & OPOST) == (b.c_oflag & OPOST) &&
         ::cfgetispeed(&a) == ::cfgetispeed(&b) && ::cfgetospeed(&a) == ::cfgetospeed(&b) &&
         a.c_cc[VMIN] == b.c_cc[VMIN] && a.c_cc[VTIME] == b.c_cc[VTIME];
}

bool apply(int fd, const termios& wanted) {
  ::tcsetattr(fd, TCSANOW, &wanted);  // its result says little: see above
  termios got{};
  return ::tcgetattr(fd, &got) == 0 && sameSettings(got, wanted);
}

// UNIX98 pseudo-terminal slaves (/dev/pts/N) have majors 136..143.
bool pseudoTerminal(int fd) {
  struct stat st {};
  return ::fstat(fd, &st) == 0 && major(st.st_rdev) >= 136 && major(st.st_rdev) <= 143;
}

tcflag_t sizeFlag(int bits) {
  switch (bits) {
    case 5: return CS5;
    case 6: return CS6;
    case 7: return CS7;
    default: return CS8;
  }
}

}  // namespace

bool supportedBaud(int baud) { return findBaud(baud) != nullptr; }

std::string describe(const LineSettings& s) {
  const char parity = s.parity == Parity::None ? 'N' : s.parity == Parity::Even ? 'E' : 'O';
  const char* flow = s.flow == FlowControl::None     ? "no flow control"
                     : s.flow == FlowControl::RtsCts ? "RTS/CTS flow control"
                                                     : "XON/XOFF flow control";
  return fmt::format("{} {}{}{}, {}", s.baud, s.dataBits, parity, s.stopBits, flow);
}

std::string configureTerminal(int fd, const LineSettings& s) {
  const BaudEntry* baud = findBaud(s.baud);
  if (!baud) return fmt::format("baud rate {} is not supported", s.baud);
  if (s.dataBits < 5 || s.dataBits > 8) return fmt::format("{} data bits: expected 5..8", s.dataBits);
  if (s.stopBits != 1 && s.stopBits != 2) return fmt::format("{} stop bits: expected 1 or 2", s.stopBits);
  termios t{};
  if (::tcgetattr(fd, &t) != 0) return fmt::format("not a serial device: {}", std::strerror(errno));
  ::cfmakeraw(&t);
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY | ISTRIP | INPCK | PARMRK | IGNPAR);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  t.c_cflag |= CLOCAL | CREAD | sizeFlag(s.dataBits);
  if (s.parity != Parity::None) {
    t.c_cflag |= PARENB;
    if (s.parity == Parity::Odd) t.c_cflag |= PARODD;
    t.c_iflag |= INPCK;  // a byte with a parity error reads as 0x00: garbage, not data
  }
  if (s.stopBits == 2) t.c_cflag |= CSTOPB;
  if (s.flow == FlowControl::RtsCts) t.c_cflag |= CRTSCTS;
  if (s.flow == FlowControl::XonXoff) t.c_iflag |= IXON | IXOFF;
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  if (::cfsetispeed(&t, baud->code) != 0 || ::cfsetospeed(&t, baud->code) != 0)
    return fmt::format("cannot set {} baud: {}", s.baud, std::strerror(errno));
  if (apply(fd, t)) return {};
  const std::string why = std::strerror(errno);
  // A pseudo-terminal (the emulator) has no wire: data bits and parity
  // mean nothing there, and some kernels refuse them. Raw 8-bit is enough.
  if (pseudoTerminal(fd)) {
    t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
    t.c_cflag |= CS8;
    t.c_iflag &= ~static_cast<tcflag_t>(INPCK);
    if (apply(fd, t)) return {};
  }
  return fmt::format("cannot apply the line settings ({}): {}", describe(s), why);
}

std::unique_ptr<SerialPort> SerialPort::open(const std::string& path, const LineSettings& settings,
                                             std::string& error) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error = fmt::format("cannot open {}: {}", path, std::strerror(errno));
    return nullptr;
  }
  if (!::isatty(fd)) {
    error = fmt::format("{} is not a serial device (not a terminal)", path);
    ::close(fd);
    return nullptr;
  }
  if (::ioctl(fd, TIOCEXCL) != 0) {
    error = fmt::format("cannot open {} exclusively: {}", path, std::strerror(errno));
    ::close(fd);
    return nullptr;
  }
  if (std::string e = configureTerminal(fd, settings); !e.empty()) {
    error = fmt::format("{}: {}", path, e);
    ::ioctl(fd, TIOCNXCL);
    ::close(fd);
    return nullptr;
  }
  ::tcflush(fd, TCIOFLUSH);
  return std::unique_ptr<SerialPort>(new SerialPort(path, fd));
}

SerialPort::~SerialPort() {
  if (fd_ < 0) return;
  ::ioctl(fd_, TIOCNXCL);
  ::close(fd_);
}

vm::Status SerialPort::write(std::span<const std::uint8_t> bytes, Micros timeout) {
  const std::int64_t deadline = steadyMicros() + std::max<Micros>(timeout, 0);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      if (errno == EIO || errno == ENXIO || errno == ENODEV || errno == EPIPE)
        return vm::Status::closed(fmt::format("{}: the port is gone ({})", path_, std::strerror(errno)));
      return vm::Status::fault(fmt::format("{}: write failed: {}", path_, std::strerror(errno)));
    }
    const int ready = waitFor(fd_, POLLOUT, deadline - steadyMicros());
    if (ready == 0 && steadyMicros() < deadline) continue;  // a signal: part of a line cannot be taken back
    if (ready == 0) return vm::Status::timeout();
    if (ready < 0) return vm::Status::fault(fmt::format("{}: poll failed: {}", path_, std::strerror(errno)));
    if ((ready & (POLLHUP | POLLERR | POLLNVAL)) && !(ready & POLLOUT))
      return vm::Status::closed(fmt::format("{}: the port hung up", path_));
  }
  return vm::Status::ok();
}

// A signal ends the wait early with a timeout: the ControllerSession looks at the
// Ctrl-C flag and reads again with the time that is left.
vm::Status SerialPort::read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) {
  count = 0;
  const int ready = waitFor(fd_, POLLIN, timeout);
  if (ready == 0) return vm::Status::timeout();
  if (ready < 0) return vm::Status::fault(fmt::format("{}: poll failed: {}", path_, std::strerror(errno)));
  for (;;) {
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) {
      count = static_cast<std::size_t>(n);
      return vm::Status::ok();
    }
    if (n == 0) return vm::Status::closed(fmt::format("{}: the port hung up", path_));
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) {
      if (ready & (POLLHUP | POLLERR | POLLNVAL)) return vm::Status::closed(fmt::format("{}: the port hung up", path_));
      return vm::Status::timeout();
    }
    if (errno == EIO || errno == ENXIO || errno == ENODEV)
      return vm::Status::closed(fmt::format("{}: the port is gone ({})", path_, std::strerror(errno)));
    return vm::Status::fault(fmt::format("{}: read failed: {}", path_, std::strerror(errno)));
  }
}

namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& dir, const std::string& prefix) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() > prefix.size()) names.push_back(name);
  }
  // Natural order: ttyS2 before ttyS10.
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return names;
}

// A /dev/ttyS* node exists for every possible 8250 port; TIOCGSERIAL says
// whether a UART answered at boot.
bool uartPresent(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return errno == EBUSY || errno == EACCES;  // in use or not ours: something is there
  serial_struct info{};
  const bool present = ::ioctl(fd, TIOCGSERIAL, &info) != 0 || info.type != PORT_UNKNOWN;
  ::close(fd);
  return present;
}

}  // namespace

std::vector<PortInfo> listPorts(const std::string& root) {
  std::vector<PortInfo> ports;
  const fs::path dev(root);
  for (const std::string& name : entries(dev / "serial" / "by-id", "")) {
    std::error_code ec;
    const fs::path link = dev / "serial" / "by-id" / name;
    const fs::path target = fs::read_symlink(link, ec);
    ports.push_back({link.string(), ec ? "stable name" : "-> " + target.string(), true});
  }
  for (const std::string& name : entries(dev, "ttyUSB"))
    ports.push_back({(dev / name).string(), "USB serial adapter", true});
  for (const std::string& name : entries(dev, "ttyACM"))
    ports.push_back({(dev / name).string(), "USB modem-class (CDC ACM) device", true});
  for (const std::string& name : entries(dev, "ttyS")) {
    const std::string path = (dev / name).string();
    const bool present = root != "/dev" || uartPresent(path);
    ports.push_back({path, present ? "built-in serial port" : "no UART detected", present});
  }
  return ports;
}

}  // namespace rs::rhino
