// The pendant's keys, the same in every UI: the web page reads this table
// (as JSON, in its model) and the terminal pendant maps its keys to the
// same names. A UI keeps its own selection (the motor and the point the
// keys act on, the jog step); the actions are Pendant operations.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

namespace rs::teach {

enum class KeyAction : std::uint8_t {
  PrevMotor, NextMotor, JogMinus, JogPlus, Step1, Step10, Step100,
  OpenGripper, CloseGripper, Teach, GoTo, Reteach, Delete, Rename,
  PrevPoint, NextPoint, ReadPosition, ResetCell, Help, Quit,
};

struct KeyBinding {
  std::string_view key;     ///< as a browser's KeyboardEvent.key names it ("ArrowUp", "t")
  KeyAction action;
  std::string_view name;    ///< the action's name in the page's script and the TUI
  std::string_view help;    ///< one line for the help panel
};

inline constexpr std::array<KeyBinding, 22> kKeys{{
    {"ArrowUp", KeyAction::PrevMotor, "prevMotor", "select the motor above"},
    {"ArrowDown", KeyAction::NextMotor, "nextMotor", "select the motor below"},
    {"ArrowLeft", KeyAction::JogMinus, "jogMinus", "jog the selected motor by -step"},
    {"ArrowRight", KeyAction::JogPlus, "jogPlus", "jog the selected motor by +step"},
    {"-", KeyAction::JogMinus, "jogMinus", "jog the selected motor by -step"},
    {"+", KeyAction::JogPlus, "jogPlus", "jog the selected motor by +step"},
    {"1", KeyAction::Step1, "step1", "jog step 1 count"},
    {"2", KeyAction::Step10, "step10", "jog step 10 counts"},
    {"3", KeyAction::Step100, "step100", "jog step 100 counts"},
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
    {"?", KeyAction::Help, "help", "show or hide the keys"},
    {"q", KeyAction::Quit, "quit", "quit (the terminal pendant)"},
}};

/// The binding of `key`, if any.
std::optional<KeyBinding> keyBinding(std::string_view key);

/// [{"key", "action", "help"}...] in table order, for the page.
nlohmann::ordered_json keysJson();

}  // namespace rs::teach
