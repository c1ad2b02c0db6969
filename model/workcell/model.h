// The workcell model: what a description (.rsd) compiles to. Geometry is
// kept as the paper's DESIGN module drew it: every line in global (design)
// coordinates at the robot's home position; the kinematic chain says how
// each link's drawing moves when its joints do.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/ascii.h"
#include "model/kinematics/chain_model.h"
#include "model/kinematics/frame.h"
#include "model/kinematics/gripper.h"
#include "model/workcell/devices.h"

namespace rs::workcell {

/// The 16 colours of the EGA palette, by number 0..15.
enum class Color : std::uint8_t {
  Black, Blue, Green, Cyan, Red, Magenta, Brown, LightGray,
  DarkGray, LightBlue, LightGreen, LightCyan, LightRed, LightMagenta, Yellow, White,
};

/// One wireframe line, in design coordinates.
struct Segment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  Color color = Color::White;
};

/// One convex piece of a shape's collision geometry: the convex hull of
/// its points, in the shape's design coordinates. A BOX's piece has its 8
/// corners (`box` true: the collision model insets it face by face).
struct ConvexPiece {
  std::vector<Eigen::Vector3d> points;
  bool box = false;
};

/// A BOX statement as drawn, kept beside its 12 lines for what speaks in
/// solids rather than lines (the URDF export).
struct DrawnBox {
  /// Its centre and edge directions (x from left to right, y from bottom
  /// to top, z from back to front) after the shape's ROTATE and MOVE.
  Eigen::Isometry3d F_design_box = Eigen::Isometry3d::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< edge lengths along those directions
  Color color = Color::White;
  std::size_t firstSegment = 0;  ///< its 12 lines are segments[firstSegment, firstSegment + 12)
};

/// A link or an object: a named collection of lines, and the convex pieces
/// that stand for its solid in collision checks (docs/models.md,
/// "Collisions": each BOX a piece, the LINEs together one hull, unless
/// COLLIDE statements give them).
struct Shape {
  std::string name;
  std::vector<Segment> segments;
  std::vector<ConvexPiece> collision;
  /// Its BOX statements, from the description reader (a shape read from an
  /// image's cell section has its lines only, and none here).
  std::vector<DrawnBox> boxes;
};

/// A gripper: a base and two fingers that turn about r2 and r3 as it
/// closes, its motor, and its end-effector frame (normal n = x, approach
/// a = z, origin at the tool centre point). Drawn in the design coordinates
/// of the robot that carries it.
struct Gripper {
  std::string name;
  Shape base, finger2, finger3;
  char letter = 'A';
  std::int32_t min = 0, max = 0;  // min = open, max = closed
  std::int32_t speed = 200;
  std::int32_t acceleration = 0;  // encoder units per second², 0 = constant speed
  std::int32_t actuation = 0;     // microseconds every move takes, 0 = by speed (runtime/sim/motion.h)
  kinematics::GripperModel model;  // r2, r3, F_G_E, precision
};

struct JointSpec {
  kinematics::JointType type = kinematics::JointType::Revolute;
  char letter = 'A';
  double precision = 1.0;  // degrees or length units per encoder unit
  std::int32_t min = 0, max = 0;
  bool coupling = false;
  std::int32_t speed = 400;  // encoder units per second
  std::int32_t acceleration = 0;  // encoder units per second², 0 = constant speed (runtime/sim/motion.h)
};

/// Where a robot read from a URDF file came from (`describe` says it): the
/// file and the links its chain runs between. Not carried by images.
struct UrdfSource {
  std::string file;
  std::string rootLink, tipLink;
};

/// A robot: links 0..n in order (0 = base) with their home frames F_design_i,
/// joints 1..n, and optionally a gripper whose n/a vectors give the last
/// frame. The chain is derived (D-H) from the frames when the robot is built.
struct Robot {
  std::string name;
  std::vector<Shape> links;
  std::vector<Eigen::Isometry3d> frames;  // F_design_i of each link, then the gripper's
  /// F_design_tool at home, when the tool centre point's frame is not the
  /// last frame (a description's TOOL, a URDF arm's tip link): the chain
  /// then carries it as its tool frame (ChainModel::withTool).
  std::optional<Eigen::Isometry3d> tool;
  std::vector<JointSpec> joints;
  bool hasGripper = false;
  Gripper gripper;
  std::optional<kinematics::ChainModel> chain;  // derived; frames in design coordinates
  std::optional<UrdfSource> urdf;               // read from a URDF file
};

