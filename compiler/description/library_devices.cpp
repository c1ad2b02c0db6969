// A workcell's devices resolved against its placed objects (issue 35):
// conveyors to the objects whose belts they run, signals to sensors,
// feeders to the objects they copy; every mistake a positioned error with
// a hint (docs/models.md, "Devices"). Linear in the number of lines: each
// name is looked up in a hash map.
#include <fmt/format.h>

#include <unordered_map>

#include "base/ascii.h"
#include "base/near_names.h"
#include "compiler/description/library.h"

namespace rs::compiler {

namespace {

using workcell::Signal;

std::string upper(std::string_view name) {
  std::string out(name);
  for (char& c : out) c = base::asciiUpper(c);
  return out;
}

std::string lineOf(diag::Pos p) { return fmt::format("line {}", p.line); }

// "did you mean 'eye'?" when `word` is a near miss of one of `names` (each
// a string of the element `nameOf` gives), else `otherwise`.
template <class Names, class NameOf>
std::string nearNameHint(std::string_view word, const Names& names, NameOf nameOf, std::string otherwise) {
  const std::string_view near = base::nearestNameBy(word, names, nameOf, base::typoDistance(word));
  return near.empty() ? std::move(otherwise) : fmt::format("did you mean '{}'?", near);
}

// The box of everything placed (robots at home, objects), in the world.
Eigen::AlignedBox3d cellBounds(const workcell::Workcell& cell) {
  Eigen::AlignedBox3d box;
  const auto add = [&](const workcell::Shape& s, const Eigen::Isometry3d& F) {
    for (const workcell::Segment& seg : s.segments) box.extend(F * seg.a), box.extend(F * seg.b);
  };
  for (const workcell::PlacedRobot& r : cell.robots) {
    for (const workcell::Shape& l : r.robot.links) add(l, r.F_world_design);
    if (r.robot.hasGripper) {
      add(r.robot.gripper.base, r.F_world_design);
      add(r.robot.gripper.finger2, r.F_world_design);
      add(r.robot.gripper.finger3, r.F_world_design);
    }
  }
  for (const workcell::PlacedObject& o : cell.objects) add(o.shape, o.F_world_design);
  return box;
}

// Whether two boxes share volume deeper than `tolerance` on every axis
// (touching, such as a part standing on a belt, is not overlapping).
bool overlaps(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double tolerance) {
  for (int k = 0; k < 3; ++k)
    if (std::min(a.max()[k], b.max()[k]) - std::max(a.min()[k], b.min()[k]) <= tolerance) return false;
  return true;
}

std::string spanText(const Eigen::AlignedBox3d& b) {
  return fmt::format("x {:g}..{:g}, y {:g}..{:g}, z {:g}..{:g}", b.min().x(), b.max().x(), b.min().y(), b.max().y(),
                     b.min().z(), b.max().z());
}

}  // namespace

bool Library::buildDevices(const WorkcellDef& def, const DescriptionFile& from, workcell::Workcell& cell) {
  workcell::Devices d = def.devices;
  if (d.empty()) return true;
  bool ok = true;
  const auto fail = [&](diag::Pos at, std::string message, std::string hint) {
    error(from, at, std::move(message), std::move(hint));
    ok = false;
  };

  // Device names: one namespace for sensors, feeders and sinks.
  std::unordered_map<std::string, diag::Pos> devices;
  std::unordered_map<std::string, std::size_t> sensors;
  const auto named = [&](const std::string& name, diag::Pos at, std::string_view what) {
    const std::string key = upper(name);
    const auto [it, fresh] = devices.emplace(key, at);
    if (!fresh)
      fail(at, fmt::format("a second device named '{}' (the first is at {})", name, lineOf(it->second)),
           fmt::format("give this {} a name of its own", what));
    return fresh;
  };
  for (std::size_t i = 0; i < d.sensors.size(); ++i)
    if (named(d.sensors[i].name, d.sensors[i].pos, "sensor")) sensors.emplace(upper(d.sensors[i].name), i);
  for (const workcell::Feeder& f : d.feeders) named(f.name, f.pos, "feeder");
  for (const workcell::Sink& s : d.sinks) named(s.name, s.pos, "sink");

  // Robot labels (issue 36): `LABEL.OUT n` and `LABEL.IN n` name a robot of
  // the cell; in a cell of several, a line without a label is ambiguous.
  std::string labels;
  for (const workcell::PlacedRobot& r : cell.robots) labels += (labels.empty() ? "" : ", ") + r.labelOf();
  const auto robotOf = [&](std::string& label, diag::Pos at, std::string_view what, int number) {
    if (label.empty()) {
      if (cell.robots.size() > 1)
        fail(at, fmt::format("{} {} names no robot, and this workcell has {}", what, number, cell.robots.size()),
             fmt::format("say whose, such as {}.{} {}: the robots are {}", cell.robots.front().labelOf(), what, number,
                         labels));
      return;
    }
    const std::size_t i = cell.robotLabeled(label);
    if (i == workcell::kNoIndex) {
      const std::string all = cell.robots.empty()
                                  ? std::string("the workcell places no robot")
                                  : fmt::format("the robots are {} (a ROBOT line's AS label, else its name)", labels);
      const std::string near =
          nearNameHint(label, cell.robots, [](const workcell::PlacedRobot& r) -> const std::string& { return r.labelOf(); }, "");
      return fail(at, fmt::format("no robot labelled '{}' in this workcell", label), near.empty() ? all : near + " " + all);
    }
    label = cell.robots[i].labelOf();  // as the ROBOT line spells it
  };

  const auto resolve = [&](Signal& s) {
    if (s.kind == Signal::Kind::Output || s.kind == Signal::Kind::Input)
      robotOf(s.robot, s.pos, s.kind == Signal::Kind::Output ? "OUT" : "IN", s.number);
    if (s.kind != Signal::Kind::Sensor) return;
    const auto it = sensors.find(upper(s.name));
    if (it == sensors.end())
      return fail(s.pos, fmt::format("unknown sensor '{}'", s.name),
                  nearNameHint(s.name, d.sensors, [](const workcell::Sensor& n) -> const std::string& { return n.name; },
                               "a signal is a SENSOR's name (declared in this WORKCELL), OUT n, LABEL.OUT n, ON or OFF"));
    s.sensor = it->second;
  };

  // Conveyors: each names one object (by its cell name) that has a belt.
  std::unordered_map<std::string, std::size_t> objects;  // cell name -> index, kNoIndex when two share it
  for (std::size_t o = 0; o < cell.objects.size(); ++o) {
    const auto [it, fresh] = objects.emplace(upper(cell.objects[o].name), o);
    if (!fresh) it->second = workcell::kNoIndex;
  }
  std::unordered_map<std::size_t, diag::Pos> run;  // object -> its CONVEYOR line
  for (workcell::Conveyor& v : d.conveyors) {
    resolve(v.run);
    const auto it = objects.find(upper(v.name));
    if (it == objects.end()) {
      fail(v.pos, fmt::format("unknown object '{}': no OBJECT line of this workcell places it or names it so", v.name),
           nearNameHint(v.name, cell.objects, [](const workcell::PlacedObject& o) -> const std::string& { return o.name; },
                        "a CONVEYOR names an object placed in the cell, by its AS name when it has one"));
      continue;
    }
    if (it->second == workcell::kNoIndex) {
      fail(v.pos, fmt::format("two objects of this workcell are named '{}'", v.name),
           "give each its own name with AS on its OBJECT line, and name one here");
      continue;
    }
    const workcell::PlacedObject& o = cell.objects[it->second];
    if (!o.belt) {
      fail(v.pos, fmt::format("object '{}' ({}) has no BELT to run", v.name, o.shape.name),
           fmt::format("a CONVEYOR runs an object whose description has a BELT line; {} has none", o.shape.name));
      continue;
    }
    if (const auto [first, fresh] = run.emplace(it->second, v.pos); !fresh) {
      fail(v.pos, fmt::format("a second CONVEYOR for '{}' (the first is at {})", v.name, lineOf(first->second)),
           "one CONVEYOR line runs one belt");
      continue;
    }
    v.object = it->second;
  }

  // Sensors and sinks: in the cell.
  // "In the cell": within the box of what it holds, grown on every side by
  // a quarter of its largest extent (the robot reaches beyond its home pose).
  Eigen::AlignedBox3d bounds = cellBounds(cell);
  if (!bounds.isEmpty()) {
    const double margin = bounds.sizes().maxCoeff() / 4;
    bounds.min().array() -= margin, bounds.max().array() += margin;
  }
  const auto inCell = [&](const Eigen::AlignedBox3d& box, diag::Pos at, std::string_view what, const std::string& name) {
    const bool belowFloor = cell.floor && box.max().y() < *cell.floor;
    if (!belowFloor && !bounds.isEmpty() && overlaps(box, bounds, -1e-9)) return;
    fail(at,
         fmt::format("{} '{}' is out of the cell: {}", what, name,
                     belowFloor ? "it is under the floor"
                                : fmt::format("it is nowhere near what the cell holds ({})", bounds.isEmpty() ? "nothing" : spanText(bounds))),
         "place it where parts go: across a belt, over a table or a pallet, within the robot's reach");
  };
  for (const workcell::Sensor& s : d.sensors) {
    Eigen::AlignedBox3d box = s.zone;
    if (s.shape == workcell::Sensor::Shape::Beam) box = Eigen::AlignedBox3d(s.a.cwiseMin(s.b), s.a.cwiseMax(s.b));
    inCell(box, s.pos, "sensor", s.name);
  }
  for (const workcell::Sink& s : d.sinks) inCell(s.zone, s.pos, "sink", s.name);

  // Feeders: the object they copy, its place clear of every fixture.
  std::unordered_map<std::string, std::size_t> fed;  // OBJECT name -> index in cell.fedParts
  for (workcell::Feeder& f : d.feeders) {
    if (f.when) resolve(*f.when);
    const std::string key = upper(f.objectName);
    auto it = fed.find(key);
    if (it == fed.end()) {
      if (!find<ShapeDef>(Kind::Object, f.objectName, &from)) {
        // The names a near miss may have meant: this file's objects and those the cell places.
        std::vector<std::string> known;
        for (const ShapeDef& o : from.objects) known.push_back(o.name);
        for (const workcell::PlacedObject& o : cell.objects) known.push_back(o.shape.name);
        fail(f.objectPos,
             fmt::format("unknown object '{0}': not defined in this file, and no {0}.rsd beside it or on the library path",
                         f.objectName),
             nearNameHint(f.objectName, known, [](const std::string& n) -> const std::string& { return n; },
                          "a FEEDER copies an OBJECT description: one of this file, or NAME.rsd beside it or on the "
                          "library path (robotsim list names the library's)"));
        continue;
      }
      auto s = shape(Kind::Object, {f.objectName, f.objectPos}, from);
      if (!s) {
        ok = false;
        continue;
      }
      workcell::PlacedObject part(std::move(*s), Eigen::Isometry3d::Identity());
      part.kind = workcell::ObjectKind::Part;
      part.name = f.objectName;
      if (const ShapeDef* sd = find<ShapeDef>(Kind::Object, f.objectName, &from)) part.belt = sd->belt;
      it = fed.emplace(key, cell.fedParts.size()).first;
      cell.fedParts.push_back(std::move(part));
    }
    f.part = it->second;
    const workcell::Shape& shape = cell.fedParts[f.part].shape;
    Eigen::AlignedBox3d box = workcell::boundsOf(shape);
    if (box.isEmpty()) continue;
    box.translate(f.at - workcell::atCorner(shape));
    for (const workcell::PlacedObject& o : cell.objects) {
      if (o.kind != workcell::ObjectKind::Fixture) continue;
      bool hit = false;
      for (const workcell::ConvexPiece& piece : o.shape.collision) {
        Eigen::AlignedBox3d pb;
        for (const Eigen::Vector3d& p : piece.points) pb.extend(o.F_world_design * p);
        hit = hit || overlaps(box, pb, 1e-3);
      }
      if (!hit) continue;
      fail(f.pos,
           fmt::format("feeder '{}' puts its {} inside fixture '{}' (at {}): the part would span {}", f.name,
                       f.objectName, o.name, lineOf(o.pos), spanText(box)),
           "give a place (its AT corner, as an OBJECT line's) where the part stands on the fixture, not in it");
      break;
    }
  }

  // Wires: one source per input; the second is the error.
  std::unordered_map<std::string, diag::Pos> sourced;  // robot label and input number
  for (workcell::Wire& w : d.wires) {
    resolve(w.source);
    robotOf(w.robot, w.inputPos, "IN", w.input);
    if (const auto [first, fresh] = sourced.emplace(fmt::format("{}.{}", upper(w.robot), w.input), w.pos); !fresh)
      fail(w.pos, fmt::format("input {} has a second source: the WIRE at {} drives it already", w.input, lineOf(first->second)),
           "one input takes one source: remove one of the wires, or wire this one to another input");
  }
  if (ok) cell.devices = std::move(d);
  return ok;
}

}  // namespace rs::compiler
