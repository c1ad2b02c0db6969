// LINK and OBJECT: the lines, boxes and collision pieces of a shape, and
// how ROTATE and MOVE turn what is drawn so far.
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "compiler/description/description_parser.h"

namespace rs::compiler {

namespace description_detail {

namespace {

constexpr std::array<std::string_view, 6> kBoxEdges{"left", "right", "top", "bottom", "front", "back"};

// A BOX's 8 corners as a collision piece: x left..right, y bottom..top,
// z back..front, as its lines; corner 4i + 2j + k takes the i-th x, the
// j-th y and the k-th z.
workcell::ConvexPiece boxPiece(const double (&e)[6]) {
  workcell::ConvexPiece piece;
  piece.box = true;
  const double xs[2] = {e[0], e[1]}, ys[2] = {e[3], e[2]}, zs[2] = {e[5], e[4]};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) piece.points.emplace_back(xs[i], ys[j], zs[k]);
  return piece;
}

// ROTATE and MOVE turn every collision point drawn so far with the lines.
template <typename F>
void forEachPoint(ShapeDef& shape, F&& f) {
  for (workcell::ConvexPiece& piece : shape.boxes)
    for (Eigen::Vector3d& p : piece.points) f(p);
  for (workcell::ConvexPiece& piece : shape.given)
    for (Eigen::Vector3d& p : piece.points) f(p);
  for (Eigen::Vector3d& p : shape.linePoints) f(p);
}

// A BOX's frame and size as drawn (centre, axes along its edges).
workcell::DrawnBox drawnBox(const double (&e)[6], Color color, std::size_t firstSegment) {
  workcell::DrawnBox box;
  box.F_design_box.translation() = Eigen::Vector3d{e[0] + e[1], e[2] + e[3], e[4] + e[5]} / 2;
  box.size = {std::abs(e[1] - e[0]), std::abs(e[2] - e[3]), std::abs(e[4] - e[5])};
  box.color = color;
  box.firstSegment = firstSegment;
  return box;
}

}  // namespace

Eigen::Matrix3d axisRotation(int axis, double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

// LINE, BOX, ROTATE, MOVE, COLOR: the DESIGN LINK / DESIGN OBJECT commands.
bool Parser::shapeClause(Cursor& c, ShapeDef& shape) {
  if (c.keyword("LINE")) {
    Point3 a, b;
    if (!c.point(a, "the LINE's first endpoint") || !c.point(b, "the LINE's second endpoint")) return false;
    Color color = color_;
    if (c.keyword("COLOR") && !c.color(color)) return false;
    shape.segments.push_back({a.v, b.v, color});
    shape.linePoints.push_back(a.v), shape.linePoints.push_back(b.v);
    return true;
  }
  if (c.keyword("BOX")) {
    double e[6];
    for (int k = 0; k < 6; ++k)
      if (!c.number(e[k], fmt::format("the BOX's {} edge", kBoxEdges[static_cast<std::size_t>(k)]))) return false;
    Color color = color_;
    if (c.keyword("COLOR") && !c.color(color)) return false;
    // x from left to right, y from bottom to top, z from back to front.
    const double xs[2] = {e[0], e[1]}, ys[2] = {e[3], e[2]}, zs[2] = {e[5], e[4]};
    shape.drawn.push_back(drawnBox(e, color, shape.segments.size()));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        shape.segments.push_back({{xs[0], ys[i], zs[j]}, {xs[1], ys[i], zs[j]}, color});
        shape.segments.push_back({{xs[i], ys[0], zs[j]}, {xs[i], ys[1], zs[j]}, color});
        shape.segments.push_back({{xs[i], ys[j], zs[0]}, {xs[i], ys[j], zs[1]}, color});
      }
    shape.boxes.push_back(boxPiece(e));
    return true;
  }
  if (c.keyword("COLLIDE")) {
    shape.collideGiven = true;
    if (c.keyword("NONE")) return true;
    if (!c.keyword("BOX")) return c.failOneOf("BOX or NONE");
    double e[6];
    for (int k = 0; k < 6; ++k)
      if (!c.number(e[k], fmt::format("the COLLIDE BOX's {} edge", kBoxEdges[static_cast<std::size_t>(k)]))) return false;
    shape.given.push_back(boxPiece(e));
    return true;
  }
  if (c.keyword("ROTATE")) {
    int axis = 0;
    double degrees = 0;
    if (!c.axis(axis) || !c.number(degrees, "an angle in degrees")) return false;
    const Eigen::Matrix3d r = axisRotation(axis, degrees);
    for (workcell::Segment& s : shape.segments) s.a = r * s.a, s.b = r * s.b;
    forEachPoint(shape, [&](Eigen::Vector3d& p) { p = r * p; });
    for (workcell::DrawnBox& box : shape.drawn) box.F_design_box.prerotate(r);
    if (shape.belt) {  // its box stays axis-aligned: the box of its turned corners
      Eigen::AlignedBox3d turned;
      for (int k = 0; k < 8; ++k) turned.extend(r * shape.belt->surface.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)));
      shape.belt->surface = turned;
      shape.belt->direction = r * shape.belt->direction;
    }
    return true;
  }
  if (c.keyword("MOVE")) {
    Point3 d;
    if (!c.point(d, "a displacement")) return false;
    for (workcell::Segment& s : shape.segments) s.a += d.v, s.b += d.v;
    forEachPoint(shape, [&](Eigen::Vector3d& p) { p += d.v; });
    for (workcell::DrawnBox& box : shape.drawn) box.F_design_box.pretranslate(d.v);
    if (shape.belt) shape.belt->surface.translate(d.v);
    return true;
  }
  if (c.keyword("COLOR")) return c.color(color_);
  if (block_ == Block::Object) {
    const diag::Pos at = c.pos();
    if (c.keyword("PART")) return shape.kind = workcell::ObjectKind::Part, shape.kindPos = at, true;
    if (c.keyword("FIXTURE")) return shape.kind = workcell::ObjectKind::Fixture, shape.kindPos = at, true;
    if (c.isKeyword("BELT")) return belt(c, shape, at);
    return c.failOneOf("LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE, PART, FIXTURE, BELT or END");
  }
  if (c.isKeyword("BELT") || c.isKeyword("PART") || c.isKeyword("FIXTURE"))
    return c.fail("a LINK statement", "BELT, PART and FIXTURE belong in an OBJECT, not a LINK");
  return c.failOneOf("LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END");
}

}  // namespace description_detail

std::vector<workcell::ConvexPiece> ShapeDef::collision() const {
  if (collideGiven) return given;
  std::vector<workcell::ConvexPiece> pieces = boxes;
  if (!linePoints.empty()) pieces.push_back({linePoints, false});
  return pieces;
}

}  // namespace rs::compiler
