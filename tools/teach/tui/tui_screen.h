// The terminal pendant's screen as text: what `robotsim teach --tui` shows,
// laid out from the pendant's state (tools/teach/pendant_state.h, the same value
// the web page reads) and the terminal's own selection, without a
// terminal. A pure function, so a test can read the layout without
// ncurses; tui_curses.cpp only copies it to the terminal and paints the
// marked spans.
//
//   row 0      title: program, cell, simulation or device; "? keys  q quit"
//   row 1      rule
//   rows 2..   left: the jog mode and step; MOTORS (letter, joint type,
//              value in counts, range) in joint mode, or the WORLD or TOOL
//              AXES a Cartesian jog moves along or turns about;
//              TOOL CENTRE POINT (world) and the approach, INPUTS,
//              OUTPUTS, what is held;
//              right: POINTS (name, values), scrolled to the selection
//   rows-3     rule
//   rows-2     the last operation's message (a device fault first)
//   rows-1     the prompt being answered, or the main keys
//
// With help on, rows 2 to rows-2 list every key of the shared key map
// (one column when they fit, else two) and the last row says how to
// leave it (or shows a device fault).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/teach/keys.h"
#include "tools/teach/pendant_state.h"

namespace rs::teach::tui {

/// The smallest terminal the layout fits (a VT100's).
inline constexpr int kMinCols = 80, kMinRows = 24;

/// What the terminal keeps itself: the jog mode, the motor (joint mode) or
/// axis (world, tool) and the point the keys act on, the jog step, whether
/// the key help is shown.
struct Selection {
  JogMode mode = JogMode::Joint;
  std::size_t motor = 0;
  std::size_t axis = 0;
  std::size_t point = 0;
  std::int32_t step = 10;
  bool help = false;
};

/// A question on the last row: a name being typed, or a yes/no.
struct Prompt {
  bool active = false;
  std::string question;  ///< "name of the new point: "
  std::string answer;    ///< typed so far
};

enum class Paint : std::uint8_t { Title, Selected, Error, Lamp, Dim };

/// A span of one row to paint.
struct Mark {
  int row = 0, col = 0, width = 0;
  Paint paint = Paint::Selected;
};

struct Screen {
  std::vector<std::string> rows;  ///< each exactly `cols` bytes, ASCII
  std::vector<Mark> marks;
  int cursorRow = -1, cursorCol = -1;  ///< where the cursor shows (-1: hidden)
};

/// The whole screen for a terminal of `cols` x `rows` (at least kMinCols x
/// kMinRows; a smaller one gets a one-line request to enlarge it).
/// `note` is the terminal's own message (a key that does nothing here),
/// shown instead of the state's when not empty.
Screen layoutScreen(const PendantState& state, const Selection& selection, const Prompt& prompt,
                    const std::string& note, int cols, int rows);

}  // namespace rs::teach::tui
