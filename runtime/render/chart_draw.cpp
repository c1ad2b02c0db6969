#include "runtime/render/chart_draw.h"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "base/seconds.h"
#include "runtime/render/palette.h"

namespace rs::render {

namespace {

// Pixels.
constexpr double kChartLeft = 150, kChartRightMargin = 20, kChartTitle = 34;
constexpr double kLaneGap = 6, kLanePad = 4;
constexpr double kMotorLane = 56, kTcpLane = 56, kGripperLane = 48, kDigitalRow = 8;
constexpr double kLinesLane = 22, kAxis = 28, kNoteLine = 16, kChartBottom = 10;
constexpr double kGroupTitle = 20;  // above the first lane of a robot's group (a cell's chart)
constexpr std::size_t kNotesShown = 6;  // marks listed under the axis; the rest counted
constexpr double kSmallText = 11, kTitleText = 13;
constexpr Rgb kGrid = {0x2A, 0x2F, 0x40};

void chartColor(cairo_t* cr, Rgb c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

// A row of a device's lane is higher than an input's: its name stands beside it.
constexpr double kDeviceRow = 12;

double laneHeight(const ChartLane& lane) {
  switch (lane.kind) {
    case LaneKind::Motor: return kMotorLane;
    case LaneKind::Tcp: return kTcpLane;
    case LaneKind::Gripper: return kGripperLane;
    case LaneKind::Sensors:
    case LaneKind::Conveyors: return static_cast<double>(lane.series.size()) * kDeviceRow;
    case LaneKind::Inputs:
    case LaneKind::Outputs: break;
  }
  return vm::kIoCount * kDigitalRow;
}

bool isDigitalLane(LaneKind kind) {
  return kind == LaneKind::Inputs || kind == LaneKind::Outputs || kind == LaneKind::Sensors ||
         kind == LaneKind::Conveyors;
}

workcell::Color digitalColor(LaneKind kind) {
  switch (kind) {
    case LaneKind::Inputs: return chart_colors::kInput;
    case LaneKind::Sensors: return chart_colors::kSensor;
    case LaneKind::Conveyors: return chart_colors::kConveyor;
    case LaneKind::Outputs:
    case LaneKind::Motor:
    case LaneKind::Tcp:
    case LaneKind::Gripper: break;
  }
  return chart_colors::kOutput;
}

std::size_t notesOf(const Chart& chart) {
  return std::min(chart.marks.size(), kNotesShown) + (chart.marks.size() > kNotesShown ? 1 : 0);
}

void chartText(cairo_t* cr, double x, double y, const std::string& s, double size, Rgb color, bool alignRight = false) {
  cairo_set_font_size(cr, size);
  if (alignRight) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, s.c_str(), &ext);
    x -= ext.x_advance;
  }
  chartColor(cr, color);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

double chartTextWidth(cairo_t* cr, const std::string& s, double size) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  return ext.x_advance;
}

// A value as a lane's scale shows it: whole counts, lengths with up to 2 decimals.
std::string scaleText(double v, bool length) {
  std::string s = length ? fmt::format("{:.2f}", v) : fmt::format("{:.0f}", v);
  if (length) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

// The lowest and highest value of a lane's series (a flat lane gets ±1).
std::pair<double, double> rangeOf(const Chart& chart, const ChartLane& lane) {
  double lo = INFINITY, hi = -INFINITY;
  for (const std::size_t s : lane.series)
    for (const double v : chart.series[s].values) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) lo = hi = 0;
  if (hi - lo < 1e-9) lo -= 1, hi += 1;
  return {lo, hi};
}

// A series drawn as a polyline through its samples; a flat stretch keeps
// only its ends.
void analogPath(cairo_t* cr, const Chart& chart, const ChartLayout& layout, const std::vector<double>& v,
                const ChartBox& box, double lo, double hi) {
  const auto y = [&](double value) {
    return box.y1 - kLanePad - (value - lo) / (hi - lo) * (box.y1 - box.y0 - 2 * kLanePad);
  };
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool keep = i == 0 || i + 1 == n || v[i] != v[i - 1] || v[i] != v[i + 1];
    if (!keep) continue;
    const double x = layout.xOf(chart.times[i]);
    if (i == 0)
      cairo_move_to(cr, x, y(v[i]));
    else
      cairo_line_to(cr, x, y(v[i]));
  }
}

