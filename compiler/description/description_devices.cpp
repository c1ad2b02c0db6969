// A WORKCELL's device lines (CONVEYOR, FEEDER, SENSOR, SINK, WIRE) and an
// OBJECT's BELT, read into model/workcell/devices.h's types. Names are
// resolved when the workcell is built (library_devices.cpp). Syntax:
// docs/models.md, "Devices".
#include <cmath>
#include <fmt/format.h>

#include "base/ascii.h"
#include "compiler/description/description_parser.h"
#include "vm/io_lines.h"

namespace rs::compiler::description_detail {

namespace {

// The longest time an EVERY or AFTER may give: a year, so that its
// microseconds stay far inside 64 bits.
constexpr double kMaxSeconds = 365.0 * 24 * 3600;

bool seconds(Cursor& c, std::int64_t& us, bool zeroAllowed, std::string_view what) {
  const diag::Pos at = c.pos();
  double s = 0;
  if (!c.number(s, what)) return false;
  if (!(s > 0 || (zeroAllowed && s == 0)) || s > kMaxSeconds) {
    c.failAt(at, fmt::format("{} must be {} seconds and at most a year, found {}", what,
                             zeroAllowed ? "0 or more" : "more than 0", s),
             "seconds of simulated time, such as 6 or 0.5");
    return false;
  }
  us = std::llround(s * 1e6);
  if (us == 0 && !zeroAllowed) us = 1;
  return true;
}

// l r t b f bk, as BOX gives them: x left..right, y bottom..top, z back..front.
bool boxEdges(Cursor& c, Eigen::AlignedBox3d& box, std::string_view what) {
  static constexpr std::string_view kEdges[6] = {"left", "right", "top", "bottom", "front", "back"};
  double e[6];
  for (int k = 0; k < 6; ++k)
    if (!c.number(e[k], fmt::format("the {}'s {} edge", what, kEdges[k]))) return false;
  box = Eigen::AlignedBox3d(Eigen::Vector3d{std::min(e[0], e[1]), std::min(e[2], e[3]), std::min(e[4], e[5])},
                            Eigen::Vector3d{std::max(e[0], e[1]), std::max(e[2], e[3]), std::max(e[4], e[5])});
  return true;
}

bool lineNumber(Cursor& c, int& n, std::string_view what) {
  const diag::Pos at = c.pos();
  std::int32_t v = 0;
  if (!c.integer(v, what)) return false;
  if (v < 1 || v > vm::kIoCount) {
    c.failAt(at, fmt::format("{} {} does not exist: the lines are numbered 1..{}", what, v, vm::kIoCount),
             fmt::format("use a number from 1 to {}", vm::kIoCount));
    return false;
  }
  n = v;
  return true;
}

// A word `LABEL.OUT` or `LABEL.IN` (issue 36: a robot's line by its label):
// the label, when the word is one with that keyword after its last dot.
std::optional<std::string> labelled(Cursor& c, std::string_view keyword) {
  if (c.atEnd() || !c.isName()) return std::nullopt;
  const std::string& text = c.peek().text;
  const std::size_t dot = text.rfind('.');
  if (dot == std::string::npos || dot == 0 || !base::sameName(std::string_view(text).substr(dot + 1), keyword))
    return std::nullopt;
  return text.substr(0, dot);
}

// ON, OFF, OUT n, LABEL.OUT n or a sensor's name.
bool signal(Cursor& c, workcell::Signal& s) {
  using K = workcell::Signal::Kind;
  s.pos = c.pos();
  if (c.keyword("ON")) return s.kind = K::On, true;
  if (c.keyword("OFF")) return s.kind = K::Off, true;
  if (c.keyword("OUT")) return s.kind = K::Output, lineNumber(c, s.number, "output");
  if (std::optional<std::string> label = labelled(c, "OUT")) {
    NameRef word;
    c.name(word, "a robot's output");
    s.robot = std::move(*label);
    return s.kind = K::Output, lineNumber(c, s.number, "output");
  }
  if (c.atEnd() || !c.isName() || c.isKeyword("TO") || c.isKeyword("IN") ||
      c.isKeyword("COUNT") || c.isKeyword("AFTER") || c.isKeyword("INVERTED") || labelled(c, "IN"))
    return c.fail("a signal: a sensor's name, OUT n, LABEL.OUT n, ON or OFF",
                  "a wire's source, a conveyor's RUN and a feeder's WHEN take the same signals");
  NameRef n;
  c.name(n, "a sensor name");
  s.kind = K::Sensor;
  s.name = n.name;
  return true;
}

// A device line's keyword, its whole form (the hint of any mistake in it
// without one of its own) and the optional words that may end it.
struct DeviceForm {
  std::string_view keyword;
  std::string_view form;
  std::string_view optional;
};

constexpr DeviceForm kDeviceForms[] = {
    {"CONVEYOR", "CONVEYOR NAME SPEED v RUN SIGNAL", ""},
    {"FEEDER",
     "FEEDER NAME OBJECT-NAME AT x y z EVERY s [COUNT n], or FEEDER NAME OBJECT-NAME AT x y z WHEN "
     "SIGNAL [COUNT n]",
     "COUNT"},
    {"SENSOR",
     "SENSOR NAME BEAM x y z x y z [SEES ROBOTS|ALL], or SENSOR NAME ZONE left right top bottom front "
     "back [SEES ROBOTS|ALL]",
     "SEES"},
    {"SINK", "SINK NAME ZONE left right top bottom front back", ""},
    {"WIRE", "WIRE SOURCE TO IN n [AFTER s] [INVERTED]", "AFTER or INVERTED"},
};

constexpr DeviceForm kBeltForm{"BELT", "BELT left right top bottom front back DIRECTION dx dy dz [END OPEN]",
                               "END"};

// A device line stands alone: it starts its line (checked before its
// keyword is read) ...
bool startsLine(Cursor& c, const DeviceForm& f) {
  c.setFormHint(f.keyword, f.form);
  if (c.atLineStart()) return true;
  return c.failAt(c.pos(), fmt::format("{} starts a line of its own: it cannot follow other words", f.keyword),
                  fmt::format("put the {} line on a new line", f.keyword));
}

// ... and ends it: nothing may follow a complete one.
bool endsLine(Cursor& c, const DeviceForm& f) {
  if (c.atEnd()) return true;
  std::string hint;
  if (c.isName()) {
    const std::string_view word = c.peek().text;
    for (std::size_t i = 0; i < f.optional.size();) {  // an optional word again, or out of its order
      const std::size_t j = std::min(f.optional.find(' ', i), f.optional.size());
      const std::string_view optional = f.optional.substr(i, j - i);
      if (optional != "or" && base::sameName(word, optional))
        hint = fmt::format("{} is written once, in its place: {}", optional, f.form);
      i = j + 1;
    }
    if (hint.empty()) hint = didYouMean(word, f.optional);
  }
  if (hint.empty()) hint = fmt::format("a device line stands alone: {}; start the next one on a new line", f.form);
  return c.fail(fmt::format("the end of the {} line", f.keyword), std::move(hint));
}

bool deviceName(Cursor& c, std::string& out, diag::Pos& pos, std::string_view what) {
  NameRef n;
  if (!c.name(n, what)) return false;
  out = n.name;
  pos = n.pos;
  return true;
}

}  // namespace

bool Parser::belt(Cursor& c, ShapeDef& shape, diag::Pos at) {
  if (!startsLine(c, kBeltForm)) return false;
  c.keyword("BELT");
  workcell::Belt b;
  b.pos = at;
  if (!boxEdges(c, b.surface, "BELT")) return false;
  const Eigen::Vector3d size = b.surface.sizes();
  if (size.x() <= 0 || size.z() <= 0) {
    c.failAt(at, "the BELT's top has no area: its left and right edges, or its front and back, are the same",
             "BELT left right top bottom front back, as BOX takes them");
    return false;
  }
  if (!c.keyword("DIRECTION")) return c.failOneOf("DIRECTION");
  Point3 d;
  if (!c.point(d, "the belt's direction dx dy dz")) return false;
  if (!(d.v.norm() > 1e-9)) {
    c.failAt(d.pos, "the belt's DIRECTION is zero", "the way parts on it travel, such as DIRECTION 1 0 0");
    return false;
  }
  b.direction = d.v.normalized();
  if (c.keyword("END")) {
    if (!c.keyword("OPEN")) return c.failOneOf("OPEN");
    b.endOpen = true;
  }
  if (shape.belt) {
    c.failAt(at, fmt::format("a second BELT in object '{}'", shape.name), "an object has at most one belt");
    return false;
  }
  shape.belt = b;
  return endsLine(c, kBeltForm);
}

bool Parser::deviceClause(Cursor& c, WorkcellDef& w, bool& handled) {
  const DeviceForm* form = nullptr;
  for (const DeviceForm& f : kDeviceForms)
    if (c.isKeyword(f.keyword)) form = &f;
  handled = form != nullptr;
  if (!form) return false;
  if (!startsLine(c, *form)) return false;
  return deviceLine(c, w.devices) && endsLine(c, *form);
}

bool Parser::deviceLine(Cursor& c, workcell::Devices& d) {
  const diag::Pos at = c.pos();
  if (c.keyword("CONVEYOR")) {
    workcell::Conveyor v;
    v.pos = at;
    if (!deviceName(c, v.name, v.pos, "the name of an object with a BELT (its AS name)")) return false;
    if (!c.keyword("SPEED")) return c.failOneOf("SPEED");
    const diag::Pos sp = c.pos();
    if (!c.number(v.speed, "the belt's speed (length units per second)")) return false;
    if (!(v.speed > 0) || v.speed > 1e6) {
      c.failAt(sp, fmt::format("a conveyor's SPEED must be more than 0 and at most 1000000, found {}", v.speed),
               "length units per second, such as SPEED 100");
      return false;
    }
    if (!c.keyword("RUN")) return c.failOneOf("RUN");
    if (!signal(c, v.run)) return false;
    d.conveyors.push_back(std::move(v));
    return true;
  }
  if (c.keyword("FEEDER")) {
    workcell::Feeder f;
    f.pos = at;
    if (!deviceName(c, f.name, f.pos, "a name for the feeder")) return false;
    if (!deviceName(c, f.objectName, f.objectPos, "the name of the OBJECT it feeds")) return false;
    if (!c.keyword("AT")) return c.failOneOf("AT");
    Point3 p;
    if (!c.point(p, "the place of a fed part (its AT corner)")) return false;
    f.at = p.v;
    if (c.keyword("EVERY")) {
      std::int64_t us = 0;
      if (!seconds(c, us, false, "EVERY")) return false;
      f.everyUs = us;
    } else if (c.keyword("WHEN")) {
      workcell::Signal s;
      if (!signal(c, s)) return false;
      f.when = s;
    } else {
      return c.failOneOf("EVERY or WHEN");
    }
    if (c.keyword("COUNT")) {
      const diag::Pos cp = c.pos();
      std::int32_t n = 0;
      if (!c.integer(n, "the most parts it feeds")) return false;
      if (n < 1) {
        c.failAt(cp, fmt::format("a feeder's COUNT must be 1 or more, found {}", n), "leave COUNT out for no limit");
        return false;
      }
      f.count = n;
    }
    d.feeders.push_back(std::move(f));
    return true;
  }
  if (c.keyword("SENSOR")) {
    workcell::Sensor s;
    s.pos = at;
    if (!deviceName(c, s.name, s.pos, "a name for the sensor")) return false;
    if (c.keyword("BEAM")) {
      s.shape = workcell::Sensor::Shape::Beam;
      Point3 a, b;
      if (!c.point(a, "the beam's first end") || !c.point(b, "the beam's second end")) return false;
      if ((a.v - b.v).norm() < 1e-9) {
        c.failAt(a.pos, "the beam's two ends are the same point", "a light barrier runs between two points");
        return false;
      }
      s.a = a.v, s.b = b.v;
    } else if (c.keyword("ZONE")) {
      s.shape = workcell::Sensor::Shape::Zone;
      const diag::Pos zp = c.pos();
      if (!boxEdges(c, s.zone, "ZONE")) return false;
      if (!noVolume(c, s.zone, zp)) return false;
    } else {
      return c.failOneOf("BEAM or ZONE");
    }
    if (c.keyword("SEES")) {
      if (c.keyword("ROBOTS")) s.sees = workcell::Sensor::Sees::Robots;
      else if (c.keyword("ALL")) s.sees = workcell::Sensor::Sees::All;
      else return c.failOneOf("ROBOTS or ALL");
    }
    d.sensors.push_back(std::move(s));
    return true;
  }
  if (c.keyword("SINK")) {
    workcell::Sink s;
    s.pos = at;
    if (!deviceName(c, s.name, s.pos, "a name for the sink")) return false;
    if (!c.keyword("ZONE")) return c.failOneOf("ZONE");
    const diag::Pos zp = c.pos();
    if (!boxEdges(c, s.zone, "ZONE") || !noVolume(c, s.zone, zp)) return false;
    d.sinks.push_back(std::move(s));
    return true;
  }
  if (c.keyword("WIRE")) {
    workcell::Wire wire;
    wire.pos = at;
    if (!signal(c, wire.source)) return false;
    if (!c.keyword("TO")) return c.failOneOf("TO");
    wire.inputPos = c.pos();
    if (std::optional<std::string> label = labelled(c, "IN")) {
      NameRef word;
      c.name(word, "a robot's input");
      wire.robot = std::move(*label);
    } else if (!c.keyword("IN")) {
      return c.failOneOf("IN or LABEL.IN");
    }
    if (!lineNumber(c, wire.input, "input")) return false;
    if (c.keyword("AFTER") && !seconds(c, wire.afterUs, true, "AFTER")) return false;
    if (c.keyword("INVERTED")) wire.inverted = true;
    d.wires.push_back(std::move(wire));
    return true;
  }
  return false;  // not reached: deviceClause found the keyword
}

bool Parser::noVolume(Cursor& c, const Eigen::AlignedBox3d& box, diag::Pos at) {
  const Eigen::Vector3d s = box.sizes();
  if (s.x() > 0 && s.y() > 0 && s.z() > 0) return true;
  c.failAt(at, "the ZONE has no volume: two of its opposite edges are the same",
           "ZONE left right top bottom front back, as BOX takes them, each pair apart");
  return false;
}

}  // namespace rs::compiler::description_detail
