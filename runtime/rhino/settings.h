// Everything the Rhino backend and its emulator assume about a controller,
// in one struct: the line settings, the timing, and for the Mark III every
// choice the public sources leave open (which inquiry byte carries which
// switch or input, which command drives which output). Each field has a
// key for `--serial-set KEY=VALUE`; the table is in docs/serial.md.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/result.h"
#include "runtime/rhino/serial_port.h"
#include "vm/io_lines.h"

namespace rs::rhino {

/// A Rhino controller's input lines, and its output lines: a byte each on
/// the Mark III and the Mark IV. The settings map each of a program's
/// lines onto one of them, so there must be as many.
inline constexpr int kControllerLines = 8;
static_assert(vm::kIoCount == kControllerLines, "each line of a program is one of the controller's (settings.h)");

enum class Dialect : std::uint8_t { Mark3, Mark4 };

/// "mark3" / "mark4".
std::string_view dialectName(Dialect d);
/// "Mark III" / "Mark IV", for messages.
std::string_view dialectTitle(Dialect d);

/// What ends each command line the host sends.
enum class LineEnd : std::uint8_t { Cr, CrLf, LfCr, Lf };
std::string_view lineEndBytes(LineEnd e);

/// Mark III: where a switch or input is read: bit `bit` (0..5) of the reply
/// (minus 32) to the one-letter inquiry `command` (I, J or K). command 0:
/// not wired.
struct BitSource {
  char command = 0;
  int bit = 0;
  bool wired() const { return command != 0; }
  bool operator==(const BitSource&) const = default;
};

struct RhinoSettings {
  Dialect dialect = Dialect::Mark3;
  LineSettings line;
  LineEnd lineEnd = LineEnd::Cr;

  Micros timeout = 500'000;          // a reply must start and end within this
  Micros pollInterval = 10'000;      // between status polls
  Micros stallTimeout = 5'000'000;   // a moving motor that makes no progress this long has stalled
  Micros homeTimeout = 120'000'000;  // the whole of HRDHOME

  // --- Mark III -------------------------------------------------------------
  int chunk = 40;                       // steps per move command (1..127)
  int refill = 15;                      // send the next chunk when fewer steps remain (1..127)
  bool signedRemaining = false;         // "<m>?" reply: 32 + |remaining| (false) or 32 + remaining
  std::array<BitSource, 8> switches;    // home switch of motors A..H
  std::array<BitSource, kControllerLines> inputs;  // inputs 1..kControllerLines
  bool inputsActiveLow = true;          // a 0 bit reads as input ON
  std::array<std::string, kControllerLines> outputOn;  // command templates: {n} line, {port} all outputs 0..255
  std::array<std::string, kControllerLines> outputOff;
  std::string homeOrder;   // letters; empty: motor-table order
  int homeSearch = 0;      // steps to look for a switch; 0: the motor's whole range
  int homeDirection = -1;  // when the tracked position is 0: -1 or +1

  // --- Mark IV --------------------------------------------------------------
  bool coordinated = false;  // start moves with MC instead of MI
  int tolerance = 10;        // |read-back position - target| allowed after a move
  bool checkErrors = true;   // read the error stack (SE) after every move and home
};

/// The defaults for a dialect (Mark IV: odd/even parity as the Mark III,
/// inputs active high).
RhinoSettings defaultSettings(Dialect d);

/// `s` with "KEY=VALUE" (the --serial-set form) applied, or what is wrong
/// with it, as a failure of `--serial-set`.
diag::Result<RhinoSettings> applySettingArg(RhinoSettings s, std::string_view arg);
/// `s` with a settings file's text applied: one `key = value` per line, `#`
/// comments. Or one failure per bad line, at the key's line and column
/// (`name` is its file).
diag::Result<RhinoSettings> applySettingsText(RhinoSettings s, std::string_view text, std::string_view name);

/// Every key with its current value, in documentation order.
std::vector<std::pair<std::string, std::string>> listSettings(const RhinoSettings& s);

}  // namespace rs::rhino
