// Where *go to* takes the arm: a point as the program's MOVEP moves to it.
// A row of counts is its counts; a row written as a tool pose (`UP AT 240
// 900 -40 APPROACH 0 -1 0`) is resolved by the compiler, as when the
// program is compiled (docs/language.md, "Points as tool poses"): the rows
// above it give what it does not write, and without GRIP it leaves the
// gripper as it is when the move starts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/workcell/model.h"
#include "tools/teach/points_edit.h"

namespace rs::teach {

struct PointTarget {
  std::vector<std::int32_t> values;  ///< one count per motor (when resolved)
  bool keepsGripper = false;         ///< the gripper motor stays as it is (a pose without GRIP)
  std::string error;                 ///< why the point cannot be resolved, with its file line ("" when resolved)
  bool ok() const { return error.empty(); }
};

/// Row `index` of `points` on the robot `cell` drives. Only the rows up to
/// it are read: a mistake in a row below does not stop it.
PointTarget pointTarget(const PointsText& points, std::size_t index, const workcell::Workcell& cell);

}  // namespace rs::teach
