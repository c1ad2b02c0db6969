// Robot and workcell descriptions (.rsd), first stage: one file parsed into
// its definitions (links, objects, grippers, robots, workcells), every
// statement checked for shape. Names are resolved later, across files, by
// the library (library.h). Syntax: docs/models.md.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/source_file.h"
#include "model/workcell/model.h"

namespace rs::compiler {

struct NameRef {
  std::string name;
  diag::Pos pos;
};

/// Three numbers and where the first was written.
struct Point3 {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  diag::Pos pos;
};

// `damaged` on a definition: a line of it had an error, already reported.
// Checks of the whole (counts, numbering, parts that are missing) are then
// skipped: they would only repeat that error in other words.

struct ShapeDef {  // LINK or OBJECT
  std::string name;
  diag::Pos pos;
  std::vector<workcell::Segment> segments;
  std::vector<workcell::ConvexPiece> boxes;   // one per BOX (its corners)
  std::vector<workcell::DrawnBox> drawn;      // one per BOX (its frame and size)
  std::vector<Eigen::Vector3d> linePoints;    // the LINEs' endpoints
  std::vector<workcell::ConvexPiece> given;   // COLLIDE BOX statements
  bool collideGiven = false;                  // any COLLIDE statement
  workcell::ObjectKind kind = workcell::ObjectKind::Fixture;  // OBJECT: PART or FIXTURE
  diag::Pos kindPos;                          // where PART or FIXTURE was written (none: the default)
  std::optional<workcell::Belt> belt;         // OBJECT: BELT
  bool damaged = false;
  /// The collision pieces (docs/models.md, "Collisions"): the COLLIDE
  /// statements' when there is one, else each BOX and the hull of the LINEs.
  std::vector<workcell::ConvexPiece> collision() const;
};

struct GripperDef {
  std::string name;
  diag::Pos pos;
  NameRef base, finger2, finger3;
  char letter = 0;
  diag::Pos letterPos;
  bool hasLetter = false, hasPrecision = false, hasRange = false;
  double precision = 0;
  std::int32_t min = 0, max = 0;
  diag::Pos rangePos;
  std::int32_t speed = 200;
  std::int32_t acceleration = 0;  // ACCELERATION, 0 when not given
  diag::Pos accelerationPos;
  std::int32_t actuation = 0;  // ACTUATION in microseconds, 0 when not given
  Point3 axis2[2], axis3[2], normal[2], approach[2];  // two points each
  bool hasAxis2 = false, hasAxis3 = false, hasNormal = false, hasApproach = false;
  bool damaged = false;
};

struct RobotLinkDef {
  NameRef link;
  Point3 origin, xPoint, zPoint;  // FRAME ORIGIN .. XAXIS .. ZAXIS ..
  bool hasOrigin = false, hasX = false, hasZ = false;
  bool damaged = false;
  bool hasFrame() const { return hasOrigin || hasX || hasZ; }
};

struct JointDef {
  int number = 0;
  diag::Pos pos;
  workcell::JointSpec spec;
  bool hasLetter = false, hasPrecision = false, hasRange = false;
  diag::Pos rangePos, accelerationPos;
  bool damaged = false;
};

struct RobotDef {
  std::string name;
  diag::Pos pos;
  std::vector<RobotLinkDef> links;
  std::vector<JointDef> joints;
  NameRef gripper;  // empty name: none
  /// TOOL ORIGIN .. XAXIS .. ZAXIS ..: the tool centre point's frame at
  /// home, where it is not the last link's frame (`link` holds TOOL's place).
  std::optional<RobotLinkDef> tool;
  bool damaged = false;
};

struct PlacementDef {
  bool isRobot = true;
  NameRef what;
  std::optional<workcell::ObjectKind> kind;  // OBJECT ... PART | FIXTURE: overrides the description's
  NameRef as;                                // AS NAME (empty: the description's name)
  NameRef program;                           // ROBOT ... PROGRAM FILE, as written (empty: none)
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // ROTATE clauses, in order
};

/// A device line of a WORKCELL as read (model/workcell/devices.h): names
/// not yet resolved (Signal::sensor, Conveyor::object, Feeder::part are
/// filled when the workcell is built).
struct WorkcellDef {
  std::string name;
  diag::Pos pos;
  std::vector<PlacementDef> placements;
  workcell::Devices devices{};
  std::optional<double> floor = 0.0;  // FLOOR y, FLOOR NONE
  bool damaged = false;
};

/// Everything one file defines, in the order written.
struct DescriptionFile {
  std::unique_ptr<diag::SourceFile> source;
  std::vector<ShapeDef> links, objects;
  std::vector<GripperDef> grippers;
  std::vector<RobotDef> robots;
  std::vector<WorkcellDef> workcells;
};

/// Parses one description; every error goes to `diagnostics`.
DescriptionFile parseDescription(std::unique_ptr<diag::SourceFile> source, diag::Diagnostics& diagnostics);

/// Whether `text` starts as a description does: its first word (after
/// blank lines, comments and a byte-order mark) opens a block (LINK,
/// OBJECT, GRIPPER, ROBOT, WORKCELL, in any case), or it has no word at
/// all. A file named as a cell that is not a `.rsd` and fails this is
/// refused whole, so that no line of it is ever quoted (/etc/passwd given
/// as a cell must not be printed back, line by line, in a report).
bool looksLikeDescription(std::string_view text);

/// Colour by EGA name ("LIGHTRED") or number ("12").
std::optional<workcell::Color> colorByName(std::string_view word);
std::string_view colorName(workcell::Color color);

}  // namespace rs::compiler
