// `robotsim render` (a still of a workcell, at its placed pose or at a
// moment of a program's run: PNG, SVG or a dump of the projected lines) and
// `robotsim animate` (a self-contained HTML page replaying a run).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "launch/program.h"
#include "runtime/render/animation.h"
#include "runtime/render/camera.h"
#include "runtime/render/draw.h"
#include "runtime/render/picture.h"
#include "runtime/run/run.h"
#include "model/workcell/model.h"
#include "launch/run_request.h"

namespace CLI {
class App;
}

namespace rs::cli {

/// The most steps `animate` records unless --max-steps says otherwise.
inline constexpr std::uint64_t kAnimateMaxSteps = 1'000'000;

struct RenderOptions {
  /// file: render --program, animate's positional; cell: --cell (render's
  /// positional too: cellArgument); --lib.
  launch::ProgramRequest program;
  launch::RunRequest run;          // --input, --stimuli, --max-steps, --max-time
  std::string at;                  // render --at SECONDS
  std::string output;              // -o
  std::string view, window, size;  // "x,y,z", "x,y,z", "WxH"
  double zoom = 1.0;
  std::string center;              // render --center X,Y,Z: what --zoom zooms about
  bool axes = false;
  bool collisionShapes = false;    // render --collision-shapes
  bool path = false;               // render --path: the tool centre point's path up to the moment drawn
  std::string dump;  // --dump-lines: "", "text" or "json"
  std::vector<std::string> programs = {};  // with a cell: LABEL=FILE for its robots (cell_draw.h)
  /// render's positional CELL (program.cell is its --cell): either names
  /// the cell; beside --cell, a LABEL=FILE.
  std::string cellArgument = {};
};

int renderCommand(const RenderOptions& o, std::ostream& out, std::ostream& err);

/// What render's --zoom zooms about when no --center is given: the middle
/// of the workcell's first robot as drawn at home (the centre of the box
/// around its links and gripper, in the world: the centre of its reach at
/// rest); without a robot, nullopt (the middle of the picture).
std::optional<Eigen::Vector3d> zoomPivot(const workcell::Workcell& cell);
int animateCommand(const RenderOptions& o, std::ostream& out, std::ostream& err);

/// The page's collision marks (and their moves as events) of `run`, which
/// kept a log: each collision's parts red from its moment to its move's end.
void addCollisionMarks(const runtime::Run& run, render::AnimationInput& input);

/// A still's output, as render writes it: the --dump-lines listing (to
/// `out`), the picture in `format` (when set) to -o, and the line that
/// says what was written (`what`, at `moment`). False when the picture
/// cannot be encoded or written (printed).
bool writeStill(const RenderOptions& o, const render::Picture& picture, const workcell::Workcell& cell,
                std::optional<render::ImageFormat> format, const render::Camera& camera, const std::string& what,
                std::optional<vm::Micros> moment, std::ostream& out, std::ostream& err);

/// The options of `render` and of `animate` (commands.cpp's table names
/// both): one RenderOptions serves either.
void addRenderOptions(CLI::App* cmd, RenderOptions& o);
void addAnimateOptions(CLI::App* cmd, RenderOptions& o);

}  // namespace rs::cli
