// Jogging the tool in Cartesian coordinates, as an industrial pendant's
// world and tool modes do: a step along or about one axis of the cell's
// frame (world) or of the tool's own frame (tool), turned into encoder
// counts by the inverse kinematics (kinematics/ik.h) on the configuration
// the arm stands in (no elbow or wrist flip), and checked the whole way as
// the straight line MOVES runs (line_path.h): the caller moves the tool
// along that line (vm::Machine::moveLine), or the step is refused with the
// limit it met (range, reach, singularity, step) and nothing changed.
// Collisions are the caller's: the pendant moves the rig, whose sweep
// checks the move (tools/teach/pendant.h). docs/teach.md, "Jog modes".
//
// Which rotations there are is the arm's (docs/models.md, "Inverse
// kinematics"): a six-axis wrist turns about any axis; a five-axis arm
// pitches (about the axis its pitch joints share) and rolls (about the
// approach); a SCARA with a roll joint turns about its joints' axis; a
// cartesian arm and a SCARA without one turn about nothing.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/kinematics/ik.h"
#include "model/workcell/line_path.h"
#include "model/workcell/model.h"

namespace rs::workcell {

enum class JogFrame : std::uint8_t { World, Tool };

std::string_view jogFrameName(JogFrame frame);  ///< "world", "tool"

/// One axis a Cartesian jog can move along or turn about, at the pose the
/// arm stands in.
struct JogAxis {
  std::string name;       ///< "X", "Y", "Z"; "RX", "RY", "RZ"; "PITCH", "ROLL", "HEADING" where no frame axis is it
  bool rotation = false;  ///< turns about the axis (degrees) rather than moving along it (length units)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< in world coordinates, unit length
  std::string help;                                      ///< "along the world's X", "about the tool's z (the approach)"
};

/// Why a jog was refused: the limit it met. Step: the step itself is too
/// large to be one jog (a turn of half a turn or more, a line of more
/// knots than a line may have).
enum class JogLimit : std::uint8_t { Range, Reach, Singularity, Collision, Axis, Step };

/// "range", "reach", "singularity", "collision", "axis", "step".
std::string_view jogLimitName(JogLimit limit);

/// The pose a jog starts from and ends at: the exact joint values and the
/// tool's pose they give, with the encoder counts they round to. A pendant
/// keeps the exact pose between jogs, so that repeated steps do not drift
/// by the counts' rounding.
struct JogPose {
  std::vector<double> q;                                   ///< joint values, joints 1..n
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();  ///< F_world_tool
  std::vector<std::int32_t> encoders;                      ///< every motor (arm joints, then the gripper)
  std::uint8_t config = 0;                                 ///< kinematics::IkConfig bits the arm stands in
  bool configKnown = false;  ///< false at a singular pose, where the inverse kinematics gives no configuration
};

struct JogResult {
  JogPose pose;                   ///< where the jog goes (when ok)
  std::optional<JogLimit> limit;  ///< set when refused
  std::string message;            ///< why it was refused, a sentence without a position
  bool rotation = false;          ///< the axis turns (the amount is degrees)
  bool ok() const { return !limit.has_value(); }
};

class CartesianJog {
 public:
  /// `robot` must have a chain and outlive the jog.
  explicit CartesianJog(const PlacedRobot& robot);

  /// The pose at encoder counts `encoders` (one per motor): forward
  /// kinematics, and the configuration those joint values are in.
  JogPose poseAt(std::span<const std::int32_t> encoders) const;

  /// The axes a jog in `frame` has at `pose`: X, Y, Z, then the rotations the arm controls.
  std::vector<JogAxis> axes(const JogPose& pose, JogFrame frame) const;

  /// `pose` moved by `amount` (length units, or degrees for a rotation)
  /// along or about `axis` (a name of axes(pose, frame)), on the
  /// configuration `pose` is in, with the straight line from `pose.encoders`
  /// to the result planned as MOVES plans it; or refused with its limit.
  /// `pose.encoders` gives what the gripper motor keeps.
  JogResult jog(const JogPose& pose, JogFrame frame, std::string_view axis, double amount) const;

  /// A turn of one jog is less than this (degrees): the line turns the tool
  /// the short way round, so half a turn or more is not one step (refused
  /// as "step"; the keys turn 1, 5 or 15 degrees).
  static constexpr double kMaxTurn = 180.0;

 private:
  const PlacedRobot& robot_;
  kinematics::InverseKinematics ik_;
  Eigen::Isometry3d F_world_0_;
  LinePlanner line_;
};

}  // namespace rs::workcell
