// The pendant's keys, the same in every UI: the web page reads this table
// (as JSON, in its model) and the terminal pendant maps its keys to the
// same names. A UI keeps its own selection (the motor and the point the
// keys act on, the jog step); the actions are Pendant operations.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

namespace rs::teach {

enum class KeyAction : std::uint8_t {
  PrevMotor, NextMotor, JogMinus, JogPlus, Step1, Step10, Step100, JogMode,
  OpenGripper, CloseGripper, Teach, GoTo, Reteach, Delete, Rename,
  PrevPoint, NextPoint, ReadPosition, ResetCell, RunCell, Help, Quit,
};

struct KeyBinding {
  std::string_view key;     ///< as a browser's KeyboardEvent.key names it ("ArrowUp", "t")
  KeyAction action;
  std::string_view name;    ///< the action's name in the page's script and the TUI
  std::string_view help;    ///< one line for the help panel
};

inline constexpr std::array<KeyBinding, 24> kKeys{{
    {"ArrowUp", KeyAction::PrevMotor, "prevMotor", "select the motor (world, tool: the axis) above"},
    {"ArrowDown", KeyAction::NextMotor, "nextMotor", "select the motor (world, tool: the axis) below"},
    {"ArrowLeft", KeyAction::JogMinus, "jogMinus", "jog the selected motor or axis by -step"},
    {"ArrowRight", KeyAction::JogPlus, "jogPlus", "jog the selected motor or axis by +step"},
    {"-", KeyAction::JogMinus, "jogMinus", "jog the selected motor or axis by -step"},
    {"+", KeyAction::JogPlus, "jogPlus", "jog the selected motor or axis by +step"},
    {"1", KeyAction::Step1, "step1", "jog step 1 (count, length unit, degree)"},
    {"2", KeyAction::Step10, "step10", "jog step 10 (counts, length units; 5 degrees)"},
    {"3", KeyAction::Step100, "step100", "jog step 100 (counts, length units; 15 degrees)"},
    {"m", KeyAction::JogMode, "jogMode", "jog mode: joint, world, tool (in turn)"},
    {"o", KeyAction::OpenGripper, "openGripper", "open the gripper"},
    {"c", KeyAction::CloseGripper, "closeGripper", "close the gripper"},
    {"t", KeyAction::Teach, "teach", "teach: name the current pose as a new point"},
    {"g", KeyAction::GoTo, "goTo", "go to the selected point"},
    {"r", KeyAction::Reteach, "reteach", "re-teach the selected point (asks first)"},
    {"x", KeyAction::Delete, "delete", "delete the selected point (asks first)"},
    {"n", KeyAction::Rename, "rename", "rename the selected point"},
    {"PageUp", KeyAction::PrevPoint, "prevPoint", "select the point above"},
    {"PageDown", KeyAction::NextPoint, "nextPoint", "select the point below"},
    {"p", KeyAction::ReadPosition, "readPosition", "read position from the controller (--device)"},
    {"R", KeyAction::ResetCell, "resetCell", "reset the cell (asks first)"},
    {"w", KeyAction::RunCell, "runCell", "let the cell's devices run for 1 s (belts, feeders, sensors)"},
    {"?", KeyAction::Help, "help", "show or hide the keys"},
    {"q", KeyAction::Quit, "quit", "quit (the terminal pendant)"},
}};

/// How a jog moves (docs/teach.md, "Jog modes"): a motor by encoder counts
/// (joint), or the tool along or about an axis of the cell (world) or of
/// the tool itself (tool), through the inverse kinematics.
enum class JogMode : std::uint8_t { Joint, World, Tool };

/// "joint", "world", "tool".
std::string_view jogModeName(JogMode mode);
/// The mode after `mode`, as the `m` key goes round.
JogMode nextJogMode(JogMode mode);

/// A jog step is 1, 10 or 100 (encoder counts, or length units); a turn
/// about an axis is this many degrees for that step (1, 5, 15).
inline constexpr double jogDegrees(std::int32_t step) { return step >= 100 ? 15.0 : step >= 10 ? 5.0 : 1.0; }

/// The binding of `key`, if any.
std::optional<KeyBinding> keyBinding(std::string_view key);

/// [{"key", "action", "help"}...] in table order, for the page.
nlohmann::ordered_json keysJson();
/// {"1": 1, "10": 5, "100": 15}: jogDegrees of each step, for the page.
nlohmann::ordered_json jogDegreesJson();

}  // namespace rs::teach
