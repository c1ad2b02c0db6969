// The description reader's parser (description*.cpp): one line at a time
// into the DescriptionFile, each statement by the block it stands in.
// description.cpp opens and closes blocks; each kind of block reads its
// statements in its own file: description_shapes.cpp (LINK, OBJECT),
// description_robots.cpp (GRIPPER, ROBOT, their motors),
// description_workcell.cpp (WORKCELL), description_devices.cpp
// (its devices, an OBJECT's BELT). Private to those files.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "compiler/description/description.h"
#include "compiler/description/description_cursor.h"

namespace rs::compiler::description_detail {

using workcell::Color;

enum class Block { None, Link, Object, Gripper, Robot, Workcell };

/// The rotation by `degrees` about axis 0, 1 or 2 (X, Y, Z): ROTATE in a
/// shape and in a workcell.
Eigen::Matrix3d axisRotation(int axis, double degrees);

class Parser {
 public:
  Parser(DescriptionFile& file, diag::Diagnostics& d) : f_(file), diag_(d) {}
  void line(const std::vector<Word>& words, diag::Pos lineEnd);
  void finish();

 private:
  void readLine(const std::vector<Word>& words, diag::Pos lineEnd);
  void markDamaged(Block b);
  void open(Cursor& c, const Word& head);
  bool shapeClause(Cursor& c, ShapeDef& shape);
  bool gripperClause(Cursor& c, GripperDef& g);
  bool robotClause(Cursor& c, RobotDef& r);
  bool workcellClause(Cursor& c, WorkcellDef& w);
  // description_devices.cpp: `handled` false when the word opens no device line.
  bool deviceClause(Cursor& c, WorkcellDef& w, bool& handled);
  bool deviceLine(Cursor& c, workcell::Devices& d);
  /// `c` at the word BELT.
  bool belt(Cursor& c, ShapeDef& shape, diag::Pos at);
  static bool noVolume(Cursor& c, const Eigen::AlignedBox3d& box, diag::Pos at);
  bool motorClause(Cursor& c, char& letter, diag::Pos& letterPos, double& precision, std::int32_t& min, std::int32_t& max,
                   diag::Pos& rangePos, std::int32_t& speed, std::int32_t& acceleration, diag::Pos& accelerationPos,
                   bool* hasLetter, bool* hasPrecision, bool* hasRange);

  DescriptionFile& f_;
  diag::Diagnostics& diag_;
  Block block_ = Block::None;
  diag::Pos blockPos_;
  Color color_ = Color::White;
  enum class Item { None, Link, Joint, Tool };
  Item robotItem_ = Item::None;  // in a ROBOT: what the last LINK, JOINT or TOOL line added
};

}  // namespace rs::compiler::description_detail
