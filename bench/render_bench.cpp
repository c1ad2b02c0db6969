// render_bench: how long a still of a 5,000-line workcell takes (SVG and a
// 1024x768 PNG), in-process, best and median of N runs; and the files for
// the browser's frame-time bench (tests/browser/frame_bench.mjs).
//
//   render_bench [--smoke] [--reps N] [--workdir DIR]
//
// Writes DIR/bench-cell.rsd (a SCOROBOT-like arm whose five links and
// gripper hold 5,016 lines) and DIR/bench.rsp (ten back-and-forth moves of
// every motor, 60 s simulated). Not a test: it prints numbers
// (docs/render.md).
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_args.h"
#include "compiler/description/library.h"
#include "runtime/render/draw.h"
#include "runtime/render/picture.h"
#include "runtime/render/png.h"

namespace {

using Clock = std::chrono::steady_clock;

// Cubes along a bone from p to q: 12 lines each.
std::string cubes(const std::string& name, const double p[3], const double q[3], int count, double half) {
  std::string text = "LINK " + name + "\n";
  static const char* const kColors[] = {"LIGHTGRAY", "BLUE", "LIGHTBLUE", "LIGHTCYAN", "YELLOW"};
  for (int k = 0; k < count; ++k) {
    const double f = (k + 0.5) / count;
    const double c[3] = {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2])};
    const double h = half * (0.6 + 0.4 * ((k * 7) % 10) / 10.0);
    text += fmt::format("  BOX {:.3f} {:.3f} {:.3f} {:.3f} {:.3f} {:.3f} COLOR {}\n", c[0] - h, c[0] + h, c[1] + h,
                        c[1] - h, c[2] + h, c[2] - h, kColors[k % 5]);
  }
  return text + "END\n\n";
}

std::string benchCell() {
  const double bones[5][2][3] = {{{0, 0, 0}, {0, 0, 1220}},
                                 {{-150, 0, 1220}, {150, 0, 1220}},
                                 {{0, 0, 1220}, {0, 0, 1997}},
                                 {{0, 0, 1997}, {707, 0, 1997}},
                                 {{707, 0, 1997}, {757, 0, 1497}}};
  std::string text = "; bench-cell: 5,016 lines on a SCOROBOT-like arm (written by render_bench)\n\n";
  for (int i = 0; i < 5; ++i) text += cubes(fmt::format("bench_link{}", i), bones[i][0], bones[i][1], 83, 40);
  text += R"(LINK bench_palm
  BOX 717 797 1497 1457 60 -60 COLOR LIGHTGREEN
END
LINK bench_finger_left
  BOX 717 797 1457 1397 -30 -50 COLOR LIGHTGREEN
END
LINK bench_finger_right
  BOX 717 797 1457 1397 50 30 COLOR LIGHTGREEN
END
GRIPPER bench_gripper
  BASE bench_palm  FINGERS bench_finger_left bench_finger_right
  LETTER A  PRECISION 0.5  RANGE 0 40  SPEED 100
  AXIS2 757 -40 1457  857 -40 1457
  AXIS3 757 40 1457  657 40 1457
  NORMAL 757 0 1397  757 -100 1397
  APPROACH 757 0 1397  757 0 1297
END
ROBOT bench_arm
  LINK bench_link0  FRAME ORIGIN 0 0 0       XAXIS 100 0 0      ZAXIS 0 0 100
  LINK bench_link1  FRAME ORIGIN 0 0 1220    XAXIS 100 0 1220   ZAXIS 0 -100 1220
  LINK bench_link2  FRAME ORIGIN 0 0 1997    XAXIS 0 0 2097     ZAXIS 0 -100 1997
  LINK bench_link3  FRAME ORIGIN 707 0 1997  XAXIS 807 0 1997   ZAXIS 707 -100 1997
  LINK bench_link4  FRAME ORIGIN 757 0 1997  XAXIS 857 0 1997   ZAXIS 757 0 1897
  JOINT 1 REVOLUTE  LETTER F  PRECISION 0.1175  RANGE -1000 1000  SPEED 400
  JOINT 2 REVOLUTE  LETTER E  PRECISION 0.1175  RANGE -700 700    SPEED 400
  JOINT 3 REVOLUTE  LETTER D  PRECISION 0.1175  RANGE -900 900    SPEED 400
  JOINT 4 REVOLUTE  LETTER C  PRECISION 0.1175  RANGE -900 900    SPEED 400
  JOINT 5 REVOLUTE  LETTER B  PRECISION 0.1175  RANGE -1500 1500  SPEED 400
  GRIPPER bench_gripper
END
WORKCELL bench-cell
  ROBOT bench_arm AT 0 0 0 ROTATE X -90
END
)";
  return text;
}

const char* const kBenchProgram = R"(; bench.rsp: every motor back and forth ten times (written by render_bench)
        SET N 0
loop:   MOVETO 600 300 -400 500 700 30
        MOVETO -600 -300 400 -500 -700 0
        ADD N 1
        JMPVAR N < 10 loop
        END
)";

double cpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

// Wall and CPU milliseconds, best and median. On a loaded machine the wall
// time includes waiting for a core; the CPU time does not.
struct Stats {
  double best, median, cpuBest, cpuMedian;
};

