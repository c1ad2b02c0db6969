#include "tools/teach/tui/tui_curses.h"

#include <curses.h>
#include <signal.h>
#include <term.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <vector>
#include <fmt/format.h>

#include "tools/teach/tui/tui_session.h"

namespace rs::teach::tui {

namespace {

volatile sig_atomic_t stopSignal = 0;

// What the crash handler writes: copied at start, so the handler reads
// only static memory.
struct CrashRestore {
  bool armed = false;
  struct termios modes {};
  char leave[64] = {};  // rmcup, then cnorm, then sgr0
  std::size_t leaveLength = 0;
} crash;

// The SIGINT handler in force before the pendant's: with --device, the
// serial layer's (runtime/rhino/interrupt.h), which makes a move under
// way stop every motor at the first Ctrl-C and writes stop to the port and
// exits at a second. The pendant's handler calls it too, so Ctrl-C stops a
// real robot as in a run.
struct sigaction previousInterrupt {};

// Puts the terminal back with async-signal-safe calls only.
void restoreFromHandler() {
  if (!crash.armed) return;
  ::tcsetattr(STDIN_FILENO, TCSANOW, &crash.modes);
  if (crash.leaveLength > 0) {
    const ssize_t n = ::write(STDOUT_FILENO, crash.leave, crash.leaveLength);
    (void)n;
  }
}

void onStop(int sig) {
  const bool again = stopSignal != 0;
  stopSignal = sig;
  const auto chained = previousInterrupt.sa_handler;
  if (sig != SIGINT || (previousInterrupt.sa_flags & SA_SIGINFO) != 0 || chained == SIG_DFL || chained == SIG_IGN)
    return;
  if (again) restoreFromHandler();  // the serial layer's second Ctrl-C exits at once
  chained(sig);
}

void onCrash(int sig) {
  restoreFromHandler();
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void appendCap(const char* name) {
  char* s = tigetstr(const_cast<char*>(name));
  if (s == nullptr || s == reinterpret_cast<char*>(-1)) return;
  const std::size_t n = std::strlen(s);
  if (crash.leaveLength + n > sizeof crash.leave) return;
  std::memcpy(crash.leave + crash.leaveLength, s, n);
  crash.leaveLength += n;
}

// The signal handlers in force while the pendant runs, put back after.
class Handlers {
 public:
  Handlers() {
    for (const int sig : kStop) install(sig, onStop);
    for (const int sig : kCrash) install(sig, onCrash);
  }
  ~Handlers() {
    for (std::size_t i = 0; i < saved_.size(); ++i) ::sigaction(savedSignal_[i], &saved_[i], nullptr);
    previousInterrupt = {};
  }
  Handlers(const Handlers&) = delete;
  Handlers& operator=(const Handlers&) = delete;

 private:
  static constexpr int kStop[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
  static constexpr int kCrash[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
  void install(int sig, void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    struct sigaction old {};
    ::sigaction(sig, &action, &old);
    if (sig == SIGINT) previousInterrupt = old;
    saved_.push_back(old);
    savedSignal_.push_back(sig);
  }
  std::vector<struct sigaction> saved_;
  std::vector<int> savedSignal_;
};

// ncurses for the lifetime of the object; endwin() on every way out of scope.
class Curses {
 public:
  explicit Curses(std::string& error) {
    if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO)) {
      error = "the terminal pendant needs a terminal on standard input and output (without one, leave out --tui)";
      return;
    }
    ::tcgetattr(STDIN_FILENO, &crash.modes);
    screen_ = newterm(nullptr, stdout, stdin);
    if (screen_ == nullptr) {
      const char* term = std::getenv("TERM");
      error = fmt::format("cannot drive the terminal (TERM={})", term ? term : "");
      return;
    }
    appendCap("rmcup");
    appendCap("cnorm");
    appendCap("sgr0");
    crash.armed = true;
    cbreak();  // Ctrl-C stays a signal: it quits, cleanly
    noecho();
    keypad(stdscr, TRUE);
    set_escdelay(25);
    timeout(100);
    if (has_colors()) {
      start_color();
      use_default_colors();
      init_pair(1, COLOR_RED, -1);
      init_pair(2, COLOR_GREEN, -1);
    }
  }
  ~Curses() {
    if (screen_ == nullptr) return;
    curs_set(1);
    endwin();
    crash.armed = false;
    delscreen(screen_);
  }
  Curses(const Curses&) = delete;
  Curses& operator=(const Curses&) = delete;
  bool ok() const { return screen_ != nullptr; }

 private:
  SCREEN* screen_ = nullptr;
};

// An ncurses key as the shared key map names it ("" for keys it ignores).
std::string keyName(int key) {
  switch (key) {
    case KEY_UP: return "ArrowUp";
    case KEY_DOWN: return "ArrowDown";
    case KEY_LEFT: return "ArrowLeft";
    case KEY_RIGHT: return "ArrowRight";
    case KEY_PPAGE: return "PageUp";
    case KEY_NPAGE: return "PageDown";
    case KEY_ENTER:
    case '\n':
    case '\r': return "Enter";
    case KEY_BACKSPACE:
    case 127:
    case 8: return "Backspace";
    case 27: return "Escape";
    case KEY_RESIZE: return "Resize";
    default: break;
  }
  if (key >= 0x20 && key < 0x7f) return std::string(1, static_cast<char>(key));
  if (key == 3 || key == 7) return std::string(1, static_cast<char>(key));
  return "";
}

attr_t attributeOf(Paint paint) {
  const bool colour = has_colors();
  switch (paint) {
    case Paint::Title: return A_BOLD;
    case Paint::Selected: return A_REVERSE;
    case Paint::Error: return A_BOLD | (colour ? COLOR_PAIR(1) : A_STANDOUT);
    case Paint::Lamp: return A_BOLD | (colour ? COLOR_PAIR(2) : A_NORMAL);
    case Paint::Dim: return A_DIM;
  }
  return A_NORMAL;
}

void draw(const TuiSession& session) {
  int rows = 0, cols = 0;
  getmaxyx(stdscr, rows, cols);
  const Screen screen = session.screen(cols, rows);
  erase();
  for (std::size_t r = 0; r < screen.rows.size() && static_cast<int>(r) < rows; ++r) {
    // The bottom-right cell last: writing it may fail (the cursor cannot
    // move past it), which does not matter.
    mvaddnstr(static_cast<int>(r), 0, screen.rows[r].c_str(), cols);
  }
  for (const Mark& m : screen.marks) {
    const attr_t a = attributeOf(m.paint);
    mvchgat(m.row, m.col, m.width, a & ~A_COLOR, static_cast<short>(PAIR_NUMBER(a)), nullptr);
  }
  if (screen.cursorRow >= 0) {
    curs_set(1);
    move(screen.cursorRow, screen.cursorCol);
  } else {
    curs_set(0);
  }
  refresh();
}

}  // namespace

TuiEnd runTerminalPendant(Pendant& pendant) {
  TuiEnd end;
  stopSignal = 0;
  Handlers handlers;
  Curses curses(end.error);
  if (!curses.ok()) return end;
  TuiSession session(pendant);
  draw(session);
  std::uint64_t drawn = pendant.revision();
  for (;;) {
    const int key = getch();
    if (stopSignal != 0) {
      end.signal = stopSignal;
      break;
    }
    if (key == ERR) {
      // A device can change without a key (a fault): draw what changed.
      if (pendant.revision() != drawn) draw(session), drawn = pendant.revision();
      continue;
    }
    const std::string name = keyName(key);
    if (name.empty()) continue;
    if (!session.press(name)) break;
    draw(session);
    drawn = pendant.revision();
  }
  return end;
}

}  // namespace rs::teach::tui
