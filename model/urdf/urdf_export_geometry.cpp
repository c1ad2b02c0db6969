#include "model/urdf/urdf_export_geometry.h"

namespace rs::urdf {

namespace {

// A box along the line from a to b: x from a to b, y and z any two
// directions across it (chosen from the coordinate axis the line leans on
// least, so that the choice is the same every time).
SolidBox lineBox(const workcell::Segment& s, double thin) {
  const Eigen::Vector3d along = s.b - s.a;
  const Eigen::Vector3d x = along.normalized();
  Eigen::Index least = 0;
  x.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d y = x.cross(Eigen::Vector3d::Unit(least)).normalized();
  SolidBox box;
  box.F_design_box.linear() << x, y, x.cross(y);
  box.F_design_box.translation() = (s.a + s.b) / 2;
  box.size = {std::max(along.norm(), thin), thin, thin};
  box.color = s.color;
  return box;
}

}  // namespace

std::vector<SolidBox> solidsOf(const workcell::Shape& shape, double thin) {
  std::vector<SolidBox> solids;
  std::vector<bool> boxEdge(shape.segments.size(), false);
  for (const workcell::DrawnBox& b : shape.boxes) {
    solids.push_back({b.F_design_box, b.size.cwiseMax(thin), b.color});
    for (std::size_t i = b.firstSegment; i < b.firstSegment + 12 && i < boxEdge.size(); ++i) boxEdge[i] = true;
  }
  for (std::size_t i = 0; i < shape.segments.size(); ++i) {
    const workcell::Segment& s = shape.segments[i];
    if (!boxEdge[i] && (s.b - s.a).norm() > 0) solids.push_back(lineBox(s, thin));
  }
  return solids;
}

}  // namespace rs::urdf
