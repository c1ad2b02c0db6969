// How deep two convex hulls are in each other, for messages (a collision
// "0.16 deep"; a block set down "0.16 into the pallet: end it 0.16
// higher"): the least overlap of their projections over a set of axes (the
// separating-axis test's measure), and the way the first leaves the second
// soonest along it. The axes are the world's, each hull's own (its pose's)
// and their cross products: exact for two boxes, an upper bound for other
// hulls. Not used by the check itself (gjk.h decides what overlaps).
#pragma once

#include <Eigen/Geometry>

#include "model/workcell/gjk.h"

namespace rs::workcell {

/// Two parts in each other: how far, and which way.
struct Overlap {
  double depth = 0;                                 ///< length units, >= 0
  Eigen::Vector3d away = Eigen::Vector3d::UnitY();  ///< unit: moved by depth along it, the first leaves the second
  bool operator==(const Overlap&) const = default;
};

/// The hulls' overlap (depth 0 when some axis separates them).
Overlap hullOverlap(const PlacedHull& a, const PlacedHull& b);

}  // namespace rs::workcell
