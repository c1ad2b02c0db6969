// `robotsim plot` and the chart of a run (runtime/render/chart.h,
// chart_draw.h): the samples against values worked out by hand from the
// gantry's speeds and its Cartesian arithmetic, the marks at the moments
// the moves' timing puts them, the picture's bytes the same on every run,
// the PNG decoded, the SVG read by python3's XML parser, and bad input.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>
#include <sstream>

#include "render_test_util.h"
#include "runtime/render/chart.h"
#include "runtime/render/chart_draw.h"
#include "runtime/render/draw.h"
#include "tools/cli/lib/plot_command.h"

using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

namespace {

// On the gantry-cell (motors X, Z, Y, then the gripper A; X and Z 1000
// counts/s, Y 800, A 200, all at constant speed; the tool centre point at
// (500 + X/10, 200 - Y/10, 400 + Z/10)):
//   line 1  X -2800, Z +2800 together: 0 .. 2.8 s
//   line 2  output 3 on at 2.8 s
//   line 3  waits for input 2, which --input turns on at 3.5 s
//   line 4  Y +1000: 3.5 .. 4.75 s
//   line 5  output 3 off at 4.75 s
//   line 6  DELAY 0.5: 4.75 .. 5.25 s
//   line 7  END at 5.25 s
const std::string kChartGantryProgram =
    "MOVETO -2800 2800 0 0\n"
    "OUTSIG 3 ON\n"
    "WAITFOR 2 ON\n"
    "MOVE 0 0 1000 0\n"
    "OUTSIG 3 OFF\n"
    "DELAY 0.5\n"
    "END\n";

// The closing move of a grasp at the block's middle grazes the pallet
// (tests/browser/animation_test.mjs): 0 .. 2.8 s over the block, 1500 / 800
// = 1.875 s down (to 4.675 s), closing 100 / 200 = 0.5 s (to 5.175 s).
const std::string kChartGrazeProgram = "MOVETO -2800 2800 0 0\nMOVETO -2800 2800 1500 0\nMOVE 0 0 0 100\nEND\n";
// A grasp 40 too high: 2.8 s over, 1100 / 800 = 1.375 s down, the close
// ends on nothing at 4.675 s.
const std::string kChartHighProgram = "MOVETO -2800 2800 0 0\nMOVETO -2800 2800 1100 0\nMOVE 0 0 0 100\nEND\n";

// "5.250000" -> 5250000 (the CSV's exact seconds).
std::int64_t chartMicros(const std::string& text) {
  const std::size_t dot = text.find('.');
  REQUIRE(dot != std::string::npos);
  REQUIRE(text.size() - dot - 1 == 6);
  return std::stoll(text.substr(0, dot)) * 1'000'000 + std::stoll(text.substr(dot + 1));
}

struct ChartCsvTable {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

ChartCsvTable parseChartCsv(const std::string& csv) {
  ChartCsvTable table;
  std::istringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (table.header.empty()) {
      table.header = cells;
      continue;
    }
    REQUIRE(cells.size() == table.header.size());
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size(); ++i) row[table.header[i]] = cells[i];
    table.rows.push_back(std::move(row));
  }
  return table;
}

// A constant-speed move's count at t (runtime/sim/motion.h rounds the
// distance covered down): from `from` to `to` at `speed` counts/s from `start`.
std::int64_t chartByHand(std::int64_t from, std::int64_t to, std::int64_t speed, std::int64_t start, std::int64_t t) {
  if (t <= start) return from;
  const std::int64_t covered = std::min<std::int64_t>((t - start) * speed / 1'000'000, std::llabs(to - from));
  return to > from ? from + covered : from - covered;
}

// A run of `program` on the gantry-cell with a log, and its chart with the
// marks plot gives it.
struct ChartRun {
  rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  rs::vm::Image image;
  std::unique_ptr<rs::runtime::Run> run;
  std::vector<std::uint32_t> lineOf;
  rs::render::Chart chart;

  ChartRun(const std::string& program, rs::runtime::CollisionMode mode) {
    image = rendertest::compileText(program, cell);
    run = rendertest::runOf(image, &cell, {}, /*log=*/true, mode);
    const rs::vm::RunOutcome outcome = run->runUntil({});
    lineOf = image.lines.toVector();
    rs::render::ChartInput input;
    input.cell = &cell;
    input.run = run->log();
    input.lineOf = lineOf;
    input.marks = rs::cli::chartMarks(*run, outcome.ok() ? "" : outcome.message);
    chart = rs::render::chartOf(input);
  }
};

