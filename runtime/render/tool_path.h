// The tool centre point's path over a logged run, in world coordinates:
// what `render --program P --path` and the animation page draw, so that a
// student sees a MOVES line beside the curve a MOVEP makes (docs/render.md,
// "The tool's path").
//
// Why from the log's moves rather than evenly spaced samples: a straight
// line is many short lock-step moves, each of which must be a vertex, and a
// joint move is a curve only between its motors' starts and ends; sampling
// at those moments (a joint move also every few counts in between) follows
// both, whatever the run's length. The points are then thinned to what can be
// told apart (`tolerance`), so a long run's path stays small.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "model/workcell/model.h"
#include "runtime/run/run_log.h"

namespace rs::render {

/// The colour the path is drawn in: EGA cyan, which no library workcell
/// uses for its parts (stdlib/) and which is far from the tool mark's white.
inline constexpr workcell::Color kPathColor = workcell::Color::Cyan;

/// How far (a fraction of the picture's fit radius, camera.h) the drawn path
/// may stray from the tool's: a third of a pixel in a 1024x768 still at zoom 1.
inline constexpr double kPathTolerance = 1e-3;

struct PathPoint {
  vm::Micros at = 0;  ///< when the tool centre point was there
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  /// The path is broken before this point: a RESET jumped the motors
  /// (the tool did not travel between the two).
  bool jump = false;
};

/// The path of `robot`'s tool centre point (the robot that ran the logged
/// program) from time 0 to the log's end, starting at home, sampled where
/// each move starts and ends and every few counts of a joint move: no sample
/// lies farther than `tolerance` (world units) from the polyline returned
/// (a point of a straight stretch, or one closer than that to the last one
/// kept, is left out). Between samples the motors step count by count, so
/// the tool itself zig-zags about the line by up to a count's worth.
std::vector<PathPoint> toolPathOf(const runtime::RunLog& log, const workcell::PlacedRobot& robot, double tolerance);

/// The part of `path` up to time `t`: every point at or before `t`, then
/// `tcp` (where the tool is at `t`) when it differs from the last of them.
std::vector<PathPoint> pathUntil(const std::vector<PathPoint>& path, vm::Micros t, const Eigen::Vector3d& tcp);

}  // namespace rs::render