// An on/off series in row `row` of a digital lane, the level a sample
// found holding until the next sample: each stretch ON as a pulse in the
// lane's bright colour (up at its start, high, down at its end), each
// stretch OFF as a dim line low down. A line that never turns on is one dim
// line: nothing bright that could be read as ON.
void digitalPath(cairo_t* cr, const Chart& chart, const ChartLayout& layout, const std::vector<double>& v,
                 const ChartBox& box, std::size_t row, Rgb on, double rowHeight) {
  const double top = box.y0 + static_cast<double>(row) * rowHeight;
  const double high = top + 1.5, low = top + rowHeight - 1.5;
  const std::size_t n = v.size();
  for (const bool level : {false, true}) {
    bool any = false;
    for (std::size_t i = 0; i < n;) {
      const bool isOn = v[i] > 0.5;
      std::size_t j = i + 1;
      while (j < n && (v[j] > 0.5) == isOn) ++j;
      if (isOn == level) {  // samples i..j-1; the stretch lasts until sample j (or the end)
        const double x0 = layout.xOf(chart.times[i]), x1 = layout.xOf(chart.times[std::min(j, n - 1)]);
        const double y = level ? high : low;
        cairo_move_to(cr, x0, level && i > 0 ? low : y);
        if (level && i > 0) cairo_line_to(cr, x0, high);
        cairo_line_to(cr, x1, y);
        if (level && j < n) cairo_line_to(cr, x1, low);
        any = true;
      }
      i = j;
    }
    if (!any) continue;
    chartColor(cr, level ? on : rgb(chart_colors::kOff));
    cairo_stroke(cr);
  }
}

// Bands where the gripper holds an object (the "held" series > 0, or
// the lane's robot's "LABEL.held").
void heldBands(cairo_t* cr, const Chart& chart, const ChartLayout& layout, const ChartLane& lane, const ChartBox& box) {
  // A cell's chart names each robot's series by its label (cell_chart.h).
  const std::string column = lane.group.empty() ? "held" : lane.group + ".held";
  const auto held = std::find_if(chart.series.begin(), chart.series.end(),
                                 [&](const ChartSeries& s) { return s.column == column; });
  if (held == chart.series.end()) return;
  const std::vector<double>& v = held->values;
  for (std::size_t i = 0; i < v.size();) {
    if (v[i] <= 0) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < v.size() && v[j + 1] > 0) ++j;
    const double x0 = layout.xOf(chart.times[i]), x1 = layout.xOf(chart.times[std::min(j + 1, v.size() - 1)]);
    cairo_rectangle(cr, x0, box.y0, std::max(x1 - x0, 1.0), box.y1 - box.y0);
    i = j + 1;
  }
  chartColor(cr, rgb(chart_colors::kHeld), 0.45);
  cairo_fill(cr);
}

void drawLane(cairo_t* cr, const Chart& chart, const ChartLayout& layout, const ChartLane& lane, const ChartBox& box) {
  cairo_rectangle(cr, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
  chartColor(cr, chart_colors::kLane);
  cairo_fill(cr);
  chartText(cr, 8, box.y0 + 12, lane.label, kSmallText, rgb(workcell::Color::LightGray));
  cairo_set_line_width(cr, 1.25);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (isDigitalLane(lane.kind)) {
    const workcell::Color color = digitalColor(lane.kind);
    for (std::size_t r = 0; r < lane.series.size(); ++r) {
      const double row = lane.rows.empty() ? kDigitalRow : kDeviceRow;
      chartText(cr, box.x0 - 6, box.y0 + static_cast<double>(r + 1) * row - 0.5,
                r < lane.rows.size() ? lane.rows[r] : std::to_string(r + 1), lane.rows.empty() ? 8 : 9,
                rgb(workcell::Color::DarkGray), true);
      digitalPath(cr, chart, layout, chart.series[lane.series[r]].values, box, r, rgb(color), row);
    }
    return;
  }
  if (lane.kind == LaneKind::Gripper) heldBands(cr, chart, layout, lane, box);
  const auto [lo, hi] = rangeOf(chart, lane);
  const bool length = lane.kind == LaneKind::Tcp;
  const Rgb dim = rgb(workcell::Color::DarkGray);
  chartText(cr, box.x0 - 6, box.y0 + kLanePad + 8, scaleText(hi, length), kSmallText, dim, true);
  chartText(cr, box.x0 - 6, box.y1 - kLanePad, scaleText(lo, length), kSmallText, dim, true);
  for (std::size_t k = 0; k < lane.series.size(); ++k) {
    analogPath(cr, chart, layout, chart.series[lane.series[k]].values, box, lo, hi);
    const workcell::Color color = lane.kind == LaneKind::Tcp       ? chart_colors::kTcp[lane.axis % 3]
                                  : lane.kind == LaneKind::Gripper ? chart_colors::kGripper
                                                                   : chart_colors::kMotor;
    chartColor(cr, rgb(color));
    cairo_stroke(cr);
  }
}

// The time axis: a tick and its seconds every 1, 2 or 5 times a power of
// ten, about ten of them, with a faint grid line across the lanes.
void drawTimeAxis(cairo_t* cr, const Chart& chart, const ChartLayout& layout) {
  const vm::Micros tick = chartInterval(chart.end, 10);
  const double y = layout.lines.y1 + 2;
  cairo_set_line_width(cr, 1);
  for (vm::Micros t = 0; t <= chart.end; t += tick) {
    const double x = std::round(layout.xOf(t)) + 0.5;
    cairo_move_to(cr, x, layout.top);
    cairo_line_to(cr, x, layout.bottom);
  }
  chartColor(cr, kGrid);
  cairo_stroke(cr);
  for (vm::Micros t = 0; t <= chart.end; t += tick) {
    std::string s = base::formatSeconds(t);
    while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) s.pop_back();
    const double x = layout.xOf(t), w = chartTextWidth(cr, s, kSmallText);
    chartText(cr, std::clamp(x - w / 2, layout.left - w / 2, layout.right - w), y + 14, s, kSmallText,
         rgb(workcell::Color::LightGray));
  }
  chartText(cr, layout.left - 6, y + 14, "s", kSmallText, rgb(workcell::Color::DarkGray), true);
}

