#include "tools/cli/lib/plot_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>

#include "base/file_io.h"
#include "base/seconds.h"
#include "base/text.h"
#include "launch/run_diagnostics.h"
#include "runtime/render/chart_draw.h"
#include "runtime/run/empty_close.h"
#include "tools/cli/lib/cell_draw_commands.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"
#include "tools/cli/lib/options.h"
#include "tools/cli/lib/render_commands.h"
#include "tools/cli/lib/run_warnings.h"
#include "vm/io_lines.h"

namespace rs::cli {

namespace {

/// --width's rule.
inline constexpr NumberRule kChartWidthRule{"a chart's width",
                                            static_cast<double>(render::kChartMinWidth),
                                            static_cast<double>(render::kChartMaxWidth),
                                            true,
                                            false,
                                            "whole pixels, e.g. 1200 (the height follows from the lanes)"};

// "run.SVG" -> "svg"; "" when the name has no extension plot writes.
std::string formatOfPath(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || path.find('/', dot) != std::string_view::npos) return "";
  std::string ext(path.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == "svg" || ext == "png" || ext == "csv" ? ext : "";
}

// What to write: --format, or -o's extension; "" (printed why) when
// neither says or they disagree.
std::string plotFormat(const PlotOptions& o, std::ostream& err) {
  const std::string fromPath = o.output.empty() ? "" : formatOfPath(o.output);
  if (!o.format.empty()) {
    if (!fromPath.empty() && fromPath != o.format) {
      err << fmt::format("robotsim: error: -o {} names a .{} file but --format is {}\n  hint: give the file the "
                         "extension of its format, or leave out --format\n",
                         base::safeText(o.output), fromPath, o.format);
      return "";
    }
    if (o.output.empty() && o.format != "csv") {
      err << fmt::format("robotsim: error: --format={} needs -o FILE\n  hint: only CSV goes to the standard output\n",
                         o.format);
      return "";
    }
    return o.format;
  }
  if (o.output.empty()) {
    err << "robotsim: error: give -o FILE.svg, FILE.png or FILE.csv, or --format=csv for the standard output\n";
    return "";
  }
  if (fromPath.empty()) {
    err << fmt::format("robotsim: error: -o {}: the file name must end in .svg, .png or .csv\n  hint: or say which "
                       "with --format=svg|png|csv\n",
                       base::safeText(o.output));
    return "";
  }
  return fromPath;
}

}  // namespace

std::vector<render::ChartMark> chartMarks(const runtime::Run& run, const std::string& stop) {
  std::vector<render::ChartMark> marks;
  const runtime::CollisionWatch* watch = run.rig().collisionWatch();
  for (const runtime::CollisionEvent& e : run.rig().collisions())
    marks.push_back({render::MarkKind::Collision, e.at, watch ? watch->describe(e.contact) : std::string("collision")});
  if (const auto first = run.rig().firstEmptyClose())
    if (const auto warning = runtime::gripperWarning(run, run.spec().image->sourceName))
      marks.push_back({render::MarkKind::Warning, first->second.at, warning->message});
  if (!stop.empty()) marks.push_back({render::MarkKind::Stop, run.rig().clock(), stop});
  return marks;
}

int plotCommand(const PlotOptions& o, std::ostream& out, std::ostream& err) {
  const std::string format = plotFormat(o, err);
  if (format.empty()) return kExitBadInput;
  vm::Micros every = 0;
  if (!o.every.empty()) {
    if (!parseSecondsArg(o.every, "--every", every, err)) return kExitBadInput;
    if (every <= 0) {
      err << "--every: error: the interval must be above 0\n  hint: e.g. --every 0.01 for a sample every 10 ms\n";
      return kExitBadInput;
    }
  }

  if (const std::optional<int> code = plotCellIfSeveral(o, format, every, out, err)) return *code;
  if (o.program.file.empty()) {
    err << "robotsim: error: which program? give a program file, or --cell CELL to plot every PROGRAM its ROBOT "
           "lines name (LABEL=FILE gives or overrides one)\n";
    return kExitBadInput;
  }
  const launch::LoadedProgram loaded = launch::loadProgramToDraw(o.program);
  std::vector<diag::Diagnostic> diags = loaded.diagnostics;
  std::optional<runtime::RunSpec> spec;
  if (loaded.ok()) spec = launch::prepareRun(loaded, o.run, diags, kAnimateMaxSteps);  // it keeps a log, as animate
  launch::printDiagnostics(err, diags, loaded);
  if (!spec || !loaded.ok()) return kExitBadInput;
  spec->log = true;
  // The straight lines' knots thinned as they are logged, the log exact at
  // every sample (the slot divides the interval: run_log.h).
  spec->lines.on = true;
  spec->lines.slot = every;
  const runtime::CollisionMode collisions = spec->collisions;
  runtime::Run run(std::move(*spec));
  const vm::RunOutcome outcome = run.runUntil({});
  const vm::Image& image = *run.spec().image;
  const runtime::RunLog& log = *run.log();
  if (every > 0 && static_cast<std::uint64_t>(log.end / every) + 2 > render::kMaxChartSamples) {
    err << fmt::format("--every: error: {} s over a run of {} s makes more than {} samples\n  hint: take a longer "
                       "interval, e.g. --every {}\n",
                       base::formatSeconds(every), base::formatSeconds(log.end), render::kMaxChartSamples,
                       base::formatSeconds(render::chartInterval(log.end, 1000)));
    return kExitBadInput;
  }

  std::string stop;
  if (!outcome.ok()) {
    const diag::Diagnostic d = launch::stopDiagnostic(image, outcome, image.sourceName);
    launch::printDiagnostics(err, {d}, loaded);
    stop = d.message;
  }
  printRunWarnings(err, launch::runWarnings(run, collisions, image.sourceName), loaded);

  render::ChartInput input;
  input.cell = run.rig().cell() ? run.rig().cell() : loaded.cell.get();  // with its devices and feeders' slots
  input.run = &log;
  input.marks = chartMarks(run, stop);
  input.every = every;
  const std::string name = o.program.file.substr(o.program.file.find_last_of('/') + 1);
  input.title = fmt::format("{} on {}", base::safeText(name), base::safeText(loaded.cell->name));
  const std::vector<std::uint32_t> lineOf = image.lines.toVector();
  input.lineOf = lineOf;
  const render::Chart chart = render::chartOf(input);
  if (!writeChart(o, format, chart, base::safeText(o.program.file), out, err)) return kExitBadInput;
  return outcome.ok() ? kExitOk : kExitRunFailed;
}

bool writeChart(const PlotOptions& o, const std::string& format, const render::Chart& chart, const std::string& what,
                std::ostream& out, std::ostream& err) {
  std::vector<std::uint8_t> bytes;
  std::string written;
  if (format == "csv") {
    const std::string csv = render::chartCsv(chart);
    if (o.output.empty()) {
      out << csv;
      return true;
    }
    bytes.assign(csv.begin(), csv.end());
    written = fmt::format("{} samples", chart.times.size());
  } else {
    const render::ChartLayout layout = render::chartLayout(chart, o.width);
    diag::Result<std::vector<std::uint8_t>> encoded =
        render::encodeChart(chart, layout, format == "png" ? render::ImageFormat::Png : render::ImageFormat::Svg);
    if (!encoded) {
      err << fmt::format("{}: error: {}\n", base::safeText(o.output), encoded.failure().message);
      return false;
    }
    bytes = std::move(encoded).value();
    written = fmt::format("{}x{} pixels, {} samples", layout.width, layout.height, chart.times.size());
  }
  std::string error;
  const std::size_t size = bytes.size();
  if (!base::writeFileAtomically(o.output, bytes, error)) {
    err << fmt::format("{}: error: cannot write: {}\n", base::safeText(o.output), error);
    return false;
  }
  out << fmt::format("{} -> {} ({}, {} bytes, {} s simulated)\n", what, base::safeText(o.output), written, size,
                     base::formatSeconds(chart.end));
  return true;
}

void addPlotOptions(CLI::App* cmd, PlotOptions& o) {
  cmd->add_option("program", o.program.file,
                  "Program source (.rsp) or compiled image (.rsb); without it, every PROGRAM of --cell");
  cmd->add_option("programs", o.programs,
                  "With --cell: LABEL=FILE gives or overrides the program of the cell's robot LABEL; every robot "
                  "with a program runs it on the cell's one clock, each a lane group of the chart");
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  cmd->add_option("-o,--output", o.output, "Chart to write: FILE.svg, FILE.png, or FILE.csv for the samples");
  cmd->add_option("--format", o.format, "svg, png or csv (default: from -o's extension; csv without -o: to stdout)")
      ->check(CLI::IsMember({"svg", "png", "csv"}));
  cmd->add_option("--every", o.every,
                  "Sample every SECONDS (default: 1, 2 or 5 times a power of ten giving at most 1000 intervals)")
      ->transform(secondsArg());
  cmd->add_option("--width", o.width, "Chart width in pixels (default 1200; the height follows from the lanes)")
      ->transform(numberArg(kChartWidthRule));
  addRunOptions(cmd, o.run, std::to_string(kAnimateMaxSteps));
  cmd->footer(fmt::format(
      "Lanes, top to bottom: each motor of the arm, the tool centre point's x, y and z, the gripper (shaded while "
      "it holds an object), inputs 1-{0}, outputs 1-{0}, on a cell with devices a row per sensor (ON while it sees a "
      "part) and per conveyor (ON while its belt runs), and the source lines that ran (a tick where each starts). "
      "Collisions (red), warnings (yellow) and a failed stop (magenta) are marked across the lanes and listed "
      "under the time axis. The CSV has one row a sample: time_s, each motor by its letter (encoder counts), "
      "tcp_x, tcp_y, tcp_z, held (the object the gripper holds, 0 none), in1..in{0}, out1..out{0} (1 on), "
      "sensor_NAME and belt_NAME on a cell with devices, line. "
      "Exit 0 when the run ended well, 1 when it failed (the chart is written either way), 2 on bad input.",
      vm::kIoCount));
}

}  // namespace rs::cli
