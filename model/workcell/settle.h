// Where a released part comes to rest (docs/models.md, "Objects in the
// gripper"): straight down, the world's -y, onto the first thing under
// it — the top of a solid piece of another object (a fixture's, another
// part's), a belt's surface, or the floor. What is "under" it is judged by
// world boxes: a piece's box (its collision piece, turned and placed, as
// an axis-aligned box) whose footprint in x and z overlaps the part's and
// whose top is at most kSettleTolerance above the part's bottom, or below
// the part's middle. A part let go inside its support is lifted onto its
// top; one
// with nothing under it (a cell with FLOOR NONE) stays where it was let go.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <vector>
#include <optional>
#include <span>

#include "model/workcell/model.h"

namespace rs::workcell {

/// How far a part may be put into its support and still count as resting
/// on it, in length units: a carried part checked against the objects and
/// the floor collides only when it is more than this into them (the
/// collision model raises it by this much for those checks), and a part
/// let go that far inside its support settles onto its top.
inline constexpr double kSettleTolerance = 0.5;

/// The result of settling one part.
struct Settled {
  enum class On : std::uint8_t { Object, Belt, Floor, Nothing };
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< F_world_design where it rests
  On on = On::Nothing;
  std::size_t support = 0;  ///< the object (Object, Belt), an index in Workcell::objects
  /// How far it went down (negative: lifted out of its support, at most
  /// kSettleTolerance); 0 for Nothing.
  double drop = 0;
  bool operator==(const Settled& o) const {
    return pose.matrix() == o.pose.matrix() && on == o.on && support == o.support && drop == o.drop;
  }
};

/// The world boxes settle() judges supports by, kept per object with the
/// pose they were worked out for: a fixture, or a part that has not moved,
/// is boxed once however often parts are let go onto it. A pure cache (the
/// same boxes, bit for bit, as working them out again).
struct SupportBoxes {
  struct Object {
    Eigen::Matrix4d at = Eigen::Matrix4d::Constant(std::numeric_limits<double>::quiet_NaN());  // equal to no pose
    std::vector<Eigen::AlignedBox3d> pieces;
    Eigen::AlignedBox3d belt;
  };
  std::vector<Object> objects;
};

/// Part `part` of `cell`, let go at `pose`, with every other object at
/// `poses` (indexed as Workcell::objects; `poses[part]` is ignored, and so
/// is object `skip`, when given: one the gripper still carries).
/// `reach`, when given (per object, settleReach), lets it pass over the
/// objects too far aside to hold it up without looking at their pieces;
/// `boxes`, when given, keeps their boxes from one call to the next;
/// `among`, when given, names the objects to look at (in index order: the
/// ones in the cell, Grasping::inCell), else every one.
Settled settle(const Workcell& cell, std::span<const Eigen::Isometry3d> poses, std::size_t part,
               const Eigen::Isometry3d& pose, std::optional<std::size_t> skip = std::nullopt,
               std::span<const double> reach = {}, SupportBoxes* boxes = nullptr,
               const std::vector<std::size_t>* among = nullptr);

/// How far any point of object `o`'s collision pieces and belt lies from
/// its design origin: where it rests, nothing of it is farther than this
/// from its pose's translation.
double settleReach(const PlacedObject& o);

}  // namespace rs::workcell
