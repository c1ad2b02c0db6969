// What a shape is in URDF, which draws solids, not lines: each BOX as the
// box it is, each LINE as a thin box along it.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "model/workcell/model.h"

namespace rs::urdf {

/// One box of a link's URDF geometry, in design coordinates.
struct SolidBox {
  Eigen::Isometry3d F_design_box = Eigen::Isometry3d::Identity();  ///< its centre and edge directions
  Eigen::Vector3d size = Eigen::Vector3d::Zero();                   ///< edge lengths, each at least `thin`
  workcell::Color color = workcell::Color::White;
};

/// The boxes that stand for `shape`: its BOX statements in order, then each
/// line that is not a BOX's edge as a box `thin` units square with x along
/// the line (a line of zero length has none). An edge shorter than `thin`
/// (a flat BOX) is made `thin`, so that every box has a volume.
std::vector<SolidBox> solidsOf(const workcell::Shape& shape, double thin);

}  // namespace rs::urdf
