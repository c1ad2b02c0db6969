#include "tools/teach/tui/tui_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "tools/teach/keys.h"
#include "vm/io_lines.h"

namespace rs::teach::tui {

namespace {

// A point name is at most this long (more cannot be a sensible name, and
// the line must hold it).
constexpr std::size_t kMaxName = 40;

bool isYes(std::string_view key) { return key == "y" || key == "Y"; }

// Lines 1..9 answer with their one key; more lines would be typed, then Enter.
constexpr bool kLineIsOneKey = vm::kIoCount < 10;

// An input or output line typed as its number, 1..vm::kIoCount.
std::optional<int> ioLine(std::string_view text) {
  int line = 0;
  if (text.empty() || text.size() > 2) return std::nullopt;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    line = line * 10 + (c - '0');
  }
  return vm::isIoLine(line) ? std::optional<int>(line) : std::nullopt;
}

}  // namespace

void TuiSession::clampSelection() {
  const PendantState s = pendant_.state();
  if (!s.motors.empty()) selection_.motor = std::min(selection_.motor, s.motors.size() - 1);
  const std::vector<PendantJogAxis>& axes = selection_.mode == JogMode::Tool ? s.toolAxes : s.worldAxes;
  selection_.axis = axes.empty() ? 0 : std::min(selection_.axis, axes.size() - 1);
  if (!s.points.empty()) selection_.point = std::min(selection_.point, s.points.size() - 1);
  else selection_.point = 0;
}

std::optional<std::string> TuiSession::selectedPoint() {
  const PendantState s = pendant_.state();
  if (selection_.point < s.points.size()) return s.points[selection_.point].name;
  note_ = "there are no points yet: t teaches one";
  return std::nullopt;
}

void TuiSession::ask(Asking what, std::string question) {
  asking_ = what;
  prompt_ = {true, std::move(question), ""};
}

bool TuiSession::press(std::string_view key) {
  if (key == "Resize") return true;  // the terminal changed size: only a redraw, whatever is asked
  if (asking_ != Asking::Nothing) return answer(key);
  note_.clear();
  // The key list covers the panels: any other key hides it, then acts.
  if (selection_.help && key != "?") selection_.help = false;
  if (key == "i") {
    ask(Asking::InputLine, fmt::format("toggle input (1..{}): ", vm::kIoCount));
    return true;
  }
  if (key == "u") {
    ask(Asking::OutputLine, fmt::format("switch output (1..{}): ", vm::kIoCount));
    return true;
  }
  if (key == "l") {  // the page's "reload file" button
    pendant_.reload();
    clampSelection();
    return true;
  }
  const std::optional<KeyBinding> binding = keyBinding(key);
  if (!binding) {
    note_ = fmt::format("no key {} (? lists the keys)", key);
    return true;
  }
  const PendantState now = pendant_.state();
  const bool joint = selection_.mode == JogMode::Joint;
  const std::vector<PendantJogAxis>& axes = selection_.mode == JogMode::World ? now.worldAxes : now.toolAxes;
  std::size_t& row = joint ? selection_.motor : selection_.axis;
  const std::size_t rows = joint ? now.motors.size() : axes.size();
  const auto jog = [&](int sign) {
    if (joint) {
      pendant_.jog(selection_.motor, sign * selection_.step);
    } else if (selection_.axis < axes.size()) {
      const PendantJogAxis& a = axes[selection_.axis];
      pendant_.jogCartesian(selection_.mode == JogMode::World ? workcell::JogFrame::World : workcell::JogFrame::Tool,
                            a.name, sign * (a.rotation ? jogDegrees(selection_.step) : selection_.step));
    }
  };
  switch (binding->action) {
    case KeyAction::PrevMotor:
      if (row > 0) --row;
      break;
    case KeyAction::NextMotor:
      if (row + 1 < rows) ++row;
      break;
    case KeyAction::JogMinus: jog(-1); break;
    case KeyAction::JogPlus: jog(1); break;
    case KeyAction::Step1: selection_.step = 1; break;
    case KeyAction::Step10: selection_.step = 10; break;
    case KeyAction::Step100: selection_.step = 100; break;
    case KeyAction::JogMode:
      if (now.worldAxes.empty()) {
        note_ = "this robot has no kinematic chain: it jogs joint by joint only";
      } else {
        selection_.mode = nextJogMode(selection_.mode);
        note_ = fmt::format("jog mode {}", jogModeName(selection_.mode));
      }
      break;
    case KeyAction::OpenGripper: pendant_.gripper(false); break;
    case KeyAction::CloseGripper: pendant_.gripper(true); break;
    case KeyAction::Teach: ask(Asking::TeachName, "name of the new point (Enter teaches, Esc cancels): "); break;
    case KeyAction::GoTo:
      if (const auto name = selectedPoint()) pendant_.goTo(*name);
      break;
    case KeyAction::Reteach:
      if (const auto name = selectedPoint()) {
        if (now.points[selection_.point].pose)
          ask(Asking::ReteachAs,
              fmt::format("re-teach {}: p as a pose (AT ...), c as counts, any other key cancels ", *name));
        else
          ask(Asking::ConfirmReteach, fmt::format("re-teach {} with the current pose? (y/n) ", *name));
      }
      break;
    case KeyAction::Delete:
      if (const auto name = selectedPoint()) ask(Asking::ConfirmDelete, fmt::format("delete {}? (y/n) ", *name));
      break;
    case KeyAction::Rename:
      if (const auto name = selectedPoint())
        ask(Asking::NewName, fmt::format("new name for {} (Enter renames, Esc cancels): ", *name));
      break;
    case KeyAction::PrevPoint:
      if (selection_.point > 0) --selection_.point;
      break;
    case KeyAction::NextPoint:
      if (selection_.point + 1 < pendant_.state().points.size()) ++selection_.point;
      break;
    case KeyAction::ReadPosition: pendant_.readPosition(); break;
    case KeyAction::ResetCell:
      ask(Asking::ConfirmReset, "reset the cell: motors home, objects back, lines off? (y/n) ");
      break;
    case KeyAction::RunCell: pendant_.runCell(1.0); break;
    case KeyAction::Help: selection_.help = !selection_.help; break;
    case KeyAction::Quit: return false;
  }
  clampSelection();
  return true;
}

