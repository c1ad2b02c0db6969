#include "model/workcell/cell_file.h"

#include "base/byte_io.h"
#include "base/text.h"

#include <cmath>
#include <fmt/format.h>

namespace rs::workcell {

namespace {

constexpr std::uint32_t kCellMagic = 0x4C435352;  // "RSCL"
// Version 2 adds a robot's tool frame (Robot::tool); a cell without one is
// written as version 1, byte for byte as before.
constexpr std::uint16_t kCellVersion = 1;
constexpr std::uint16_t kCellVersionTool = 2;
// The image's byte writer and reader, with the cell's compound fields.
class Out : public base::ByteWriter {
 public:
  void vec(const Eigen::Vector3d& v) { f64(v.x()), f64(v.y()), f64(v.z()); }
  void pose(const Eigen::Isometry3d& p) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) f64(p.matrix()(r, c));
  }
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

}  // namespace

std::vector<std::uint8_t> encodeCell(const Workcell& cell) {
  Out o;
  std::uint16_t version = kCellVersion;
  for (const PlacedRobot& r : cell.robots)
    if (r.robot.tool) version = kCellVersionTool;
  o.u32(kCellMagic);
  o.u16(version);
  o.str(cell.name);
  o.u32(static_cast<std::uint32_t>(cell.robots.size()));
  for (const PlacedRobot& r : cell.robots) writeRobot(o, r.robot, version), o.pose(r.F_world_design);
  o.u32(static_cast<std::uint32_t>(cell.objects.size()));
  for (const PlacedObject& ob : cell.objects) o.shape(ob.shape), o.pose(ob.F_world_design);
  return o.out;
}

diag::Result<Workcell> decodeCell(std::span<const std::uint8_t> bytes) {
  In in(bytes);
  if (in.u32() != kCellMagic) return diag::refusal("cell section: bad magic number");
  const std::uint16_t version = in.u16();
  if (version != kCellVersion && version != kCellVersionTool)
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
    // The section does not carry an object's kind (yet): every object read
    // from it can be taken, as every object could before kinds existed.
    cell.objects.back().kind = ObjectKind::Part;
  }
  if (!in.failed && !in.atEnd()) in.fail("unexpected bytes after the last object");
  if (in.failed) return diag::refusal("cell section: " + in.error);
  return cell;
}

}  // namespace rs::workcell
