#include "model/workcell/cell_file.h"

#include "base/byte_io.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rs::workcell {

namespace {

constexpr std::uint32_t kCellMagic = 0x4C435352;  // "RSCL"
// Version 2 adds a robot's tool frame (Robot::tool); version 3 (issue 35)
// what a WORKCELL says beyond geometry: the floor, each object's kind,
// name and belt, each robot's label, the devices and the parts feeders
// copy. A cell that needs neither is written as version 1, byte for byte
// as before.
constexpr std::uint16_t kCellVersion = 1;
constexpr std::uint16_t kCellVersionTool = 2;
constexpr std::uint16_t kCellVersionDevices = 3;
// The image's byte writer and reader, with the cell's compound fields.
class Out : public base::ByteWriter {
 public:
  void vec(const Eigen::Vector3d& v) { f64(v.x()), f64(v.y()), f64(v.z()); }
  void pose(const Eigen::Isometry3d& p) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) f64(p.matrix()(r, c));
  }
  void i64(std::int64_t v) {
    const auto u = static_cast<std::uint64_t>(v);
    u32(static_cast<std::uint32_t>(u)), u32(static_cast<std::uint32_t>(u >> 32));
  }
  void box(const Eigen::AlignedBox3d& b) { vec(b.min()), vec(b.max()); }
  void index(std::size_t i) { u32(i == kNoIndex ? UINT32_MAX : static_cast<std::uint32_t>(i)); }
  void shape(const Shape& s) {
    str(s.name);
    u32(static_cast<std::uint32_t>(s.segments.size()));
    for (const Segment& seg : s.segments) vec(seg.a), vec(seg.b), u8(static_cast<std::uint8_t>(seg.color));
  }
};

class In : public base::ByteReader {
 public:
  explicit In(std::span<const std::uint8_t> b)
      : ByteReader(std::string_view(reinterpret_cast<const char*>(b.data()), b.size()), "cell section") {}
  double number() {
    const double v = f64();
    if (!std::isfinite(v) || std::abs(v) > 1e12) fail("a number that is not finite or too large");
    return v;
  }
  Eigen::Vector3d vec() {
    const double x = number(), y = number(), z = number();
    return {x, y, z};
  }
  Eigen::Isometry3d pose() {
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) p.matrix()(r, c) = number();
    const Eigen::Matrix3d rtr = p.linear().transpose() * p.linear();
    if (!failed && (!rtr.isIdentity(1e-6) || p.linear().determinant() < 0)) fail("a placement that is not a rotation");
    return p;
  }
  std::int64_t i64() {
    const std::uint64_t lo = u32(), hi = u32();
    return static_cast<std::int64_t>(lo | (hi << 32));
  }
  // A box whose corners are ordered and which has volume (every zone and
  // belt a description can write).
  Eigen::AlignedBox3d box() {
    const Eigen::Vector3d lo = vec(), hi = vec();
    if (!failed && !((lo.array() < hi.array()).all())) fail("a box without volume");
    return {lo, hi};
  }
  // An index into a list of `size`, or kNoIndex when `optional` allows it.
  std::size_t index(std::size_t size, std::string_view what, bool optional = false) {
    const std::uint32_t i = u32();
    if (optional && i == UINT32_MAX) return kNoIndex;
    if (!failed && i >= size) fail(fmt::format("{} {} out of range", what, i));
    return i;
  }
  Shape shape() {
    Shape s;
    s.name = name();
    const std::size_t n = count(49, "segment");
    s.segments.reserve(n);
    for (std::size_t i = 0; i < n && !failed; ++i) {
      Segment seg;
      seg.a = vec(), seg.b = vec();
      const std::uint8_t color = u8();
      if (color > 15) fail(fmt::format("colour {}", color));
      seg.color = static_cast<Color>(color);
      s.segments.push_back(seg);
    }
    return s;
  }
  // Names come from descriptions, which never hold control characters.
  std::string name() {
    std::string s = str();
    if (!failed && base::hasControlCharacter(s)) fail("a name that holds a control character");
    return s;
  }
  char letter() {
    const auto c = static_cast<char>(u8());
    if (c < 'A' || c > 'Z') fail("a motor letter outside A..Z");
    return c;
  }
  bool atEnd() const { return remaining() == 0; }
};

