// Numbers on the command line: one reader for every command that takes
// them (ik, where, matrix, render, animate, the run limits, emulate,
// test). A number must be written as a decimal (a sign, digits, a point,
// an exponent), be finite, lie within what it counts (an encoder count is
// a whole number an int32 holds, a coordinate at most 1e9 in size, ...)
// and be whole where only whole numbers make sense. A bad one is refused
// at the option, before anything is loaded or run, as
//   --encoders: error: value 1 '1e308' is out of range: an encoder count is a whole number from -2147483648 to
//   2147483647
//     hint: ...
// so that `ik ... nan` is not a pose and `where --encoders 1e308` prints
// no 300-digit number.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class Validator;
}

namespace rs::cli {

/// What one number on the command line may be.
struct NumberRule {
  std::string_view what;  ///< "an encoder count": how messages name it
  double min = -1e9, max = 1e9;
  bool whole = false;     ///< only whole numbers
  bool aboveMin = false;  ///< min itself is refused ("above 0")
  std::string_view hint;  ///< how to write a good one
};

/// The rules of the command line's numbers (docs/cli.md, "Numbers").
namespace rules {
inline constexpr NumberRule kEncoderCount{"an encoder count",
                                          -2147483648.0,
                                          2147483647.0,
                                          true,
                                          false,
                                          "encoder counts are whole numbers within each motor's RANGE "
                                          "(robotsim describe CELL lists them)"};
inline constexpr NumberRule kJointValue{
    "a joint value", -1e9, 1e9, false, false, "degrees for a revolute joint, the length d for a prismatic one"};
inline constexpr NumberRule kCoordinate{"a coordinate", -1e9,  1e9,
                                        false,          false, "in the workcell's length units, e.g. -130 or 812.5"};
inline constexpr NumberRule kDirection{"a direction's component",
                                       -1e9,
                                       1e9,
                                       false,
                                       false,
                                       "a direction is three numbers X,Y,Z, e.g. 0,0,-1; its length does not matter"};
inline constexpr NumberRule kAngle{"an angle", -1e9, 1e9, false, false, "degrees, e.g. 25 or -35.5"};
inline constexpr NumberRule kZoom{"a zoom", 0.0,  1e6,
                                  false,    true, "1 fits the workcell in the picture, 2 is twice as large"};
inline constexpr NumberRule kPixels{
    "a picture's side", 16.0, 16384.0, true, false, "write WIDTHxHEIGHT in whole pixels, e.g. 1024x768"};
inline constexpr NumberRule kFrameNumber{
    "a frame number", 0.0, 1e6, true, false, "frames are numbered from 0 (the base) to the robot's joint count"};
inline constexpr NumberRule kSolution{
    "a solution number", 1.0, 8.0, true, false, "robotsim ik --help lists each family's configurations"};
inline constexpr NumberRule kStepCount{"a step count", 1.0,   4611686018427387904.0,
                                       true,           false, "the number of instructions to allow, e.g. 10000000"};
inline constexpr NumberRule kShownCount{"a number of diagnostics", 0.0, 1e9, true, false, "0 prints them all"};
inline constexpr NumberRule kJobs{"a number of jobs", 1.0, 1024.0, true, false, "tests run at once, e.g. 4"};
inline constexpr NumberRule kSpeedFactor{
    "a speed factor", 0.01, 1000.0, false, false, "1 plays the robot's own speeds, 2 twice as fast"};
inline constexpr NumberRule kLatency{"a latency in seconds", 0.0, 10.0, false, false, "e.g. 0.005"};
inline constexpr NumberRule kSwitchWidth{"a switch width in steps", 0.0, 10000.0, true, false, "e.g. 20"};
inline constexpr NumberRule kCommandCount{"a number of commands", 0.0, 4611686018427387904.0, true, false, "e.g. 10"};
inline constexpr NumberRule kControllers{
    "a number of controllers", 1.0, 16.0, true, false, "one a robot of the cell, e.g. 2"};
inline constexpr NumberRule kSlowDelay{"a delay in seconds", 0.0, 3600.0, false, false, "e.g. 2"};
inline constexpr NumberRule kDuration{
    "a duration in seconds", 0.0, 1e7, false, false, "e.g. 60; 0 runs until Ctrl-C or quit"};
}  // namespace rules

/// A number read by a rule: its value and the text CLI11 converts to
/// exactly that value, or the problem as a phrase ("'nan' is not a
/// number").
struct NumberRead {
  double value = 0;
  std::string canonical;
  std::string problem;  ///< empty when the number is good
};
NumberRead readNumber(std::string_view text, const NumberRule& rule);

/// "OPTION: error: PROBLEM\n  hint: HINT\n".
std::string numberError(std::string_view option, std::string_view problem, const NumberRule& rule);

/// For CLI11 (`->transform(numberArg(rule))`): reads each value of the
/// option by `rule` and writes it back as `canonical`; a bad one fails the
/// parse with "error: PROBLEM\n  hint: HINT" after the option's name.
CLI::Validator numberArg(const NumberRule& rule);
/// The same for a list of numbers separated by commas ("76,72,-90"), each
/// item by `rule` (how many there must be is the command's to check).
CLI::Validator numberListArg(const NumberRule& rule);

/// Seconds (render --at): exact to the microsecond, as the stimuli's times
/// (compiler/stimuli/stimuli_text.h: digits with at most 6 decimals, at most
/// 1000000); a problem is printed as "OPTION: error: ..." with a hint.
inline constexpr std::string_view kSecondsHint = "a time is seconds with at most 6 decimals, from 0 to 1000000";
bool parseSecondsArg(const std::string& text, std::string_view option, std::int64_t& micros, std::ostream& err);
/// For CLI11: refuses what parseSecondsArg refuses, at the option.
CLI::Validator secondsArg();

/// The numbers of `text`, separated by commas, into `out` (cleared first).
/// A bad item is printed on `err` as numberError with "value N 'ITEM' ..."
/// and gives false.
bool parseNumberList(const std::string& text, std::string_view option, const NumberRule& rule, std::vector<double>& out,
                     std::ostream& err);

}  // namespace rs::cli
