// The terminal pendant's keys: each key a person presses, named as the
// shared key map names it (tools/teach/keys.h: "ArrowLeft", "t", "PageDown"),
// becomes one Pendant operation, or a question on the last row whose
// answer does (a point's name; yes or no before re-teach, delete and
// reset cell; over a point written as a tool pose, re-teach asks p for a
// pose or c for counts). No terminal here: tui_curses.cpp turns ncurses key codes
// into names and draws layoutScreen(session); a test can press keys by
// name and read the screen.
//
// Besides the shared map, the terminal has `i` then a line number (1..vm::kIoCount) to toggle an
// input and `u` then one to switch an output (the page does both by a
// click), `l` to read the program file
// again (the page's "reload file" button), and in a question Enter answers,
// Escape (or Ctrl-C's ETX, or Ctrl-G) cancels, Backspace deletes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "tools/teach/pendant.h"
#include "tools/teach/tui/tui_screen.h"

namespace rs::teach::tui {

class TuiSession {
 public:
  /// `pendant` must outlive the session.
  explicit TuiSession(Pendant& pendant) : pendant_(pendant) {}

  /// One key, by its shared-map name; a printable character is its own
  /// name, and "Enter", "Escape", "Backspace" serve the questions;
  /// "Resize" (the terminal changed size) only asks for a redraw.
  /// Returns false when the key quits.
  bool press(std::string_view key);

  Screen screen(int cols, int rows) const;
  const Selection& selection() const { return selection_; }

 private:
  enum class Asking {
    Nothing, TeachName, NewName, ConfirmReteach, ReteachAs, ConfirmDelete, ConfirmReset, InputLine, OutputLine,
  };
  bool answer(std::string_view key);
  void ask(Asking what, std::string question);
  void finish(Asking what, const std::string& text);
  /// The selected point's name, or nullopt (and a note) when there is none.
  std::optional<std::string> selectedPoint();
  void clampSelection();

  Pendant& pendant_;
  Selection selection_;
  Prompt prompt_;
  Asking asking_ = Asking::Nothing;
  std::string note_;
};

}  // namespace rs::teach::tui
