// A compiled program: what the compiler produces, the loader verifies and the
// interpreter runs. Self-contained: it carries the motor table it was
// compiled for, so a `.rsb` file runs without its source or robot files.
// The byte layout of the file form is in docs/bytecode.md.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/packed_numbers.h"
#include "vm/opcodes.h"

namespace rs::vm {

enum class JointKind : std::uint8_t { Revolute = 0, Prismatic = 1, Gripper = 2 };

/// One motor as the program sees it: a letter, how far one encoder unit
/// turns (degrees) or slides (length units), its encoder range and speed,
/// and how it gets to speed (runtime/sim/motion.h: constant speed by default,
/// a trapezoid with an acceleration, a fixed time for a gripper with an
/// actuation time).
struct MotorSpec {
  char letter = 'A';
  JointKind kind = JointKind::Revolute;
  double precision = 1.0;     // degrees or length units per encoder unit
  std::int32_t min = 0;       // encoder range, inclusive
  std::int32_t max = 0;
  std::int32_t speed = 1;     // encoder units per second, > 0
  std::int32_t acceleration = 0;  // encoder units per second², 0 = starts and stops at full speed
  std::int32_t actuation = 0;     // microseconds every move takes whatever its length (grippers only), 0 = none
  bool operator==(const MotorSpec&) const = default;
};

/// Bounds of the motion settings, checked by the description reader and
/// the verifier; they keep runtime/sim/motion.h's integer arithmetic exact.
inline constexpr std::int32_t kMaxAcceleration = 1'000'000'000;  // encoder units per second²
inline constexpr std::int32_t kMaxSecondsToSpeed = 1000;         // speed / acceleration at most this
inline constexpr std::int32_t kMaxActuation = 60'000'000;        // microseconds (a minute)

/// A taught point: one encoder value per motor.
struct Point {
  std::string name;
  std::vector<std::int32_t> values;
  /// For a point written as a tool pose, the pose as written
  /// ("AT 300 120 50 APPROACH 0 -1 0"), for listings and traces. Only a
  /// compile fills it: image files do not store it, and it takes no part in
  /// comparing points (the values are the point).
  std::string origin = {};
  bool operator==(const Point& o) const { return name == o.name && values == o.values; }
};

/// A label the source gave an instruction (kept for listings and traces).
/// Its name is in the image's labelNames, up to nameEnd (from the end of
/// the label before): 8 bytes a label and its letters, where a string each
/// was 40 (a program of labels compiles in half the memory).
struct Label {
  std::uint32_t index = 0;    // 0-based instruction index
  std::uint32_t nameEnd = 0;  // in Image::labelNames
  bool operator==(const Label&) const = default;
};

using LineTable = base::RisingNumbers;   // lines only grow in a compiled program
using ColumnTable = base::SmallNumbers;  // columns are mostly small

inline constexpr std::uint16_t kDefaultCallDepth = 64;
inline constexpr std::uint16_t kMaxCallDepth = 4096;

struct Image {
  std::string sourceName;   // file the program came from (for messages)
  std::string robotName;    // robot the motor table came from
  std::uint16_t callDepthLimit = kDefaultCallDepth;
  std::vector<MotorSpec> motors;
  std::vector<Instr> code;
  LineTable lines;      // source line of each instruction
  ColumnTable columns;  // source column of each mnemonic
  std::vector<std::int32_t> constants;
  std::vector<std::string> variables;  // slot -> name
  std::vector<Point> points;
  std::vector<Label> labels;          // sorted by index
  std::string labelNames;             // every label's name, one after the other
  std::vector<std::uint8_t> cell;     // the workcell compiled in, opaque to the VM (may be empty)
  bool operator==(const Image&) const = default;

  std::string_view labelName(std::size_t i) const {
    const std::size_t start = i == 0 ? 0 : labels[i - 1].nameEnd;
    return std::string_view(labelNames).substr(start, labels[i].nameEnd - start);
  }
  std::string_view labelName(const Label& l) const { return labelName(static_cast<std::size_t>(&l - labels.data())); }
  void addLabel(std::uint32_t index, std::string_view name) {
    labelNames += name;
    labels.push_back({index, static_cast<std::uint32_t>(labelNames.size())});
  }
};

}  // namespace rs::vm