bool TuiSession::answer(std::string_view key) {
  const Asking what = asking_;
  const bool confirm = what == Asking::ConfirmReteach || what == Asking::ConfirmDelete || what == Asking::ConfirmReset;
  const bool poseOrCounts = what == Asking::ReteachAs && (key == "p" || key == "c");
  if (key == "Escape" || key == "\x03" || key == "\x07" || (confirm && !isYes(key)) ||
      (what == Asking::ReteachAs && !poseOrCounts)) {
    asking_ = Asking::Nothing;
    prompt_ = {};
    note_ = "cancelled";
    return true;
  }
  if (confirm || poseOrCounts || (kLineIsOneKey && (what == Asking::InputLine || what == Asking::OutputLine) && key.size() == 1)) {
    asking_ = Asking::Nothing;
    prompt_ = {};
    finish(what, std::string(key));
    return true;
  }
  if (key == "Enter") {
    const std::string text = prompt_.answer;
    asking_ = Asking::Nothing;
    prompt_ = {};
    finish(what, text);
  } else if (key == "Backspace") {
    if (!prompt_.answer.empty()) prompt_.answer.pop_back();
  } else if (key.size() == 1 && key[0] > 0x20 && key[0] < 0x7f && prompt_.answer.size() < kMaxName) {
    prompt_.answer += key;
  }
  return true;
}

void TuiSession::finish(Asking what, const std::string& text) {
  note_.clear();
  switch (what) {
    case Asking::TeachName:
      if (pendant_.teach(text).ok) {
        // Select the new point, wherever the file put it.
        const PendantState s = pendant_.state();
        for (std::size_t i = 0; i < s.points.size(); ++i)
          if (s.points[i].name == text) selection_.point = i;
      }
      break;
    case Asking::NewName:
      if (const auto name = selectedPoint()) pendant_.rename(*name, text);
      break;
    case Asking::ConfirmReteach:
      if (const auto name = selectedPoint()) pendant_.reteach(*name);
      break;
    case Asking::ReteachAs:
      if (const auto name = selectedPoint())
        pendant_.reteach(*name, text == "p" ? Pendant::Reteach::Pose : Pendant::Reteach::Counts);
      break;
    case Asking::ConfirmDelete:
      if (const auto name = selectedPoint()) pendant_.remove(*name);
      break;
    case Asking::ConfirmReset: pendant_.resetCell(); break;
    case Asking::InputLine:
      if (const std::optional<int> line = ioLine(text)) pendant_.toggleInput(*line);
      else note_ = fmt::format("inputs are 1..{}, not {}", vm::kIoCount, text);
      break;
    case Asking::OutputLine:
      if (const std::optional<int> line = ioLine(text)) {
        pendant_.setOutput(*line, !vm::lineIsOn(pendant_.state().outputs, *line));
      } else {
        note_ = fmt::format("outputs are 1..{}, not {}", vm::kIoCount, text);
      }
      break;
    case Asking::Nothing: break;
  }
  clampSelection();
}

Screen TuiSession::screen(int cols, int rows) const {
  return layoutScreen(pendant_.state(), selection_, prompt_, note_, cols, rows);
}

}  // namespace rs::teach::tui