void writeRobot(Out& o, const Robot& r, std::uint16_t version) {
  o.str(r.name);
  o.u32(static_cast<std::uint32_t>(r.links.size()));
  for (const Shape& s : r.links) o.shape(s);
  o.u32(static_cast<std::uint32_t>(r.frames.size()));
  for (const Eigen::Isometry3d& f : r.frames) o.pose(f);
  if (version >= kCellVersionTool) {
    o.u8(r.tool.has_value());
    if (r.tool) o.pose(*r.tool);
  }
  o.u32(static_cast<std::uint32_t>(r.joints.size()));
  for (const JointSpec& j : r.joints) {
    o.u8(static_cast<std::uint8_t>(j.type)), o.u8(static_cast<std::uint8_t>(j.letter)), o.u8(j.coupling);
    o.f64(j.precision), o.i32(j.min), o.i32(j.max), o.i32(j.speed);
  }
  o.u8(r.hasGripper);
  if (!r.hasGripper) return;
  const Gripper& g = r.gripper;
  o.str(g.name), o.shape(g.base), o.shape(g.finger2), o.shape(g.finger3);
  o.u8(static_cast<std::uint8_t>(g.letter)), o.i32(g.min), o.i32(g.max), o.i32(g.speed);
  o.f64(g.model.precision);
  o.vec(g.model.r2.point), o.vec(g.model.r2.direction), o.vec(g.model.r3.point), o.vec(g.model.r3.direction);
  o.pose(g.model.F_G_E);
}

std::optional<Robot> readRobot(In& in, std::uint16_t version) {
  Robot r;
  r.name = in.name();
  const std::size_t nl = in.count(6, "link");
  for (std::size_t i = 0; i < nl && !in.failed; ++i) r.links.push_back(in.shape());
  const std::size_t nf = in.count(96, "frame");
  for (std::size_t i = 0; i < nf && !in.failed; ++i) r.frames.push_back(in.pose());
  if (version >= kCellVersionTool && in.u8() != 0 && !in.failed) r.tool = in.pose();
  const std::size_t nj = in.count(23, "joint");
  for (std::size_t i = 0; i < nj && !in.failed; ++i) {
    JointSpec j;
    const std::uint8_t type = in.u8();
    if (type > 1) in.fail(fmt::format("joint type {}", type));
    j.type = static_cast<kinematics::JointType>(type);
    j.letter = in.letter();
    j.coupling = in.u8() != 0;
    j.precision = in.number(), j.min = in.i32(), j.max = in.i32(), j.speed = in.i32();
    if (!in.failed && (j.min > j.max || j.min > 0 || j.max < 0 || j.speed <= 0 || j.precision <= 0)) in.fail("a joint with a bad range, speed or precision");
    r.joints.push_back(j);
  }
  r.hasGripper = in.u8() != 0;
  if (r.hasGripper && !in.failed) {
    Gripper& g = r.gripper;
    g.name = in.name(), g.base = in.shape(), g.finger2 = in.shape(), g.finger3 = in.shape();
    g.letter = in.letter(), g.min = in.i32(), g.max = in.i32(), g.speed = in.i32();
    g.model.precision = in.number();
    g.model.r2.point = in.vec(), g.model.r2.direction = in.vec();
    g.model.r3.point = in.vec(), g.model.r3.direction = in.vec();
    g.model.F_G_E = in.pose();
    if (!in.failed && (g.min > g.max || g.min > 0 || g.max < 0 || g.speed <= 0 || g.model.precision <= 0)) in.fail("a gripper with a bad range");
  }
  if (in.failed) return std::nullopt;
  if (r.frames.size() != r.joints.size() + 1 || r.links.empty()) {
    in.fail(fmt::format("robot {}: {} frames for {} joints", r.name, r.frames.size(), r.joints.size()));
    return std::nullopt;
  }
  std::vector<kinematics::JointType> types;
  std::vector<kinematics::JointDrive> drives;
  for (const JointSpec& j : r.joints) types.push_back(j.type), drives.push_back({j.precision, -1, j.coupling});
  auto chain = kinematics::ChainModel::fromFrames(r.frames, types, drives);
  if (!chain.ok()) {
    in.fail(fmt::format("robot {}: {}", r.name, chain.errors.front().message));
    return std::nullopt;
  }
  r.chain = std::move(chain.value);
  if (r.tool) r.chain = r.chain->withTool(r.frames.back().inverse(Eigen::Isometry) * *r.tool);
  return r;
}


