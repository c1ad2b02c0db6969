#include "tools/teach/tui/tui_screen.h"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "base/number_text.h"
#include "tools/teach/keys.h"
#include "vm/io_lines.h"

namespace rs::teach::tui {

using base::formatNumber;

namespace {

constexpr int kLeftWidth = 44;  // the right panel starts after "| " at kLeftWidth

// Only printable ASCII reaches the terminal: a name from a file cannot
// move the cursor or switch character sets.
std::string printable(std::string_view s) {
  std::string out;
  for (const char c : s) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out;
}

class Canvas {
 public:
  Canvas(int cols, int rows) : cols_(cols) { screen_.rows.assign(static_cast<std::size_t>(rows), std::string(static_cast<std::size_t>(cols), ' ')); }

  // Writes `text` at (row, col), cut at `limit` (a column, exclusive); a
  // cut shows as '~' in the last column kept. Returns the column after it.
  int put(int row, int col, std::string_view text, int limit = -1) {
    if (limit < 0 || limit > cols_) limit = cols_;
    if (row < 0 || row >= static_cast<int>(screen_.rows.size()) || col >= limit) return col;
    const std::string s = printable(text);
    std::string& line = screen_.rows[static_cast<std::size_t>(row)];
    int c = col;
    for (std::size_t i = 0; i < s.size() && c < limit; ++i, ++c) line[static_cast<std::size_t>(c)] = s[i];
    if (col + static_cast<int>(s.size()) > limit) line[static_cast<std::size_t>(limit - 1)] = '~';
    return c;
  }
  void mark(int row, int col, int width, Paint paint) {
    width = std::min(width, cols_ - col);
    if (width > 0) screen_.marks.push_back({row, col, width, paint});
  }
  void rule(int row) { put(row, 0, std::string(static_cast<std::size_t>(cols_), '-')); }
  Screen& screen() { return screen_; }

