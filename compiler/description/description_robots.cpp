// GRIPPER and ROBOT: their parts, frames and joints, and the motor
// settings both share (LETTER, PRECISION, RANGE, SPEED, ACCELERATION), with
// the gripper's ACTUATION.
#include <cmath>
#include <tuple>
#include <fmt/format.h>

#include "base/ascii.h"
#include "compiler/description/description_parser.h"
#include "vm/image.h"

namespace rs::compiler::description_detail {

// LETTER, PRECISION, RANGE, SPEED, ACCELERATION: shared by GRIPPER and JOINT.
bool Parser::motorClause(Cursor& c, char& letter, diag::Pos& letterPos, double& precision, std::int32_t& min,
                         std::int32_t& max, diag::Pos& rangePos, std::int32_t& speed, std::int32_t& acceleration,
                         diag::Pos& accelerationPos, bool* hasLetter, bool* hasPrecision, bool* hasRange) {
  // has* is set as soon as the keyword is seen: a bad value is reported
  // once, not again as "missing".
  if (c.keyword("LETTER")) return *hasLetter = true, c.letter(letter, letterPos);
  if (c.keyword("PRECISION")) {
    *hasPrecision = true;
    const diag::Pos at = c.pos();
    if (!c.number(precision, "a precision (degrees or length units per encoder unit)")) return false;
    if (precision <= 0) {
      diag_.error(at, "a precision must be greater than 0");
      return false;
    }
    return true;
  }
  if (c.keyword("RANGE")) {
    *hasRange = true;
    rangePos = c.pos();
    if (!c.integer(min, "the minimum encoder value") || !c.integer(max, "the maximum encoder value")) return false;
    if (min > max) {
      diag_.error(rangePos, fmt::format("range {}..{} is empty: the minimum is greater than the maximum", min, max));
      return false;
    }
    if (min > 0 || max < 0) {
      diag_.error(rangePos, fmt::format("range {}..{} must include 0: every motor starts at encoder 0 (home)", min, max));
      return false;
    }
    return true;
  }
  if (c.keyword("SPEED")) {
    const diag::Pos at = c.pos();
    if (!c.integer(speed, "a speed in encoder units per second")) return false;
    if (speed <= 0) {
      diag_.error(at, "a speed must be greater than 0");
      return false;
    }
    return true;
  }
  if (c.keyword("ACCELERATION")) {
    accelerationPos = c.pos();
    if (!c.integer(acceleration, "an acceleration in encoder units per second squared")) return false;
    if (acceleration <= 0 || acceleration > vm::kMaxAcceleration) {
      diag_.error(accelerationPos, fmt::format("an acceleration must be 1..{} encoder units per second squared "
                                               "(leave it out for a motor that starts and stops at full speed)",
                                               vm::kMaxAcceleration));
      acceleration = 0;
      return false;
    }
    return true;
  }
  return false;
}

bool Parser::gripperClause(Cursor& c, GripperDef& g) {
  if (c.keyword("BASE")) return c.name(g.base, "the gripper's base link");
  if (c.keyword("FINGERS")) return c.name(g.finger2, "the first finger link") && c.name(g.finger3, "the second finger link");
  const auto twoPoints = [&](Point3 (&p)[2], bool& has, std::string_view what) {
    has = true;
    return c.point(p[0], fmt::format("the {}'s start point", what)) && c.point(p[1], fmt::format("the {}'s end point", what));
  };
  if (c.keyword("AXIS2")) return twoPoints(g.axis2, g.hasAxis2, "axis r2");
  if (c.keyword("AXIS3")) return twoPoints(g.axis3, g.hasAxis3, "axis r3");
  if (c.keyword("NORMAL")) return twoPoints(g.normal, g.hasNormal, "normal vector");
  if (c.keyword("APPROACH")) return twoPoints(g.approach, g.hasApproach, "approach vector");
  if (c.keyword("ACTUATION")) {
    const diag::Pos at = c.pos();
    double seconds = 0;
    if (!c.number(seconds, "an actuation time in seconds")) return false;
    const double limit = vm::kMaxActuation / 1e6;
    if (!(seconds > 0 && seconds <= limit)) {
      diag_.error(at, fmt::format("an actuation time must be more than 0 and at most {} s", limit));
      return false;
    }
    g.actuation = static_cast<std::int32_t>(std::llround(seconds * 1e6));  // whole microseconds
    if (g.actuation == 0) g.actuation = 1;
    return true;
  }
  const std::size_t before = diag_.errorCount();
  if (motorClause(c, g.letter, g.letterPos, g.precision, g.min, g.max, g.rangePos, g.speed, g.acceleration,
                  g.accelerationPos, &g.hasLetter, &g.hasPrecision, &g.hasRange))
    return true;
  if (diag_.errorCount() > before) return false;
  return c.failOneOf(
      "BASE, FINGERS, LETTER, PRECISION, RANGE, SPEED, ACCELERATION, ACTUATION, AXIS2, AXIS3, NORMAL, APPROACH or END");
}

bool Parser::robotClause(Cursor& c, RobotDef& r) {
  if (const diag::Pos at = c.pos(); c.keyword("LINK")) {
    if (r.tool) {
      diag_.error(at, "LINK after TOOL: the tool comes after the last link");
      return false;
    }
    robotItem_ = Item::Link;
    r.links.push_back({});
    return c.name(r.links.back().link, "a link name");
  }
  if (c.keyword("FRAME")) return true;  // introduces ORIGIN, XAXIS, ZAXIS
  {
    const diag::Pos at = c.pos();
    if (c.keyword("TOOL")) {
      if (r.tool) {
        diag_.error(at, "a second TOOL: a robot has one tool centre point");
        return false;
      }
      r.tool.emplace();
      r.tool->link = {"TOOL", at};
      robotItem_ = Item::Tool;
      return true;
    }
  }
  for (auto [kw, member, has] : {std::tuple{"ORIGIN", &RobotLinkDef::origin, &RobotLinkDef::hasOrigin},
                                 std::tuple{"XAXIS", &RobotLinkDef::xPoint, &RobotLinkDef::hasX},
                                 std::tuple{"ZAXIS", &RobotLinkDef::zPoint, &RobotLinkDef::hasZ}}) {
    const diag::Pos at = c.pos();
    if (!c.keyword(kw)) continue;
    if (r.links.empty() && robotItem_ != Item::Tool) {
      diag_.error(at, fmt::format("{} before any LINK: a frame belongs to the LINK before it", kw));
      return false;
    }
    RobotLinkDef& owner = robotItem_ == Item::Tool ? *r.tool : r.links.back();
    owner.*has = true;
    return c.point(owner.*member, fmt::format("the frame's {} point", kw));
  }
  if (c.keyword("JOINT")) {
    robotItem_ = Item::None;  // until the joint is added
    JointDef j;
    j.pos = c.pos();
    std::int32_t n = 0;
    if (!c.integer(n, "a joint number")) return false;
    j.number = n;
    if (c.keyword("REVOLUTE")) j.spec.type = kinematics::JointType::Revolute;
    else if (c.keyword("PRISMATIC")) j.spec.type = kinematics::JointType::Prismatic;
    else return c.failOneOf("REVOLUTE or PRISMATIC");
    r.joints.push_back(j);
    robotItem_ = Item::Joint;
    return true;
  }
  if (c.keyword("COUPLING")) {
    if (r.joints.empty()) return c.fail("a JOINT before COUPLING");
    return c.onOff(r.joints.back().spec.coupling);
  }
  if (c.keyword("GRIPPER")) return c.name(r.gripper, "a gripper name");
  if (r.joints.empty()) {
    for (std::string_view kw : {"LETTER", "PRECISION", "RANGE", "SPEED", "ACCELERATION"})
      if (!c.atEnd() && base::sameName(c.peek().text, kw)) {
        diag_.error(c.pos(), fmt::format("{} before any JOINT: motor settings belong to the JOINT before them", kw));
        return false;
      }
  } else {
    JointDef& j = r.joints.back();
    diag::Pos letterPos;
    const std::size_t before = diag_.errorCount();
    if (motorClause(c, j.spec.letter, letterPos, j.spec.precision, j.spec.min, j.spec.max, j.rangePos, j.spec.speed,
                    j.spec.acceleration, j.accelerationPos, &j.hasLetter, &j.hasPrecision, &j.hasRange))
      return true;
    if (diag_.errorCount() > before) return false;
  }
  return c.failOneOf(
      "LINK, FRAME, ORIGIN, XAXIS, ZAXIS, TOOL, JOINT, LETTER, PRECISION, RANGE, COUPLING, SPEED, ACCELERATION, GRIPPER "
      "or END");
}

}  // namespace rs::compiler::description_detail