// Version 3's part: what a WORKCELL says beyond geometry. Every index and
// count is checked here, so the runtime can trust a decoded cell as it
// trusts one the description reader built (which also checked names, and
// lines' numbers against the machine's: launch does that for an image).
bool needsDevicesVersion(const Workcell& cell) {
  if (cell.floor || !cell.devices.empty() || !cell.fedParts.empty()) return true;
  for (const PlacedObject& o : cell.objects)
    if (o.kind != ObjectKind::Part || !o.name.empty() || o.belt) return true;
  for (const PlacedRobot& r : cell.robots)
    if (!r.label.empty()) return true;
  return false;
}

void writeObjectFacts(Out& o, const PlacedObject& ob) {
  o.u8(static_cast<std::uint8_t>(ob.kind)), o.str(ob.name), o.u8(ob.belt.has_value());
  if (ob.belt) o.box(ob.belt->surface), o.vec(ob.belt->direction), o.u8(ob.belt->endOpen);
}

void readObjectFacts(In& in, PlacedObject& ob) {
  const std::uint8_t kind = in.u8();
  if (kind > 1) in.fail(fmt::format("object kind {}", kind));
  ob.kind = static_cast<ObjectKind>(kind & 1);
  ob.name = in.name();
  if (in.u8() == 0 || in.failed) return;
  Belt belt;
  belt.surface = in.box(), belt.direction = in.vec();
  belt.endOpen = in.u8() != 0;
  if (!in.failed && std::abs(belt.direction.norm() - 1) > 1e-9) in.fail("a belt direction that is not of unit length");
  ob.belt = belt;
}

void writeSignal(Out& o, const Signal& s) {
  o.u8(static_cast<std::uint8_t>(s.kind)), o.i32(s.number), o.str(s.name), o.index(s.sensor), o.str(s.robot);
}

Signal readSignal(In& in, std::size_t sensors) {
  Signal s;
  const std::uint8_t kind = in.u8();
  if (kind > static_cast<std::uint8_t>(Signal::Kind::Sensor)) in.fail(fmt::format("signal kind {}", kind));
  s.kind = static_cast<Signal::Kind>(std::min<std::uint8_t>(kind, 4));
  s.number = in.i32();
  s.name = in.name();
  s.sensor = in.index(sensors, "sensor", s.kind != Signal::Kind::Sensor);
  s.robot = in.name();
  const bool line = s.kind == Signal::Kind::Output || s.kind == Signal::Kind::Input;
  if (!in.failed && line && (s.number < 1 || s.number > 255)) in.fail(fmt::format("signal line {}", s.number));
  return s;
}