std::string chartPython(const std::string& args) {
  std::string out;
  FILE* p = ::popen(("python3 " + rendertest::kSourceDir + "/tests/render/check_chart_svg.py " + args + " 2>&1").c_str(),
                    "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int status = ::pclose(p);
  out += fmt::format("\n(exit status {})", status);
  return out;
}

}  // namespace

TEST_CASE("chartInterval picks 1, 2 or 5 times a power of ten for at most N intervals", "[render][chart]") {
  CHECK(rs::render::chartInterval(0) == 1);
  CHECK(rs::render::chartInterval(1'000'000) == 1'000);
  CHECK(rs::render::chartInterval(1'000'001) == 2'000);
  CHECK(rs::render::chartInterval(5'250'000) == 10'000);
  CHECK(rs::render::chartInterval(5'250'000, 10) == 1'000'000);
  CHECK(rs::render::chartInterval(60'000'000) == 100'000);
}

TEST_CASE("plot's CSV: motors, TCP, I/O and lines equal the values worked out by hand", "[render][chart][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("gantry.rsp", kChartGantryProgram);
  const auto r = runCli({"plot", prog, "--cell", "gantry-cell", "--input", "2=ON@3.5", "--format=csv"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const ChartCsvTable t = parseChartCsv(r.out);
  const std::vector<std::string> header{"time_s", "X", "Z", "Y", "A", "tcp_x", "tcp_y", "tcp_z", "held",
                                        "in1", "in2", "in3", "in4", "in5", "in6", "in7", "in8",
                                        "out1", "out2", "out3", "out4", "out5", "out6", "out7", "out8", "line"};
  CHECK(t.header == header);
  // 5.25 s at the default interval 0.01 s: 0 .. 5.24, then the end.
  REQUIRE(t.rows.size() == 526);
  CHECK(t.rows.back().at("time_s") == "5.250000");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto& row = t.rows[i];
    const std::int64_t at = chartMicros(row.at("time_s"));
    INFO("t = " << row.at("time_s"));
    CHECK(at == std::min<std::int64_t>(static_cast<std::int64_t>(i) * 10'000, 5'250'000));
    const std::int64_t x = chartByHand(0, -2800, 1000, 0, at), z = chartByHand(0, 2800, 1000, 0, at);
    const std::int64_t y = chartByHand(0, 1000, 800, 3'500'000, at);
    CHECK(row.at("X") == std::to_string(x));
    CHECK(row.at("Z") == std::to_string(z));
    CHECK(row.at("Y") == std::to_string(y));
    CHECK(row.at("A") == "0");
    CHECK(std::stod(row.at("tcp_x")) == Approx(500 + x / 10.0).margin(1e-3));
    CHECK(std::stod(row.at("tcp_y")) == Approx(200 - y / 10.0).margin(1e-3));
    CHECK(std::stod(row.at("tcp_z")) == Approx(400 + z / 10.0).margin(1e-3));
    CHECK(row.at("held") == "0");
    CHECK(row.at("in2") == (at >= 3'500'000 ? "1" : "0"));
    CHECK(row.at("out3") == (at >= 2'800'000 && at < 4'750'000 ? "1" : "0"));
    for (const char* other : {"in1", "in3", "in8", "out1", "out2", "out4", "out8"}) CHECK(row.at(other) == "0");
    // The instruction in progress: at a moment where several start, the last of them.
    const char* line = at < 2'800'000 ? "1" : at < 3'500'000 ? "3" : at < 4'750'000 ? "4" : at < 5'250'000 ? "6" : "7";
    CHECK(row.at("line") == line);
  }
}

TEST_CASE("plot --every samples at that interval, and a gripper's take shows in held", "[render][chart][cli]") {
  const TempDir dir;
  // examples/gantry_pick.rsp's first pick: its first block (object 2, as
  // `describe gantry-cell` numbers it) taken at the end of the
  // closing move (2.8 + 1.8625 + 0.5 = 5.1625 s), carried until the gripper
  // opens over the right pallet.
  const auto r = runCli({"plot", rendertest::kSourceDir + "/examples/gantry_pick.rsp", "--cell", "gantry-cell",
                         "--every", "0.25", "-o", dir.file("pick.csv")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("pick.csv (") != std::string::npos);
  const ChartCsvTable t = parseChartCsv(readBytes(dir.file("pick.csv")));
  REQUIRE(t.rows.size() > 10);
  for (std::size_t i = 0; i + 1 < t.rows.size(); ++i)
    CHECK(chartMicros(t.rows[i].at("time_s")) == static_cast<std::int64_t>(i) * 250'000);
  for (const auto& row : t.rows) {
    const std::int64_t at = chartMicros(row.at("time_s"));
    if (at <= 5'000'000) CHECK(row.at("held") == "0");
    if (at >= 5'250'000 && at <= 7'000'000) CHECK(row.at("held") == "2");  // block 1 is object 2, after pallet 1
  }
}

TEST_CASE("a chart marks a collision within its move and the empty grasp at its end", "[render][chart]") {
  SECTION("collision, the run going on") {
    const ChartRun c(kChartGrazeProgram, rs::runtime::CollisionMode::Warn);
    REQUIRE(c.chart.marks.size() == 1);
    const rs::render::ChartMark& m = c.chart.marks[0];
    CHECK(m.kind == rs::render::MarkKind::Collision);
    CHECK(m.at >= 4'675'000);  // during the closing move
    CHECK(m.at <= 5'175'000);
    CHECK(m.text.find("hits") != std::string::npos);
    CHECK(m.text.find("pallet") != std::string::npos);
  }
  SECTION("collision that stops the run: the collision and the stop") {
    const ChartRun c(kChartGrazeProgram, rs::runtime::CollisionMode::Error);
    REQUIRE(c.chart.marks.size() == 2);
    CHECK(c.chart.marks[0].kind == rs::render::MarkKind::Collision);
    CHECK(c.chart.marks[1].kind == rs::render::MarkKind::Stop);
    CHECK(c.chart.marks[1].at == c.chart.end);
    CHECK(c.chart.marks[0].at >= 4'675'000);
    CHECK(c.chart.marks[0].at <= c.chart.end);
  }
  SECTION("the gripper closed on nothing") {
    const ChartRun c(kChartHighProgram, rs::runtime::CollisionMode::Error);
    REQUIRE(c.chart.marks.size() == 1);
    CHECK(c.chart.marks[0].kind == rs::render::MarkKind::Warning);
    CHECK(c.chart.marks[0].at == 4'675'000);
    CHECK(c.chart.end == 4'675'000);
  }
  SECTION("the lines that ran, every change at its step's start") {
    const ChartRun c(kChartGrazeProgram, rs::runtime::CollisionMode::Off);
    REQUIRE(c.chart.lineChanges.size() == 4);
    const std::int64_t at[] = {0, 2'800'000, 4'675'000, 5'175'000};
    for (std::uint32_t i = 0; i < 4; ++i) {
      CHECK(c.chart.lineChanges[i].line == i + 1);
      CHECK(c.chart.lineChanges[i].at == at[i]);
    }
  }
}

TEST_CASE("plot writes the same bytes for the same run, and the PNG decodes", "[render][chart][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("graze.rsp", kChartGrazeProgram);
  for (const char* ext : {"svg", "png"}) {
    const std::string a = dir.file(std::string("a.") + ext), b = dir.file(std::string("b.") + ext);
    const auto ra = runCli({"plot", prog, "--cell", "gantry-cell", "--collisions=warn", "-o", a});
    const auto rb = runCli({"plot", prog, "--cell", "gantry-cell", "--collisions=warn", "-o", b});
    INFO(ra.err);
    REQUIRE(ra.code == 0);
    REQUIRE(rb.code == 0);
    CHECK(ra.err.find("collision at") != std::string::npos);  // the warning, as run prints it
    const std::string bytesA = readBytes(a), bytesB = readBytes(b);
    CHECK(bytesA.size() > 1000);
    CHECK(bytesA == bytesB);
  }
  CHECK(readBytes(dir.file("a.svg")).rfind("<?xml", 0) == 0);
  const std::string png = readBytes(dir.file("a.png"));
  const rs::diag::Result<rs::render::Decoded> decoded = rs::render::decodePng({png.begin(), png.end()});
  REQUIRE(decoded);
  const rs::render::Decoded& d = *decoded;
  CHECK(d.width == 1200);
  // The height the layout gives, worked out from the lanes rather than
  // trusted: X, Z, Y (3 motors of 56 px), the TCP's x, y and z (a lane of
  // 56 px each), the gripper (48), inputs and outputs (8 rows of 8 px), the
  // line lane, the axis and one mark's note, 6 px between lanes.
  CHECK(d.height == static_cast<int>(34 + 3 * (56 + 6) + 3 * (56 + 6) + (48 + 6) + 2 * (64 + 6) + 22 + 28 + 16 + 10));
  // Drawn: the collision mark's red (EGA 4) runs down a column, and the
  // three TCP colours appear.
  const auto count = [&](rs::render::Rgb c) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < d.rgb.size(); i += 3)
      if (d.rgb[i] == c.r && d.rgb[i + 1] == c.g && d.rgb[i + 2] == c.b) ++n;
    return n;
  };
  CHECK(count(rs::render::kEga[4]) > 300);
  CHECK(count(rs::render::kEga[12]) > 50);
  CHECK(count(rs::render::kEga[10]) > 50);
  CHECK(count(rs::render::kEga[9]) > 50);
  const auto wide = runCli({"plot", prog, "--cell", "gantry-cell", "--collisions=off", "--width", "800", "-o",
                            dir.file("w.png")});
  REQUIRE(wide.code == 0);
  const std::string w = readBytes(dir.file("w.png"));
  CHECK(rs::render::decodePng({w.begin(), w.end()})->width == 800);
}

TEST_CASE("the chart's SVG, read by python3's XML parser, has every series and mark where the samples put them",
          "[render][chart][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("graze.rsp", kChartGrazeProgram);
  const auto svg = runCli({"plot", prog, "--cell", "gantry-cell", "--collisions=warn", "-o", dir.file("c.svg")});
  const auto csv = runCli({"plot", prog, "--cell", "gantry-cell", "--collisions=warn", "-o", dir.file("c.csv")});
  REQUIRE(svg.code == 0);
  REQUIRE(csv.code == 0);
  // The collision's moment, as the run's warning says it (to the ms).
  const std::size_t at = svg.err.find("collision at ");
  REQUIRE(at != std::string::npos);
  const std::string seconds = svg.err.substr(at + 13, svg.err.find(' ', at + 13) - at - 13);
  const std::string out = chartPython(fmt::format("{} {} --collision {} --lines 0,2.8,4.675,5.175",
                                                  dir.file("c.svg"), dir.file("c.csv"), seconds));
  INFO(out);
  CHECK(out.find("ok:") != std::string::npos);
  CHECK(out.find("(exit status 0)") != std::string::npos);
  // The checker can fail: a wrong moment for the mark is caught.
  const std::string wrong = chartPython(fmt::format("{} {} --collision 1.5 --lines 0,2.8,4.675,5.175",
                                                    dir.file("c.svg"), dir.file("c.csv")));
  INFO(wrong);
  CHECK(wrong.find("(exit status 0)") == std::string::npos);
}

TEST_CASE("plot: the TCP's x, y and z each on its own scale, inputs and outputs bright only while ON",
          "[render][chart][cli]") {
  // The gantry program: x 500 -> 220 and z 400 -> 680 over 2.8 s, then a
  // lowering of only 100 in y (200 -> 100), which one scale for the three
  // (100..680) would squeeze into a sixth of the lane; output 3 ON 2.8 ..
  // 4.75 s, input 2 ON from 3.5 s, the other fourteen lines never.
  const TempDir dir;
  const std::string prog = dir.write("gantry.rsp", kChartGantryProgram);
  for (const char* ext : {"svg", "csv"}) {
    const auto r = runCli({"plot", prog, "--cell", "gantry-cell", "--input", "2=ON@3.5", "-o",
                           dir.file(std::string("io.") + ext)});
    INFO(r.err);
    REQUIRE(r.code == 0);
  }
  const std::string out = chartPython(fmt::format("{} {} --lines 0,2.8,3.5,4.75,5.25", dir.file("io.svg"), dir.file("io.csv")));
  INFO(out);
  CHECK(out.find("ok:") != std::string::npos);
  CHECK(out.find("(exit status 0)") != std::string::npos);
  // The chart itself: a lane per coordinate, each with its one series.
  const ChartRun c(kChartGantryProgram, rs::runtime::CollisionMode::Off);
  std::vector<std::string> tcpLanes;
  for (const rs::render::ChartLane& lane : c.chart.lanes)
    if (lane.kind == rs::render::LaneKind::Tcp) {
      tcpLanes.push_back(lane.label);
      REQUIRE(lane.series.size() == 1);
      CHECK(c.chart.series[lane.series[0]].column == std::string("tcp_") + "xyz"[lane.axis]);
    }
  CHECK(tcpLanes == std::vector<std::string>{"TCP x", "TCP y", "TCP z"});
}

TEST_CASE("plot refuses bad input with a clear error and writes nothing", "[render][chart][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("ok.rsp", kChartGrazeProgram);
  const auto refused = [&](std::vector<std::string> args, const std::string& message) {
    args.insert(args.begin(), "plot");
    const auto r = runCli(args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(message) != std::string::npos);
  };
  refused({prog, "--cell", "gantry-cell"}, "give -o FILE.svg, FILE.png or FILE.csv");
  refused({prog, "--cell", "gantry-cell", "-o", dir.file("x.txt")}, "must end in .svg, .png or .csv");
  refused({prog, "--cell", "gantry-cell", "-o", dir.file("x.svg"), "--format=png"}, "names a .svg file but --format is png");
  refused({prog, "--cell", "gantry-cell", "--format=svg"}, "--format=svg needs -o FILE");
  refused({prog, "--cell", "gantry-cell", "--format=pdf"}, "--format");
  refused({prog, "--cell", "gantry-cell", "--every", "0", "-o", dir.file("x.csv")}, "--every: error: the interval must be above 0");
  refused({prog, "--cell", "gantry-cell", "--every", "abc", "-o", dir.file("x.csv")}, "--every");
  refused({prog, "--cell", "gantry-cell", "--every", "0.000001", "-o", dir.file("x.csv")}, "makes more than 1000000 samples");
  refused({prog, "--cell", "gantry-cell", "--width", "10", "-o", dir.file("x.svg")}, "--width");
  refused({prog, "--cell", "no-such-cell", "-o", dir.file("x.svg")}, "no-such-cell");
  refused({prog, "--cell", "gantry-cell", "-o", dir.file("missing/dir/x.svg")}, "cannot write");
  const std::string bad = dir.write("bad.rsp", "MOVETO 1 2\nEND\n");
  refused({bad, "--cell", "gantry-cell", "-o", dir.file("x.svg")}, "bad.rsp:1:1: error:");
  for (const char* name : {"x.txt", "x.svg", "x.csv", "x.png"}) CHECK(!std::filesystem::exists(dir.file(name)));
  // A run that fails is still plotted: exit 1, the diagnostic, the file.
  const auto failed = runCli({"plot", prog, "--cell", "gantry-cell", "-o", dir.file("stopped.svg")});
  CHECK(failed.code == 1);
  CHECK(failed.err.find("collision") != std::string::npos);
  CHECK(std::filesystem::exists(dir.file("stopped.svg")));
}

TEST_CASE("animate puts the run's chart under the scrub bar", "[render][chart][cli]") {
  const TempDir dir;
  const auto r = runCli({"animate", rendertest::kSourceDir + "/examples/gantry_pick.rsp", "--cell", "gantry-cell", "-o",
                         dir.file("run.html")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string html = readBytes(dir.file("run.html"));
  CHECK(html.find("id=\"chart\"") != std::string::npos);
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t a = html.find(open), b = html.find("</script>", a);
  REQUIRE(a != std::string::npos);
  const auto model = nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
  REQUIRE(model.contains("chart"));
  const auto& chart = model["chart"];
  CHECK(chart["width"] == rs::render::kChartWidth);
  CHECK(chart["end"] == model["run"]["end"]);
  CHECK(chart["left"].get<double>() < chart["right"].get<double>());
  CHECK(chart["right"].get<double>() <= chart["width"].get<double>());
  CHECK(chart["svg"].get<std::string>().rfind("<?xml", 0) == 0);
  // The page's chart is plot's: the same picture for the same run.
  const auto plot = runCli({"plot", rendertest::kSourceDir + "/examples/gantry_pick.rsp", "--cell", "gantry-cell",
                            "-o", dir.file("run.svg")});
  REQUIRE(plot.code == 0);
  CHECK(chart["svg"].get<std::string>() == readBytes(dir.file("run.svg")));
}
