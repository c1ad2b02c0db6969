// What each thing in a workcell stands on: what `robotsim describe` says
// so that a student can check a layout without drawing it. World y is up
// (as every description is drawn, docs/models.md). A box stands on an
// object that reaches below the box's bottom and has level lines (both
// ends at one height) there whose extent in x and z overlaps the box's
// footprint: a BOX's top face is four such lines, so a block on a
// conveyor's belt, between its side guides that rise above the belt,
// stands on the conveyor, and a gantry's feet beside a pallet's runners
// stand on the floor. It stands on the floor when its bottom is at y = 0
// and no object holds it. There is no gravity: a box resting on nothing
// is reported as such.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <span>

#include "model/workcell/model.h"

namespace rs::workcell {

struct Support {
  enum class Kind { Object, Floor, Nothing };
  Kind kind = Kind::Nothing;
  std::size_t object = 0;  ///< index into the boxes, when kind is Object
};

/// The bounds, in world coordinates, of `shape` placed by `F_world_design`.
Eigen::AlignedBox3d worldBoxOf(const Shape& shape, const Eigen::Isometry3d& F_world_design);

/// What `box` (world coordinates) stands on among `objects` (skipping
/// index `self`, if any): the object under it with the largest shared
/// footprint (the first in order on a tie), else the floor, else nothing.
Support supportOf(const Eigen::AlignedBox3d& box, std::span<const PlacedObject> objects,
                  std::optional<std::size_t> self = std::nullopt);

}  // namespace rs::workcell