void writeDevicesSection(Out& o, const Workcell& cell) {
  o.u8(cell.floor.has_value());
  if (cell.floor) o.f64(*cell.floor);
  for (const PlacedObject& ob : cell.objects) writeObjectFacts(o, ob);
  for (const PlacedRobot& r : cell.robots) o.str(r.label);
  o.u32(static_cast<std::uint32_t>(cell.fedParts.size()));
  for (const PlacedObject& p : cell.fedParts) o.shape(p.shape), o.pose(p.F_world_design), writeObjectFacts(o, p);
  const Devices& d = cell.devices;
  o.u32(static_cast<std::uint32_t>(d.sensors.size()));
  for (const Sensor& s : d.sensors) {
    o.str(s.name), o.u8(static_cast<std::uint8_t>(s.shape));
    if (s.shape == Sensor::Shape::Beam) o.vec(s.a), o.vec(s.b);
    else o.box(s.zone);
    o.u8(static_cast<std::uint8_t>(s.sees));
  }
  o.u32(static_cast<std::uint32_t>(d.conveyors.size()));
  for (const Conveyor& c : d.conveyors) o.str(c.name), o.index(c.object), o.f64(c.speed), writeSignal(o, c.run);
  o.u32(static_cast<std::uint32_t>(d.feeders.size()));
  for (const Feeder& f : d.feeders) {
    o.str(f.name), o.str(f.objectName), o.index(f.part), o.vec(f.at);
    o.u8(f.everyUs.has_value());
    if (f.everyUs) o.i64(*f.everyUs);
    o.u8(f.when.has_value());
    if (f.when) writeSignal(o, *f.when);
    o.u8(f.count.has_value());
    if (f.count) o.i64(*f.count);
  }
  o.u32(static_cast<std::uint32_t>(d.sinks.size()));
  for (const Sink& k : d.sinks) o.str(k.name), o.box(k.zone);
  o.u32(static_cast<std::uint32_t>(d.wires.size()));
  for (const Wire& w : d.wires)
    writeSignal(o, w.source), o.i32(w.input), o.str(w.robot), o.i64(w.afterUs), o.u8(w.inverted);
}

void readDevicesSection(In& in, Workcell& cell) {
  if (in.u8() != 0) cell.floor = in.number();
  for (PlacedObject& ob : cell.objects) readObjectFacts(in, ob);
  for (PlacedRobot& r : cell.robots) r.label = in.name();
  const std::size_t np = in.count(102, "fed part");
  for (std::size_t i = 0; i < np && !in.failed; ++i) {
    Shape s = in.shape();
    const Eigen::Isometry3d place = in.pose();
    cell.fedParts.push_back({std::move(s), place});
    readObjectFacts(in, cell.fedParts.back());
  }
  Devices& d = cell.devices;
  const std::size_t ns = in.count(52, "sensor");
  for (std::size_t i = 0; i < ns && !in.failed; ++i) {
    Sensor s;
    s.name = in.name();
    const std::uint8_t shape = in.u8();
    if (shape > 1) in.fail(fmt::format("sensor shape {}", shape));
    s.shape = static_cast<Sensor::Shape>(shape & 1);
    if (s.shape == Sensor::Shape::Beam) s.a = in.vec(), s.b = in.vec();
    else s.zone = in.box();
    const std::uint8_t sees = in.u8();
    if (sees > 2) in.fail(fmt::format("sensor sight {}", sees));
    s.sees = static_cast<Sensor::Sees>(std::min<std::uint8_t>(sees, 2));
    d.sensors.push_back(std::move(s));
  }
  const std::size_t nc = in.count(24, "conveyor");
  for (std::size_t i = 0; i < nc && !in.failed; ++i) {
    Conveyor c;
    c.name = in.name();
    c.object = in.index(cell.objects.size(), "conveyor object");
    c.speed = in.number();
    c.run = readSignal(in, ns);
    if (!in.failed && (!cell.objects[c.object].belt || !(c.speed > 0))) in.fail("a conveyor without a belt or speed");
    d.conveyors.push_back(std::move(c));
  }
  const std::size_t nf = in.count(35, "feeder");
  for (std::size_t i = 0; i < nf && !in.failed; ++i) {
    Feeder f;
    f.name = in.name(), f.objectName = in.name();
    f.part = in.index(cell.fedParts.size(), "fed part");
    f.at = in.vec();
    if (in.u8() != 0) f.everyUs = in.i64();
    if (in.u8() != 0) f.when = readSignal(in, ns);
    if (in.u8() != 0) f.count = in.i64();
    if (!in.failed && (f.everyUs.has_value() == f.when.has_value() || (f.everyUs && *f.everyUs <= 0) ||
                       (f.count && *f.count < 1)))
      in.fail("a feeder with a bad EVERY, WHEN or COUNT");
    d.feeders.push_back(std::move(f));
  }
  const std::size_t nk = in.count(50, "sink");
  for (std::size_t i = 0; i < nk && !in.failed; ++i) {
    Sink k;
    k.name = in.name(), k.zone = in.box();
    d.sinks.push_back(std::move(k));
  }
  const std::size_t nw = in.count(28, "wire");
  for (std::size_t i = 0; i < nw && !in.failed; ++i) {
    Wire w;
    w.source = readSignal(in, ns);
    w.input = in.i32();
    w.robot = in.name();
    w.afterUs = in.i64();
    w.inverted = in.u8() != 0;
    if (!in.failed && (w.input < 1 || w.input > 255 || w.afterUs < 0)) in.fail("a wire with a bad input or AFTER");
    for (const Wire& other : d.wires)
      if (!in.failed && other.input == w.input && base::sameName(other.robot, w.robot)) in.fail("two wires to one input");
    d.wires.push_back(std::move(w));
  }
}

}  // namespace

