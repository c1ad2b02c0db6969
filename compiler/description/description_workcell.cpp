// WORKCELL: the robots and objects placed in it (AT, ROTATE) and its floor.
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
  const bool robot = c.keyword("ROBOT");
  if (robot || c.keyword("OBJECT")) {
    PlacementDef p;
    p.isRobot = robot;
    if (!c.name(p.what, robot ? "a robot name" : "an object name")) return false;
    w.placements.push_back(p);
    return true;
  }
  if (w.placements.empty()) return c.failOneOf("ROBOT, OBJECT, FLOOR or END");
  PlacementDef& p = w.placements.back();
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
  return c.failOneOf("ROBOT, OBJECT, AT, ROTATE, FLOOR or END");
}

}  // namespace rs::compiler::description_detail