 private:
  int cols_;
  Screen screen_;
};

std::string kindName(vm::JointKind k) {
  switch (k) {
    case vm::JointKind::Revolute: return "revolute";
    case vm::JointKind::Prismatic: return "prismatic";
    case vm::JointKind::Gripper: return "gripper";
  }
  return "";
}

// A key of the shared map as a person reads it ("ArrowLeft" -> "Left").
std::string keyLabel(std::string_view key) {
  if (key.substr(0, 5) == "Arrow") return std::string(key.substr(5));
  if (key == "PageUp") return "PgUp";
  if (key == "PageDown") return "PgDn";
  return std::string(key);
}

// The axes of a Cartesian jog in the selection's mode, one a row; X, Y, Z
// with the tool centre point's coordinate in world mode.
int axesPanel(Canvas& c, const PendantState& s, const Selection& sel, int row, int bottom) {
  const std::vector<PendantJogAxis>& axes = sel.mode == JogMode::World ? s.worldAxes : s.toolAxes;
  for (std::size_t a = 0; a < axes.size() && row < bottom; ++a, ++row) {
    std::string line = fmt::format("{:<7} {}", axes[a].name, axes[a].help);
    if (a == sel.axis) c.put(row, 1, ">");
    c.put(row, 3, line, kLeftWidth);
    if (a == sel.axis) c.mark(row, 1, kLeftWidth - 2, Paint::Selected);
  }
  return row;
}

int motorsPanel(Canvas& c, const PendantState& s, const Selection& sel, int row, int bottom) {
  const bool joint = sel.mode == JogMode::Joint;
  const std::string title = joint ? "MOTORS" : sel.mode == JogMode::World ? "WORLD AXES" : "TOOL AXES";
  c.put(row, 1, title);
  c.mark(row, 1, static_cast<int>(title.size()), Paint::Title);
  const std::string step = joint ? fmt::format("jog step {}", sel.step)
                                 : fmt::format("jog step {}, {} deg", sel.step, formatNumber(jogDegrees(sel.step)));
  c.put(row, kLeftWidth - 1 - static_cast<int>(step.size()), step, kLeftWidth);
  c.put(row + 1, 3, fmt::format("mode {} (m: joint, world, tool)", jogModeName(sel.mode)), kLeftWidth);
  c.mark(row + 1, 8, static_cast<int>(jogModeName(sel.mode).size()), Paint::Selected);
  row += 2;
  if (!joint) return axesPanel(c, s, sel, row, bottom);
  for (std::size_t m = 0; m < s.motors.size() && row < bottom; ++m, ++row) {
    const vm::MotorSpec& spec = s.motors[m];
    const std::int32_t value = m < s.encoders.size() ? s.encoders[m] : 0;
    std::string line = fmt::format("{} {:<9} {:>7}  {}..{}", spec.letter, kindName(spec.kind), value, spec.min, spec.max);
    if (spec.kind == vm::JointKind::Gripper) line += fmt::format("  {}", gripperName(s.gripper));
    if (m == sel.motor) c.put(row, 1, ">");
    c.put(row, 3, line, kLeftWidth);
    if (m == sel.motor) c.mark(row, 1, kLeftWidth - 2, Paint::Selected);
  }
  return row;
}

int worldPanel(Canvas& c, const PendantState& s, int row, int bottom) {
  if (row + 2 <= bottom) {
    c.put(row, 1, "TOOL CENTRE POINT (world)");
    c.mark(row, 1, 25, Paint::Title);
    if (s.tcp)
      c.put(row + 1, 3,
            fmt::format("x {}  y {}  z {}", formatNumber((*s.tcp)[0]), formatNumber((*s.tcp)[1]),
                        formatNumber((*s.tcp)[2])),
            kLeftWidth);
    else
      c.put(row + 1, 3, "(the robot has no chain)", kLeftWidth);
    if (s.approach)
      c.put(row + 2, 3,
            fmt::format("approach {} {} {}", formatNumber((*s.approach)[0], 3), formatNumber((*s.approach)[1], 3),
                        formatNumber((*s.approach)[2], 3)),
            kLeftWidth);
    row += s.approach ? 4 : 3;
  }
  if (row + 3 <= bottom) {
    for (int line = 1; line <= vm::kIoCount; ++line) c.put(row, 10 + 2 * (line - 1), std::to_string(line % 10));
    const std::pair<const char*, vm::IoMask> lines[] = {{"INPUTS", s.inputs}, {"OUTPUTS", s.outputs}};
    for (int k = 0; k < 2; ++k) {
      c.put(row + 1 + k, 1, lines[k].first);
      c.mark(row + 1 + k, 1, static_cast<int>(std::string_view(lines[k].first).size()), Paint::Title);
      for (int i = 0; i < vm::kIoCount; ++i) {
        const bool on = vm::lineIsOn(lines[k].second, i + 1);
        c.put(row + 1 + k, 10 + 2 * i, on ? "#" : ".");
        if (on) c.mark(row + 1 + k, 10 + 2 * i, 1, Paint::Lamp);
      }
    }
    // A blank row before HOLDS, unless the device rows under it would
    // then not fit (a five-motor robot's cell with three kinds at 80x24).
    const int below = 1 + !s.sensors.empty() + !s.conveyors.empty() + !s.feeders.empty();
    row += row + 4 + below <= bottom ? 4 : 3;
  }
  if (row < bottom) {
    std::string held = "nothing";
    for (std::size_t o = 0; o < s.objects.size(); ++o)
      if (s.objects[o].held) held = fmt::format("{} (object {})", s.objects[o].name, o + 1);
    c.put(row, 1, "HOLDS");
    c.mark(row, 1, 5, Paint::Title);
    c.put(row, 10, held, kLeftWidth);
    ++row;
  }
  // The cell's devices, as the page lists them: each sensor ON or off with
  // its count of ON edges, each belt running or stopped, each feeder's count.
  const auto devices = [&](const char* title, const std::vector<PendantDevice>& list,
                           const auto& says) {
    if (list.empty() || row >= bottom) return;
    std::string text;
    for (const PendantDevice& d : list) text += fmt::format("{}{} {}", text.empty() ? "" : ", ", d.name, says(d));
    c.put(row, 1, title);
    c.mark(row, 1, static_cast<int>(std::string_view(title).size()), Paint::Title);
    c.put(row, 10, text, kLeftWidth);
    ++row;
  };
  devices("SENSORS", s.sensors, [](const PendantDevice& d) { return fmt::format("{} ({})", d.on ? "ON" : "off", d.count); });
  devices("BELTS", s.conveyors, [](const PendantDevice& d) { return std::string(d.on ? "runs" : "stopped"); });
  devices("FEEDERS", s.feeders, [](const PendantDevice& d) { return fmt::format("fed {}", d.count); });
  return row;
}

void pointsPanel(Canvas& c, const PendantState& s, const Selection& sel, int top, int bottom, int cols) {
  const int left = kLeftWidth + 2;
  for (int r = top; r < bottom; ++r) c.put(r, kLeftWidth, "|");
  c.put(top, left, fmt::format("POINTS ({})", s.points.size()), cols);
  c.mark(top, left, 6, Paint::Title);
  if (s.points.empty()) {
    c.put(top + 1, left + 2, "none yet: t teaches one", cols);
    return;
  }
  // Each value column as wide as its widest value; names as wide as the longest.
  std::size_t nameWidth = 4;
  std::vector<std::size_t> widths;
  for (const PendantPoint& p : s.points) {
    nameWidth = std::max(nameWidth, p.name.size());
    for (std::size_t i = 0; i < p.values.size(); ++i) {
      if (widths.size() <= i) widths.push_back(1);
      widths[i] = std::max(widths[i], fmt::format("{}", p.values[i]).size());
    }
  }
  const int visible = bottom - top - 1;
  const std::size_t first =
      sel.point >= static_cast<std::size_t>(visible) ? sel.point - static_cast<std::size_t>(visible) + 1 : 0;
  for (std::size_t i = first; i < s.points.size() && static_cast<int>(i - first) < visible; ++i) {
    const PendantPoint& p = s.points[i];
    const int row = top + 1 + static_cast<int>(i - first);
    std::string line = fmt::format("{:<{}}", p.name, nameWidth);
    if (p.pose) line += " (a tool pose: AT ...)";
    else if (!p.readable) line += " (not whole numbers)";
    else
      for (std::size_t v = 0; v < p.values.size(); ++v) line += fmt::format(" {:>{}}", p.values[v], widths[v]);
    if (i == sel.point) c.put(row, left, ">");
    c.put(row, left + 2, line, cols);
    if (i == sel.point) c.mark(row, left, cols - left, Paint::Selected);
  }
}

// Actions that read best as one line ("Up Down  select the motor above /
// below"): the shared map's order is kept, each group shown where its
// first action stands.
struct ActionGroup {
  KeyAction first, last;
  std::string_view help;
};
constexpr ActionGroup kGroups[] = {
    {KeyAction::PrevMotor, KeyAction::NextMotor, "select the motor (world, tool: the axis) above / below"},
    {KeyAction::JogMinus, KeyAction::JogPlus, "jog the selected motor or axis by -step / +step"},
    {KeyAction::Step1, KeyAction::Step100, "jog step 1, 10, 100 (counts, lengths; 1, 5, 15 deg)"},
    {KeyAction::OpenGripper, KeyAction::CloseGripper, "open / close the gripper"},
    {KeyAction::PrevPoint, KeyAction::NextPoint, "select the point above / below"},
};

void helpPanel(Canvas& c, int top, int bottom, int cols) {
  // One line per action or group, its keys joined ("Left Right - +"), in
  // the map's order; then the terminal's own keys.
  std::vector<std::pair<std::string, std::string>> entries;
  std::vector<std::string_view> helps;  // what each entry stands for
  for (const KeyBinding& k : kKeys) {
    std::string_view help = k.help;
    for (const ActionGroup& g : kGroups)
      if (k.action >= g.first && k.action <= g.last) help = g.help;
    const auto it = std::find(helps.begin(), helps.end(), help);
    if (it != helps.end()) {
      entries[static_cast<std::size_t>(it - helps.begin())].first += " " + keyLabel(k.key);
    } else {
      entries.emplace_back(keyLabel(k.key), std::string(help));
      helps.push_back(help);
    }
  }
  entries.emplace_back(fmt::format("i 1..{}", vm::kIoCount), "toggle an input (simulation)");
  entries.emplace_back(fmt::format("u 1..{}", vm::kIoCount), "switch an output");
  entries.emplace_back("l", "read the program file again (after an edit elsewhere)");
  // One column when it fits (21 rows at 24 rows: the help takes the rule
  // and message rows too), else two.
  const int rowsFree = bottom - top, columns = static_cast<int>(entries.size()) <= rowsFree ? 1 : 2;
  const int perColumn = std::max(1, (static_cast<int>(entries.size()) + columns - 1) / columns);
  const int width = cols / columns, label = 15;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int column = static_cast<int>(i) / perColumn, row = top + static_cast<int>(i) % perColumn;
    if (column >= columns || row >= bottom) break;
    const int col = 1 + column * width;
    c.put(row, col, entries[i].first, col + label - 1);
    c.mark(row, col, static_cast<int>(std::min<std::size_t>(entries[i].first.size(), label - 1)), Paint::Title);
    c.put(row, col + label, entries[i].second, col + width - 1);
  }
}

}  // namespace