std::vector<std::uint8_t> encodeCell(const Workcell& cell) {
  Out o;
  std::uint16_t version = kCellVersion;
  for (const PlacedRobot& r : cell.robots)
    if (r.robot.tool) version = kCellVersionTool;
  if (needsDevicesVersion(cell)) version = kCellVersionDevices;
  o.u32(kCellMagic);
  o.u16(version);
  o.str(cell.name);
  o.u32(static_cast<std::uint32_t>(cell.robots.size()));
  for (const PlacedRobot& r : cell.robots) writeRobot(o, r.robot, version), o.pose(r.F_world_design);
  o.u32(static_cast<std::uint32_t>(cell.objects.size()));
  for (const PlacedObject& ob : cell.objects) o.shape(ob.shape), o.pose(ob.F_world_design);
  if (version >= kCellVersionDevices) writeDevicesSection(o, cell);
  return o.out;
}

diag::Result<Workcell> decodeCell(std::span<const std::uint8_t> bytes) {
  In in(bytes);
  if (in.u32() != kCellMagic) return diag::refusal("cell section: bad magic number");
  const std::uint16_t version = in.u16();
  if (version < kCellVersion || version > kCellVersionDevices)
    return diag::refusal(fmt::format("cell section: version {} is not supported", version));
  Workcell cell;
  cell.name = in.name();
  const std::size_t nr = in.count(16, "robot");
  for (std::size_t i = 0; i < nr && !in.failed; ++i) {
    std::optional<Robot> r = readRobot(in, version);
    const Eigen::Isometry3d place = in.pose();
    if (r) cell.robots.push_back({std::move(*r), place});
  }
  const std::size_t no = in.count(102, "object");
  for (std::size_t i = 0; i < no && !in.failed; ++i) {
    Shape s = in.shape();
    const Eigen::Isometry3d place = in.pose();
    cell.objects.push_back({std::move(s), place});
    // Versions 1 and 2 do not carry an object's kind: every object read
    // from them can be taken, as every object could before kinds existed.
    cell.objects.back().kind = ObjectKind::Part;
  }
  if (version >= kCellVersionDevices && !in.failed) readDevicesSection(in, cell);
  if (!in.failed && !in.atEnd()) in.fail("unexpected bytes after the last object");
  if (in.failed) return diag::refusal("cell section: " + in.error);
  return cell;
}

}  // namespace rs::workcell