// The source lines that ran: a tick where each starts, its number beside
// it where there is room. Changes closer than half a pixel share a tick.
void drawSourceLines(cairo_t* cr, const Chart& chart, const ChartLayout& layout) {
  const ChartBox& box = layout.lines;
  cairo_rectangle(cr, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
  chartColor(cr, chart_colors::kLane);
  cairo_fill(cr);
  chartText(cr, 8, box.y1 - 7, "source line", kSmallText, rgb(workcell::Color::LightGray));
  cairo_set_line_width(cr, 1);
  double lastTick = -1e9;
  for (const LineChange& c : chart.lineChanges) {
    const double x = layout.xOf(c.at);
    if (x - lastTick < 0.5) continue;
    cairo_move_to(cr, x, box.y0);
    cairo_line_to(cr, x, box.y1);
    lastTick = x;
  }
  chartColor(cr, rgb(chart_colors::kLine));
  cairo_stroke(cr);
  double labelEnd = -1e9;
  for (const LineChange& c : chart.lineChanges) {
    const double x = layout.xOf(c.at) + 2;
    const std::string s = std::to_string(c.line);
    const double w = chartTextWidth(cr, s, kSmallText);
    if (x < labelEnd + 3 || x + w > box.x1) continue;
    chartText(cr, x, box.y1 - 7, s, kSmallText, rgb(workcell::Color::White));
    labelEnd = x + w;
  }
}

workcell::Color markColor(MarkKind kind) {
  switch (kind) {
    case MarkKind::Collision: return chart_colors::kCollision;
    case MarkKind::Stop: return chart_colors::kStop;
    case MarkKind::Warning: break;
  }
  return chart_colors::kWarning;
}

const char* markWord(MarkKind kind) {
  switch (kind) {
    case MarkKind::Collision: return "collision";
    case MarkKind::Stop: return "stop";
    case MarkKind::Warning: break;
  }
  return "warning";
}

// Each mark a vertical line across the lanes with its number above; the
// first few listed under the axis with their time and words.
void drawMarks(cairo_t* cr, const Chart& chart, const ChartLayout& layout) {
  for (std::size_t i = 0; i < chart.marks.size(); ++i) {
    const ChartMark& m = chart.marks[i];
    const double x = layout.xOf(m.at);
    cairo_set_line_width(cr, m.kind == MarkKind::Collision ? 2 : 1.5);
    cairo_move_to(cr, x, layout.top);
    cairo_line_to(cr, x, layout.bottom);
    chartColor(cr, rgb(markColor(m.kind)));
    cairo_stroke(cr);
    if (i < kNotesShown) chartText(cr, x + 2, layout.top - 3, std::to_string(i + 1), kSmallText, rgb(markColor(m.kind)));
  }
  double y = layout.bottom + kAxis + 4;
  for (std::size_t i = 0; i < chart.marks.size() && i < kNotesShown; ++i, y += kNoteLine) {
    const ChartMark& m = chart.marks[i];
    chartText(cr, 8, y, fmt::format("{}  {} s  {}: {}", i + 1, base::formatSeconds(m.at), markWord(m.kind), m.text),
         kSmallText, rgb(markColor(m.kind)));
  }
  if (chart.marks.size() > kNotesShown)
    chartText(cr, 8, y, fmt::format("and {} more marks", chart.marks.size() - kNotesShown), kSmallText,
         rgb(workcell::Color::LightGray));
}

// Lane `l` is the first of its group (a chart of one robot has none).
bool startsGroup(const Chart& chart, std::size_t l) {
  return !chart.lanes[l].group.empty() && (l == 0 || chart.lanes[l - 1].group != chart.lanes[l].group);
}

void drawChart(cairo_t* cr, const Chart& chart, const ChartLayout& layout) {
  chartColor(cr, kBackground);
  cairo_paint(cr);
  cairo_select_font_face(cr, "monospace", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  std::string title = chart.title.empty() ? std::string("run") : chart.title;
  title += fmt::format("   0 to {} s", base::formatSeconds(chart.end));
  if (chart.times.size() > 1)
    title += fmt::format(", a sample every {} s", base::formatSeconds(chart.times[1] - chart.times[0]));
  chartText(cr, 8, 18, title, kTitleText, rgb(workcell::Color::White));
  for (std::size_t l = 0; l < chart.lanes.size(); ++l) {
    if (startsGroup(chart, l))
      chartText(cr, 8, layout.lanes[l].y0 - 6, chart.lanes[l].group == "cell" ? "cell" : "robot " + chart.lanes[l].group,
                kTitleText, rgb(workcell::Color::Yellow));
    drawLane(cr, chart, layout, chart.lanes[l], layout.lanes[l]);
  }
  drawSourceLines(cr, chart, layout);
  drawTimeAxis(cr, chart, layout);
  drawMarks(cr, chart, layout);
}

// cairo numbers the SVG's surface ("<g id=\"surface6\">") with a counter
// of the whole process: the chart always says surface1, so that the same
// run gives the same bytes in one process as in a fresh one.
void sameSurfaceId(std::vector<std::uint8_t>& svg) {
  const std::string_view text(reinterpret_cast<const char*>(svg.data()), svg.size());
  constexpr std::string_view kOpen = "<g id=\"surface";
  const std::size_t at = text.find(kOpen);
  if (at == std::string_view::npos) return;
  const std::size_t digits = at + kOpen.size();
  std::size_t end = digits;
  while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
  if (end == digits || end >= text.size() || text[end] != '"') return;
  svg.erase(svg.begin() + static_cast<std::ptrdiff_t>(digits), svg.begin() + static_cast<std::ptrdiff_t>(end));
  svg.insert(svg.begin() + static_cast<std::ptrdiff_t>(digits), '1');
}

}  // namespace

double ChartLayout::xOf(vm::Micros t) const {
  if (end <= 0) return left;
  return left + (right - left) * static_cast<double>(t) / static_cast<double>(end);
}

ChartLayout chartLayout(const Chart& chart, int width) {
  ChartLayout layout;
  layout.width = std::clamp(width, kChartMinWidth, kChartMaxWidth);
  layout.left = kChartLeft;
  layout.right = layout.width - kChartRightMargin;
  layout.end = chart.end;
  double y = kChartTitle;
  layout.top = y;
  for (std::size_t l = 0; l < chart.lanes.size(); ++l) {
    const ChartLane& lane = chart.lanes[l];
    if (startsGroup(chart, l)) y += kGroupTitle;
    const double h = laneHeight(lane);
    layout.lanes.push_back({layout.left, y, layout.right, y + h});
    y += h + kLaneGap;
  }
  layout.lines = {layout.left, y, layout.right, y + kLinesLane};
  layout.bottom = layout.lines.y1;
  y = layout.bottom + kAxis + static_cast<double>(notesOf(chart)) * kNoteLine + kChartBottom;
  layout.height = static_cast<int>(std::ceil(y));
  return layout;
}

diag::Result<std::vector<std::uint8_t>> encodeChart(const Chart& chart, const ChartLayout& layout,
                                                    ImageFormat format) {
  if (layout.width > kChartMaxWidth || layout.height > kChartMaxWidth) return diag::refusal("chart size out of range");
  diag::Result<std::vector<std::uint8_t>> bytes =
      encodeDrawing(layout.width, layout.height, format, [&](cairo_t* cr) { drawChart(cr, chart, layout); });
  if (bytes && format == ImageFormat::Svg) sameSurfaceId(*bytes);
  return bytes;
}

}  // namespace rs::render
