// WORKCELL: the robots and objects placed in it (AT, ROTATE, PART, FIXTURE,
// AS, a robot's PROGRAM) and its floor; its devices are read in description_devices.cpp.
#include "compiler/description/description_parser.h"

namespace rs::compiler::description_detail {

bool Parser::workcellClause(Cursor& c, WorkcellDef& w) {
  if (c.keyword("FLOOR")) {
    if (c.keyword("NONE")) return w.floor.reset(), true;
    double y = 0;
    if (!c.number(y, "the floor's height (y), or NONE")) return false;
    w.floor = y;
    return true;
  }
  bool handled = false;
  const bool read = deviceClause(c, w, handled);
  if (handled) return read;
  const bool robot = c.keyword("ROBOT");
  if (robot || c.keyword("OBJECT")) {
    PlacementDef p;
    p.isRobot = robot;
    if (!c.name(p.what, robot ? "a robot name" : "an object name")) return false;
    w.placements.push_back(p);
    return true;
  }
  constexpr std::string_view kLines = "ROBOT, OBJECT, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END";
  if (w.placements.empty()) return c.failOneOf(kLines);
  PlacementDef& p = w.placements.back();
  if (!p.isRobot && c.keyword("PART")) return p.kind = workcell::ObjectKind::Part, true;
  if (!p.isRobot && c.keyword("FIXTURE")) return p.kind = workcell::ObjectKind::Fixture, true;
  if (c.keyword("AS")) {
    if (!p.as.name.empty()) return c.fail("a name once: this line has an AS already", "one AS names one robot or object");
    return c.name(p.as, p.isRobot ? "a label for this robot in the cell" : "a name for this object in the cell");
  }
  if (p.isRobot && c.keyword("PROGRAM")) {
    if (!p.program.name.empty()) return c.fail("one PROGRAM: this line has one already", "a robot runs one program");
    return c.path(p.program, "the file of the program this robot runs (relative to this file)");
  }
  if (c.keyword("AT")) {
    Point3 at;
    if (!c.point(at, "a position")) return false;
    p.at = at.v;
    return true;
  }
  if (c.keyword("ROTATE")) {
    int axis = 0;
    double degrees = 0;
    if (!c.axis(axis) || !c.number(degrees, "an angle in degrees")) return false;
    p.rotation = axisRotation(axis, degrees) * p.rotation;
    return true;
  }
  return c.failOneOf(p.isRobot ? "ROBOT, OBJECT, AT, ROTATE, AS, PROGRAM, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END"
                                : "ROBOT, OBJECT, AT, ROTATE, PART, FIXTURE, AS, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END");
}

}  // namespace rs::compiler::description_detail