Screen layoutScreen(const PendantState& state, const Selection& selection, const Prompt& prompt,
                    const std::string& note, int cols, int rows) {
  if (cols < kMinCols || rows < kMinRows) {
    Canvas c(std::max(cols, 1), std::max(rows, 1));
    c.put(0, 0, fmt::format("robotsim teach needs {}x{}: enlarge the terminal (q quits)", kMinCols, kMinRows));
    return c.screen();
  }
  Canvas c(cols, rows);
  const std::string where = state.device.empty() ? "simulation" : "robot on " + state.device;
  c.put(0, 0, fmt::format("robotsim teach  {}  on {}  ({})", state.program, state.cell, where), cols - 16);
  c.put(0, cols - 14, "? keys  q quit");
  c.mark(0, 0, cols, Paint::Title);
  c.rule(1);
  const int top = 2, bottom = rows - 3;
  if (selection.help) {
    helpPanel(c, top, rows - 1, cols);
    if (!state.fault.empty()) {
      c.put(rows - 1, 0, "DEVICE FAULT, every motor stopped: " + state.fault);
      c.mark(rows - 1, 0, cols, Paint::Error);
    } else {
      c.put(rows - 1, 0, "KEYS, as on the web page: ? hides them, q quits");
      c.mark(rows - 1, 0, cols, Paint::Dim);
    }
    return c.screen();
  }
  int row = motorsPanel(c, state, selection, top, bottom);
  worldPanel(c, state, row + 1, bottom);
  pointsPanel(c, state, selection, top, bottom, cols);
  c.rule(rows - 3);
  if (!state.fault.empty()) {
    c.put(rows - 2, 0, "DEVICE FAULT, every motor stopped: " + state.fault);
    c.mark(rows - 2, 0, cols, Paint::Error);
  } else if (!note.empty()) {
    c.put(rows - 2, 0, note);
  } else {
    c.put(rows - 2, 0, state.message);
    if (state.failed) c.mark(rows - 2, 0, cols, Paint::Error);
  }
  if (prompt.active) {
    const int end = c.put(rows - 1, 0, prompt.question + prompt.answer);
    c.mark(rows - 1, 0, static_cast<int>(prompt.question.size()), Paint::Title);
    c.screen().cursorRow = rows - 1;
    c.screen().cursorCol = std::min(end, cols - 1);
  } else {
    c.put(rows - 1, 0, "Left/Right jog  Up/Down select  m mode  1 2 3 step  o c grip  t teach  ? keys");
    c.mark(rows - 1, 0, cols, Paint::Dim);
  }
  return c.screen();
}

}  // namespace rs::teach::tui
