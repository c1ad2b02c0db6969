// `render`, `animate` and `plot` of a cell of several robots (cell_draw.h):
// each robot drawn where its motors are at the moment (render --at), the
// page replaying every robot (animate), a lane group per robot (plot). Each
// answers nullopt when the command is a run of one robot, which the
// command then does as always.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include <Eigen/Geometry>

#include "runtime/render/camera.h"
#include "runtime/render/draw.h"
#include "tools/cli/lib/plot_command.h"
#include "tools/cli/lib/render_commands.h"

namespace rs::cli {

/// render: `camera`, `format` and `center` as the command read them.
std::optional<int> renderCellIfSeveral(const RenderOptions& o, const render::Camera& camera,
                                       std::optional<render::ImageFormat> format,
                                       std::optional<Eigen::Vector3d> center, std::ostream& out, std::ostream& err);

/// animate, with the starting camera the command read.
std::optional<int> animateCellIfSeveral(const RenderOptions& o, const render::Camera& camera, std::ostream& out,
                                        std::ostream& err);

/// plot: `format` ("svg", "png", "csv") and --every (0: the default) as the command read them.
std::optional<int> plotCellIfSeveral(const PlotOptions& o, const std::string& format, vm::Micros every,
                                     std::ostream& out, std::ostream& err);

}  // namespace rs::cli