/// A robot in a cell. `label` and `program` come from its WORKCELL ROBOT
/// line (issue 36): `AS LABEL` names it in the cell (what `label.OUT n`
/// and `label.IN n` signals and stimuli name), `PROGRAM FILE` the program
/// it runs. Kept for the cell's runtime: today a run drives one robot.
struct PlacedRobot {
  PlacedRobot() = default;
  PlacedRobot(Robot r, const Eigen::Isometry3d& place) : robot(std::move(r)), F_world_design(place) {}
  Robot robot;
  Eigen::Isometry3d F_world_design = Eigen::Isometry3d::Identity();
  std::string label;    ///< AS LABEL; empty: the description's name (labelOf())
  std::string program;  ///< PROGRAM FILE, resolved against the cell file's folder; empty: none
  diag::Pos pos;        ///< its ROBOT line's robot name (none for a lone robot or an image's)
  diag::Pos labelPos;   ///< where AS's label was written (none without AS)
  diag::Pos programPos; ///< where PROGRAM's file was written (none without PROGRAM)

  /// Its name in the cell.
  const std::string& labelOf() const { return label.empty() ? robot.name : label; }
};

/// The bounds of a shape's lines (empty for a shape without lines).
inline Eigen::AlignedBox3d boundsOf(const Shape& shape) {
  Eigen::AlignedBox3d box;
  for (const Segment& s : shape.segments) box.extend(s.a), box.extend(s.b);
  return box;
}

/// The corner of a shape that a workcell's `OBJECT name AT x y z` puts at
/// the point: least x, least y, greatest z of its lines (the origin for a
/// shape without lines).
inline Eigen::Vector3d atCorner(const Shape& shape) {
  const Eigen::AlignedBox3d b = boundsOf(shape);
  if (b.isEmpty()) return Eigen::Vector3d::Zero();
  return {b.min().x(), b.min().y(), b.max().z()};
}

/// An object in a cell. `kind` and `belt` come from its description
/// (devices.h); `name` is its cell name (`AS NAME`, else the description's
/// name), which a CONVEYOR line names.
struct PlacedObject {
  PlacedObject() = default;
  PlacedObject(Shape s, const Eigen::Isometry3d& place) : shape(std::move(s)), F_world_design(place) {}
  Shape shape;
  Eigen::Isometry3d F_world_design = Eigen::Isometry3d::Identity();
  ObjectKind kind = ObjectKind::Fixture;
  std::string name;
  std::optional<Belt> belt;  ///< in the shape's design coordinates
  diag::Pos pos;             ///< its WORKCELL OBJECT line (none for a fed part)
  /// A part of another robot standing in for it in one robot's swept check
  /// (runtime/run/robot_obstacles.h): how messages name it, "link 2
  /// (upper_arm) of robot 'right'". Empty for the cell's own objects.
  std::string robotPart = {};
  /// False for a feeder's slot (runtime/cell/devices.h): out of the cell
  /// until a part is fed into it, and again once a sink takes that part.
  /// What is out of the cell is never taken and holds up nothing.
  bool inCell = true;
};

struct Workcell {
  std::string name;
  /// The floor: the plane y = *floor of the world, solid below. A WORKCELL
  /// has one at y = 0 unless it says `FLOOR NONE`; a lone robot has none.
  std::optional<double> floor;
  std::vector<PlacedRobot> robots;
  std::vector<PlacedObject> objects;
  /// The cell's devices (devices.h) and the parts its feeders copy: one per
  /// distinct OBJECT name fed, at the design origin (F_world_design is the
  /// identity; the runtime places a copy so its AT corner, atCorner(shape),
  /// is at Feeder::at), kind Part.
  Devices devices;
  std::vector<PlacedObject> fedParts;

  /// The robot a run drives, a program is compiled for and a pendant jogs:
  /// for now the first placed. The one place that says which: a cell of
  /// several robots changes this policy here.
  std::size_t drivenRobotIndex() const { return 0; }
  /// That robot, or null in a cell without robots.
  const PlacedRobot* drivenRobot() const {
    return drivenRobotIndex() < robots.size() ? &robots[drivenRobotIndex()] : nullptr;
  }
  PlacedRobot* drivenRobot() { return drivenRobotIndex() < robots.size() ? &robots[drivenRobotIndex()] : nullptr; }
  /// The robot a label names (ASCII case ignored, as names everywhere in a
  /// description), or kNoIndex.
  std::size_t robotLabeled(std::string_view label) const {
    for (std::size_t i = 0; i < robots.size(); ++i)
      if (base::sameName(robots[i].labelOf(), label)) return i;
    return kNoIndex;
  }
};

}  // namespace rs::workcell
