// Drawing a Chart (chart.h) with cairo, as PNG or SVG: lanes stacked over
// one time axis, the moments to mark as vertical lines across them with
// their words under the axis, and the source lines that ran as ticks
// labelled with their numbers (docs/render.md, "Charts of a run").
//
// The layout is a value of its own so that what places things on the
// chart (the animation page's cursor and clicks, tests reading an SVG)
// uses the same numbers as the drawing.
#pragma once

#include <vector>

#include "runtime/render/chart.h"
#include "runtime/render/draw.h"
#include "runtime/render/palette.h"

namespace rs::render {

struct ChartBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct ChartLayout {
  int width = 0, height = 0;
  double left = 0, right = 0;  ///< x of time 0 and of the run's end
  vm::Micros end = 0;
  std::vector<ChartBox> lanes;  ///< one per Chart::lanes
  ChartBox lines;               ///< the lane of the source lines that ran
  double top = 0, bottom = 0;   ///< what a mark spans: the first lane's top to the lines' bottom
  /// x of time t (the end at `right`; a run that takes no time at `left`).
  double xOf(vm::Micros t) const;
};

/// The chart's default width in pixels, and the narrowest and widest it draws.
inline constexpr int kChartWidth = 1200;
inline constexpr int kChartMinWidth = 400;
inline constexpr int kChartMaxWidth = 16384;

/// Where everything goes for a chart `width` pixels wide; its height
/// follows from the lanes and the marks.
ChartLayout chartLayout(const Chart& chart, int width = kChartWidth);

/// The chart as a PNG or SVG file's bytes (the same inputs give the same bytes).
diag::Result<std::vector<std::uint8_t>> encodeChart(const Chart& chart, const ChartLayout& layout,
                                                    ImageFormat format);

/// The colours of a chart, for the page and for tests that read a picture.
namespace chart_colors {
inline constexpr Rgb kLane = {0x18, 0x1B, 0x27};   ///< a lane's background
inline constexpr workcell::Color kMotor = workcell::Color::LightCyan;
inline constexpr workcell::Color kTcp[3] = {workcell::Color::LightRed, workcell::Color::LightGreen,
                                            workcell::Color::LightBlue};
inline constexpr workcell::Color kGripper = workcell::Color::White;
inline constexpr workcell::Color kHeld = workcell::Color::Brown;  ///< a band while the gripper holds an object
inline constexpr workcell::Color kInput = workcell::Color::LightGreen;   ///< an input while ON
inline constexpr workcell::Color kOutput = workcell::Color::LightRed;   ///< an output while ON
inline constexpr workcell::Color kSensor = workcell::Color::LightMagenta;  ///< a sensor while ON (as the stills draw it)
inline constexpr workcell::Color kConveyor = workcell::Color::Yellow;     ///< a conveyor while its belt runs
/// An input or output while OFF: dim, so that only what is ON stands out.
inline constexpr workcell::Color kOff = workcell::Color::DarkGray;
inline constexpr workcell::Color kLine = workcell::Color::LightGray;  ///< a tick where a source line starts
inline constexpr workcell::Color kCollision = workcell::Color::Red;
inline constexpr workcell::Color kWarning = workcell::Color::Yellow;
inline constexpr workcell::Color kStop = workcell::Color::LightMagenta;
}  // namespace chart_colors

}  // namespace rs::render
