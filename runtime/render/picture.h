// A picture of the workcell: its lines projected to pixels, the tool centre
// points, and the legend. One Picture feeds the cairo drawing (PNG, SVG)
// and the line dumps of the golden tests.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "runtime/render/camera.h"
#include "runtime/render/scene.h"
#include "runtime/render/tool_path.h"

namespace rs::render {

/// One line in pixels (u right, v down).
struct Line2 {
  Eigen::Vector2d a, b;
  workcell::Color color = workcell::Color::White;
  Part part;
  bool colliding = false;  ///< its part overlaps another (collision_marks.h): drawn on top, wider
};

/// A tool centre point in pixels.
struct ToolMark {
  int robot = 0;
  Eigen::Vector2d at;
};

struct Picture {
  int width = 1024, height = 768;
  Camera camera;  ///< what it was projected with
  Fit fit;
  std::vector<Line2> lines;
  std::vector<ToolMark> tools;
  std::vector<std::string> legend;  ///< text lines, top left
  /// The tool centre point's path (`render --path`, tool_path.h): one
  /// polyline in pixels per stretch the tool travelled; drawn in
  /// kPathColor under the tool marks.
  std::vector<std::vector<Eigen::Vector2d>> path;
};

/// What the legend says besides the robots: the workcell and, for a moment
/// of a run, the time.
struct Caption {
  std::string title;
  std::optional<double> seconds;
};

/// Projects the poser's current pose. Frames are drawn when camera.axes is
/// set, with axes 8% of the fit's radius long.
Picture makePicture(const CellPoser& poser, const Camera& camera, const Fit& fit, const Caption& caption);

/// Projects `path` (world points, tool_path.h) into the picture's `path`,
/// with the camera and fit it was made with.
void addPath(Picture& picture, const std::vector<PathPoint>& path);

/// The legend line of one robot: "scorobot  F=0 E=-120 ... A=20".
std::string robotLegend(const workcell::Robot& robot, std::span<const std::int32_t> encoders);

/// "link3", "gripper", "finger2", "finger3", "object", "axis2-z".
std::string partName(const Part& part);

/// The golden-test dump: two header lines (the cell, the line count, the
/// camera and the fit), then one row per line
///   robot 0 scorobot link1 LIGHTBLUE u1 v1 u2 v2
///   object 2 block object YELLOW u1 v1 u2 v2
/// then one row per tool centre point: `tool 0 scorobot u v`; with a path,
/// one row per vertex: `path N u v`, N counting its stretches from 0. Nine
/// decimals.
void dumpText(std::ostream& out, const Picture& picture, const workcell::Workcell& cell);
/// The same as one JSON object: {"width", "height", "lines": [{"owner",
/// "index", "name", "part", "color", "a": [u, v], "b": [u, v]}], "tools": [...]},
/// with a path also "path": [[[u, v], ...], ...] (a list of vertices per stretch).
void dumpJson(std::ostream& out, const Picture& picture, const workcell::Workcell& cell);

}  // namespace rs::render
