// The HTML animation of a run: one self-contained page (no network, every
// script and style inlined) that replays a run's log (runtime::RunLog) on the workcell.
//
// Why the page does the kinematics itself: it embeds the workcell as a
// compact model (each robot's D-H chain and motor drives, each link's lines
// in its own frame's coordinates, the gripper's finger axes) and the run as
// its steps and motor segments, and computes every frame from those, like
// SimMachine and CellPoser do. The file grows with the number of lines and
// steps, not with the run's duration times the frame rate (as precomputed
// keyframes would); any moment can be scrubbed to exactly; the mouse camera
// and AXES cost nothing extra; and the page's maths is checked against
// `robotsim render --dump-lines` in the browser test.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runtime/render/camera.h"
#include "runtime/render/chart.h"
#include "runtime/render/frames.h"
#include "runtime/run/run_log.h"
#include "model/workcell/model.h"

namespace rs::render {

/// The program as the page lists it.
struct Listing {
  std::string name;                   ///< file name shown in the title
  std::vector<std::string> lines;     ///< the source text's lines (or a disassembly)
  std::vector<std::uint32_t> lineOf;  ///< 1-based listing line of each instruction
};

/// A collision of the run, for the page: its parts turn red from `at` to
/// `end` (the end of the move). `robotParts` index the driven robot's
/// "parts" (links, then the gripper's base and fingers), `objects` the
/// model's "objects".
struct CollisionMark {
  vm::Micros at = 0, end = 0;
  std::vector<int> robotParts, objects;
};

/// Another robot of a cell of several (runtime/run/cell_run.h) and its log:
/// the page moves it by time, as its log says, beside the program's robot.
struct OtherRobotRun {
  std::size_t robot = 0;  ///< its index in Workcell::robots
  const runtime::RunLog* run = nullptr;
};

struct AnimationInput {
  const workcell::Workcell* cell = nullptr;  ///< its robot `robot` ran the program
  const runtime::RunLog* run = nullptr;
  /// The robot whose run `run` is (Workcell::drivenRobotIndex for a run of
  /// one), and in a cell of several the others that ran programs too.
  std::size_t robot = 0;
  std::vector<OtherRobotRun> others = {};
  Listing listing;
  /// The starting camera. Its width x height (animate: the default
  /// 1024x768) choose the fit, as for a still of that size; the page keeps
  /// that fit at any window size, scaled to the window's smaller side.
  Camera camera;
  std::string outcome;  ///< how the run stopped, for people ("" = END)
  /// A warning about the whole run, shown with its end ("" = none): the
  /// gripper closed but never took an object (runtime/run/empty_close.h).
  std::string warning;
  std::vector<CollisionMark> collisions;
  /// The steps of `run` that are events besides those its log names (the
  /// steps of the collisions), and the rule that cuts a long run down to
  /// frames (frames.h).
  std::vector<std::uint32_t> eventSteps;
  FrameRule frameRule;
  /// The run's chart, drawn under the scrub bar (chart_draw.h); may be null.
  const Chart* chart = nullptr;
};

/// The page's data: {"title", "cell", "fit", "camera", "style", "robots",
/// "objects", "program", "run"} (the schema is described in docs/render.md).
/// "style" is what the stills draw with, so that the page draws the same:
/// "palette" (the 16 EGA colours as "#rrggbb", kEga), "background"
/// (kBackground), "axisColors" (palette indices of x, y, z, kAxisColors),
/// "axisLength" (fraction of the fit radius, kAxisLength), "toolRadius",
/// "toolLineWidth" (pixels) and "toolColor" (a palette index) of the tool
/// centre point's mark (draw.h). Objects
/// the gripper carries: "run"."grasps" holds the run's grasp records as
/// parallel arrays "step", "at" (µs), "object" (index in "objects"),
/// "held", and "pose" (12 numbers per event, a 3x4 column-major matrix
/// that applies to the object's "pts", which are world coordinates at its
/// placement P: F_E_object · P⁻¹ for a take, to be followed by the first
/// robot's last frame F_world_E(t); F_world_object · P⁻¹ for a let-go).
/// "run"."collisions" holds the collision marks as parallel arrays "at",
/// "end" (µs), "robotParts" and "objects" (an array of indices each). The
/// steps are the run's frames (frames.h); when a long run was cut down,
/// "run"."frames" says so: {"steps": the run's steps, "slot": µs}.
/// With a chart, "chart": {"svg" (the picture, kChartWidth wide), "width",
/// "height" (pixels), "left", "right" (the x of time 0 and of "end", µs)}.
/// A cell of several robots adds "run"."others": per other robot {"robot"
/// (its index in "robots"), "end", "motors", "moves" (as "run"'s, by time:
/// no step numbers), "grasps" ({"at", "object", "held", "pose"}, a take's
/// pose to be followed by that robot's last frame)}; "run"."end" is then
/// the cell's end. A hand-over's let-go is left out of every "grasps": the
/// robot that took the part over carries it from its take on.
nlohmann::ordered_json animationModel(const AnimationInput& input);
/// The same from frames already made of input.run.
nlohmann::ordered_json animationModel(const AnimationInput& input, const Frames& frames);

/// The whole HTML page.
std::string animationHtml(const AnimationInput& input);
std::string animationHtml(const AnimationInput& input, const Frames& frames);

/// What every page draws a cell from: {"fit", "camera", "style",
/// "robots", "objects"} (the driven robot runs the program), as in
/// animationModel. The shared drawing script (drawScript) reads it.
nlohmann::ordered_json cellDrawing(const workcell::Workcell& cell, const Camera& camera);
/// The same with robot `robot` as the one that runs the page's program.
nlohmann::ordered_json cellDrawing(const workcell::Workcell& cell, const Camera& camera, std::size_t robot);

/// A frame as the pages read it: column-major 3x4, the x, y, z axes, then
/// the origin. The teach pendant's state sends its frames the same way.
nlohmann::ordered_json frameJson(const Eigen::Isometry3d& F);

/// The page's parts, for tests that check the script separately, and for
/// other pages that share them (the teach pendant's).
std::string_view pageScript();
std::string_view pageStyle();
std::string_view drawScript();

/// A model as the text of a <script type="application/json">: every '<'
/// written as \u003c, so that no text in it can close or comment the element.
std::string scriptSafeJson(const nlohmann::ordered_json& model);
/// Text for HTML: & < > " escaped.
std::string escapeHtml(std::string_view text);

}  // namespace rs::render
