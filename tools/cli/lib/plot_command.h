// `robotsim plot`: a program's run over time as a chart (SVG or PNG, drawn
// by runtime/render/chart_draw.h) or as the sampled series in CSV; and the
// marks a chart of a run carries, which `animate` puts on its page's chart
// too (docs/cli.md, "plot"; docs/render.md, "Charts of a run").
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/render/chart.h"
#include "runtime/run/run.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct PlotOptions {
  launch::ProgramRequest program;  // the positional file, --cell, --lib, --max-errors
  launch::RunRequest run;          // --input, --stimuli, --max-steps, --max-time, --collisions
  std::string output;              // -o FILE.svg|png|csv
  std::string format;              // --format svg|png|csv; empty: from -o
  std::string every;               // --every SECONDS
  int width = 1200;                // --width PIXELS
  std::vector<std::string> programs = {};  // with --cell: LABEL=FILE for its robots (cell_draw.h)
};

/// The moments a chart of `run` (finished) marks: each collision (with
/// what hit what), the first close of the gripper that took nothing (when
/// the run warns of it), and how the run stopped when it did not end well
/// (`stop`: the stop diagnostic's message, empty when it ended well).
std::vector<render::ChartMark> chartMarks(const runtime::Run& run, const std::string& stop);

int plotCommand(const PlotOptions& o, std::ostream& out, std::ostream& err);

/// Writes `chart` as `format` ("svg", "png", "csv") to -o (CSV without -o:
/// to `out`), then the line that says what was written, of `what`. False
/// when it cannot be encoded or written (printed).
bool writeChart(const PlotOptions& o, const std::string& format, const render::Chart& chart, const std::string& what,
                std::ostream& out, std::ostream& err);
void addPlotOptions(CLI::App* cmd, PlotOptions& o);

}  // namespace rs::cli
