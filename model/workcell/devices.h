// The cell's devices as data (issue 35): what a WORKCELL's CONVEYOR,
// FEEDER, SENSOR, SINK and WIRE lines and an OBJECT's BELT compile to.
// The description reader (compiler/description) fills them, checked (every
// name resolved, every zone with volume); the cell's runtime (runtime/cell)
// makes them act on one clock. Syntax and meaning: docs/models.md,
// "Devices". Every item keeps the place it was written, for errors and the
// language server: a named device's `pos` is where its name is written, a
// wire's its WIRE keyword, a signal's its first word.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"

namespace rs::workcell {

inline constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

/// What an object is in the cell: a part is taken by grippers, rests on
/// what is under it and rides belts; a fixture never moves and is never
/// taken. An OBJECT description says PART or FIXTURE (FIXTURE when it says
/// neither); a WORKCELL OBJECT line may override it.
enum class ObjectKind : std::uint8_t { Part, Fixture };

/// A moving surface on an object: `BELT left right top bottom front back
/// DIRECTION dx dy dz [END OPEN]`, in the object's design coordinates (as
/// its BOX statements, after the shape's ROTATE and MOVE so far). A part
/// resting on `surface`'s top face moves along `direction` while the
/// belt's conveyor runs.
struct Belt {
  Eigen::AlignedBox3d surface;                                ///< x left..right, y bottom..top, z back..front
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();       ///< unit length
  bool endOpen = false;                                       ///< END OPEN: parts run off the end
  diag::Pos pos;
};

/// Where a signal comes from: a conveyor's RUN, a feeder's WHEN and a
/// wire's source. `robot` is empty for the cell's one robot; `LABEL.OUT n`
/// fills it (issue 36), spelled as the robot's ROBOT line labels it once
/// the workcell is built.
struct Signal {
  enum class Kind : std::uint8_t {
    On,      ///< ON: always on
    Off,     ///< OFF: always off
    Output,  ///< OUT n: a robot's output n (1..vm::kIoCount)
    Input,   ///< IN n: a robot's input n (issue 36: another robot's input)
    Sensor,  ///< a sensor by name: on while it sees something
  };
  Kind kind = Kind::Off;
  int number = 0;                  ///< Output, Input: the line's number
  std::string name;                ///< Sensor: its name
  std::size_t sensor = kNoIndex;   ///< Sensor: its index in Devices::sensors
  std::string robot;               ///< the robot's label, empty: the driven robot
  diag::Pos pos;
};

/// `CONVEYOR NAME SPEED v RUN SIGNAL`: runs the belt of the object named
/// NAME (its cell name) at v length units per second while the signal is on.
struct Conveyor {
  std::string name;
  std::size_t object = kNoIndex;  ///< index in Workcell::objects; that object has a belt
  double speed = 0;               ///< length units per second, > 0
  Signal run;
  diag::Pos pos;
};

/// `SENSOR NAME BEAM x y z x y z` or `SENSOR NAME ZONE l r t b f bk`,
/// `[SEES ROBOTS | SEES ALL]`, in world coordinates. On while what it sees
/// (parts by default; robots' links and gripper with SEES ROBOTS; both with
/// SEES ALL) crosses the beam's segment or overlaps the zone.
struct Sensor {
  enum class Shape : std::uint8_t { Beam, Zone };
  enum class Sees : std::uint8_t { Parts, Robots, All };
  std::string name;
  Shape shape = Shape::Beam;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();  ///< Beam: its ends
  Eigen::AlignedBox3d zone;                                                   ///< Zone: the box
  Sees sees = Sees::Parts;
  diag::Pos pos;
};

/// `FEEDER NAME OBJECT-NAME AT x y z (EVERY s | WHEN SIGNAL) [COUNT n]`: puts
/// a new copy of `part` at its place, the first at the start of the run and
/// then every `everyUs`, or one per rising edge of `when`; at most `count`.
struct Feeder {
  std::string name;
  std::string objectName;                 ///< the OBJECT description it copies
  diag::Pos objectPos;                    ///< where OBJECT-NAME was written
  std::size_t part = kNoIndex;            ///< index in Workcell::fedParts
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  ///< its AT corner, as an OBJECT line's
  std::optional<std::int64_t> everyUs;    ///< EVERY, in microseconds (> 0)
  std::optional<Signal> when;             ///< WHEN
  std::optional<std::int64_t> count;      ///< COUNT (>= 1), none: no limit
  diag::Pos pos;
};

/// `SINK NAME ZONE l r t b f bk`: a part whose centre enters the zone leaves
/// the cell and is counted.
struct Sink {
  std::string name;
  Eigen::AlignedBox3d zone;
  diag::Pos pos;
};

/// `WIRE SOURCE TO IN n [AFTER s] [INVERTED]`: input n follows the source,
/// `afterUs` later, inverted if asked. One source per input.
struct Wire {
  Signal source;
  int input = 0;             ///< 1..vm::kIoCount
  std::string robot;         ///< whose input (`LABEL.IN n`, as the ROBOT line spells it); empty: the cell's one robot
  diag::Pos inputPos;        ///< where `IN` or `LABEL.IN` was written
  std::int64_t afterUs = 0;  ///< AFTER, in microseconds (>= 0)
  bool inverted = false;
  diag::Pos pos;
};

/// Everything a WORKCELL block declares besides its robots and objects.
struct Devices {
  std::vector<Conveyor> conveyors;
  std::vector<Sensor> sensors;
  std::vector<Feeder> feeders;
  std::vector<Sink> sinks;
  std::vector<Wire> wires;

  bool empty() const {
    return conveyors.empty() && sensors.empty() && feeders.empty() && sinks.empty() && wires.empty();
  }
};

}  // namespace rs::workcell