template <typename F>
Stats time(int reps, F&& f) {
  f();  // warm-up: fonts, caches, allocator
  std::vector<double> ms, cpu;
  for (int i = 0; i < reps; ++i) {
    const auto t0 = Clock::now();
    const double c0 = cpuMs();
    f();
    cpu.push_back(cpuMs() - c0);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  return {ms.front(), ms[ms.size() / 2], cpu.front(), cpu[cpu.size() / 2]};
}

void print(const char* what, const Stats& s, const std::string& extra = {}) {
  fmt::print("  {:<22} {:7.2f} {:7.2f}   {:7.2f} {:7.2f}   {}\n", what, s.best, s.median, s.cpuBest, s.cpuMedian,
             extra);
}

}  // namespace

constexpr const char* kRenderUsage =
    "usage: render_bench [--smoke] [--reps N] [--workdir DIR]\n"
    "A still of a 5,016-line workcell (SVG, 1024x768 PNG), in-process (docs/render.md).\n"
    "  --reps N       runs (best and median printed; default 15, with --smoke 1)\n"
    "  --workdir DIR  where the cell and program for tests/browser/frame_bench.mjs are written\n"
    "                 (default: robotsim-render-bench in the temporary folder)\n"
    "  --smoke        one run: checks that the benchmark runs and prints, measures nothing\n";

int main(int argc, char** argv) {
  std::optional<long> repsGiven;
  bool smoke = false;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "robotsim-render-bench";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      fmt::print("{}", kRenderUsage);
      return 0;
    }
    if (a == "--smoke") {
      smoke = true;
      continue;
    }
    const bool takesValue = a == "--reps" || a == "--workdir";
    if (!takesValue || i + 1 >= argc) {
      fmt::print(stderr, "render_bench: error: {}\n{}",
                 takesValue ? a + " needs a value" : "unknown argument '" + a + "'", kRenderUsage);
      return 2;
    }
    const std::string value = argv[++i];
    if (a == "--workdir") {
      dir = value;
    } else if (!(repsGiven = rs::bench::parseCount(value))) {
      fmt::print(stderr, "render_bench: error: --reps takes a whole number from 1 to {}, not '{}'\n{}",
                 rs::bench::kMaxCount, value, kRenderUsage);
      return 2;
    }
  }
  const int reps = static_cast<int>(repsGiven.value_or(smoke ? 1 : 15));
  std::filesystem::create_directories(dir);
  const auto cellPath = dir / "bench-cell.rsd", programPath = dir / "bench.rsp";
  std::ofstream(cellPath) << benchCell();
  std::ofstream(programPath) << kBenchProgram;

  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const std::optional<rs::workcell::Workcell> cell = library.workcell(cellPath.string());
  if (!cell) {
    for (const auto& d : library.diagnostics()) fmt::print(stderr, "{}\n", d.message);
    return 1;
  }
  rs::render::CellPoser poser(*cell);
  const rs::render::Camera camera;
  const rs::render::Fit fit = rs::render::fitView(poser.homePoints(), camera);
  const std::vector<std::int32_t> pose = {300, -200, 250, 400, -600, 20};
  std::size_t lines = 0, pngBytes = 0, svgBytes = 0;

  const Stats project = time(reps, [&] {
    poser.setEncoders(0, pose);
    lines = rs::render::makePicture(poser, camera, fit, {"bench-cell", 1.0}).lines.size();
  });
  const rs::render::Picture picture = rs::render::makePicture(poser, camera, fit, {"bench-cell", 1.0});
  const Stats png = time(reps, [&] {
    poser.setEncoders(0, pose);
    const rs::render::Picture p = rs::render::makePicture(poser, camera, fit, {"bench-cell", 1.0});
    pngBytes = rs::render::encodePicture(p, rs::render::ImageFormat::Png)->size();
  });
  const Stats svg = time(reps, [&] {
    poser.setEncoders(0, pose);
    const rs::render::Picture p = rs::render::makePicture(poser, camera, fit, {"bench-cell", 1.0});
    svgBytes = rs::render::encodePicture(p, rs::render::ImageFormat::Svg)->size();
  });
  // The PNG encoder alone, on an image of the same size.
  std::vector<std::uint8_t> gray(1024 * 3, 0x10);
  std::size_t encoded = 0;
  const Stats pngOnly = time(reps, [&] {
    encoded = rs::render::encodePng(1024, 768, [&](int y, std::uint8_t* rgb) {
                gray[static_cast<std::size_t>(y)] = 0xFF;  // a little structure per row
                std::copy(gray.begin(), gray.end(), rgb);
              }).size();
  });
  fmt::print("render_bench: {} lines, 1024x768; ms: wall best, median; CPU best, median ({} runs)\n", lines, reps);
  print("pose + project", project);
  print("PNG (pose .. bytes)", png, fmt::format("{} KiB", pngBytes / 1024));
  print("SVG (pose .. bytes)", svg, fmt::format("{} KiB", svgBytes / 1024));
  print("PNG encoder only", pngOnly, fmt::format("{} KiB (background only)", encoded / 1024));
  fmt::print("files for tests/browser/frame_bench.mjs: {} {}\n", cellPath.string(), programPath.string());
  return 0;
}
