// A page and a chart of straight lines are bounded by simulated time and by
// what a screen can show, not by the knots (docs/render.md, "Frames"): a
// 300-unit MOVES of the IRB 120 is hundreds of knots, seven motor moves
// each, and a loop of them logged whole took 1.65 GB for 2,000
// instructions and ended in std::bad_alloc at animate's default limits.
// The log thins a line's knots as it records them (runtime/run/run_log.h,
// LineThinning) and stays exact where it says; the page merges them
// within its slots. Checked: the thinned log against the whole one, and
// `animate` and `plot` of a MOVES loop at the default limits in a child
// process, whose page, frames, moves and peak memory stay under the bounds
// docs/render.md gives.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "render_test_util.h"
#include "tests/support/measured_process.h"
#include "runtime/run/run.h"
#include "runtime/run/run_log.h"
#include "tests/support/build_facts.h"

extern char** environ;

namespace {

// The XR-4 between a point over a block and the grasp below it, forever.
const std::string kXr4Loop =
    "        MOVEP ABOVE\nloop:   MOVES GRASP\n        MOVES ABOVE\n        GOTO loop\nPOINTS\n"
    "ABOVE AT 240 870 -40 APPROACH 0 -1 0\nGRASP AT 240 810 -40 APPROACH 0 -1 0\n";

std::unique_ptr<rs::runtime::Run> loggedLoop(const rs::workcell::Workcell& cell, std::uint64_t steps,
                                             rs::runtime::LineThinning lines) {
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(rendertest::compileText(kXr4Loop, cell));
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.log = true;
  spec.lines = lines;
  spec.limits.maxSteps = steps;
  spec.limits.maxTime = rs::vm::Micros{1'000'000} * 1'000'000;
  auto run = std::make_unique<rs::runtime::Run>(std::move(spec));
  CHECK(run->runToEnd().reason == rs::vm::StopReason::StepLimit);
  return run;
}

std::size_t lineMoves(const rs::runtime::RunLog& log) {
  std::size_t n = 0;
  for (const auto& moves : log.moves)
    for (const rs::runtime::MotorMove& m : moves) n += m.lockStep ? 1 : 0;
  return n;
}

// Every motor of `thin` where the whole log has it: at each multiple of
// the slot and at each step's start and end.
void requireExactWhereItSays(const rs::runtime::RunLog& whole, const rs::runtime::RunLog& thin) {
  REQUIRE(thin.end == whole.end);
  REQUIRE(thin.steps.size() == whole.steps.size());
  std::vector<rs::vm::Micros> times;
  for (rs::vm::Micros t = 0; t <= whole.end; t += thin.lineSlot) times.push_back(t);
  for (const rs::runtime::StepRecord& s : whole.steps) times.push_back(s.start), times.push_back(s.end);
  for (const rs::vm::Micros t : times) {
    INFO("at " << t << " us");
    REQUIRE(rs::runtime::stateAt(thin, t).encoders == rs::runtime::stateAt(whole, t).encoders);
  }
}

struct Child : rstest::Measured {
  std::string out;
};

// this build's robotsim with `args`, its standard output kept (tests/support/measured_process.h).
Child spawnMeasured(std::vector<std::string> args, const rs::testing::TempDir& dir) {
  const std::string out = (dir.path() / "stdout.txt").string();
  Child c{rstest::runMeasured(std::move(args), out, 3), {}};
  c.out = rs::testing::readBytes(out);
  return c;
}

long selfPeakKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// The IRB 120 back and forth along 300 units in front of it, in straight
// lines, forever: at the default limits (1,000,000 instructions, 3,600 s)
// the time limit ends it after about 25,000 instructions and 6 million knots.
std::string writeIrbLoop(const rs::testing::TempDir& dir) {
  return dir.write("loop.rsp",
                   "; cell: irb120-cell\n        MOVEP   A\nLOOP:   MOVES   B\n        MOVES   A\n        GOTO    LOOP\n"
                   "POINTS\nA       AT 300 1000 -150 APPROACH 0 -1 0\nB       AT 300 1000 150 APPROACH 0 -1 0\n");
}

std::uint64_t instructionsIn(const std::string& out) {
  std::smatch m;
  REQUIRE(std::regex_search(out, m, std::regex("\\(([0-9]+) instructions executed")));
  return std::stoull(m[1]);
}

nlohmann::json pageModel(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t from = html.find(open);
  REQUIRE(from != std::string::npos);
  const std::size_t start = from + open.size(), end = html.find("</script>", start);
  REQUIRE(end != std::string::npos);
  return nlohmann::json::parse(html.substr(start, end - start));
}

// docs/render.md, "Frames": what animate and plot hold while they record,
// beyond the process's own 20 MiB: 24 bytes a step, at most 150,000 line
// moves a motor of 32 bytes each (the thinned knots); and animate at most
// 12 bytes of memory a byte of the page it writes.
constexpr long kProcessKiB = 20 * 1024;
long recordingKiB(std::uint64_t steps, std::size_t motors) {
  return static_cast<long>((24 * steps + 150'000 * 32 * motors) / 1024);
}

}  // namespace

TEST_CASE("a log that thins its lines is exact at every multiple of its slot and at each step's ends",
          "[render][straight]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const auto whole = loggedLoop(cell, 1500, {});
  // A slot of its own (plot --every 0.2: the XR-4's knots here are
  // longer than 5 ms, so a slot that short has nothing to merge), and the
  // slot that grows with the run (a power of ten at most 1/5000 of its time).
  const auto fixed = loggedLoop(cell, 1500, {true, 200'000});
  const auto grown = loggedLoop(cell, 1500, {true, 0});
  const rs::runtime::RunLog& all = *whole->log();
  CHECK(all.lineSlot == 1);
  CHECK(fixed->log()->lineSlot == 200'000);
  const rs::vm::Micros slot = grown->log()->lineSlot;
  INFO("the run's " << all.end << " us, its slot " << slot << " us");
  CHECK(slot > 1);
  CHECK(slot <= all.end / rs::runtime::LineThinning::kSlotsPerRun);
  CHECK(slot * 10 > all.end / rs::runtime::LineThinning::kSlotsPerRun);
  for (rs::vm::Micros p = slot; p > 1; p /= 10) CHECK(p % 10 == 0);  // a power of ten
  requireExactWhereItSays(all, *fixed->log());
  requireExactWhereItSays(all, *grown->log());
  // Far fewer moves, within the bound: about three a slot and motor, two a line.
  const std::size_t lines = 1500 * 2 / 3, motors = all.motors.size();
  for (const auto& run : {&fixed, &grown}) {
    const rs::runtime::RunLog& log = *(*run)->log();
    CHECK(lineMoves(log) * 4 < lineMoves(all));
    CHECK(lineMoves(log) <= motors * (3 * static_cast<std::size_t>(log.end / log.lineSlot + 1) + 2 * lines));
  }
}

TEST_CASE("animate of a MOVES loop at the default limits: the page and the memory within docs/render.md's bounds",
          "[render][straight][memory]") {
  const rs::testing::TempDir dir;
  const std::string program = writeIrbLoop(dir);
  const std::string page = (dir.path() / "loop.html").string(), first = (dir.path() / "first.html").string();
  // The page of the first instruction alone: its fixed part (the cell, the
  // listing, the scripts, a chart).
  const Child one = spawnMeasured({"animate", program, "-o", first, "--max-steps", "1"}, dir);
  REQUIRE(WIFEXITED(one.status));
  const std::string fixedPart = rs::testing::readBytes(first);
  REQUIRE(fixedPart.size() > 1000);

  const long before = selfPeakKiB();
  const Child c = spawnMeasured({"animate", program, "-o", page}, dir);
  INFO(c.out);
  REQUIRE(WIFEXITED(c.status));
  CHECK(WEXITSTATUS(c.status) == 1);  // the time limit: the page is written all the same
  const std::string html = rs::testing::readBytes(page);
  REQUIRE(!html.empty());
  const std::uint64_t steps = instructionsIn(c.out);
  CHECK(steps > 20'000);

  const nlohmann::json model = pageModel(html);
  const nlohmann::json& run = model["run"];
  const std::size_t frames = run["index"].size(), motors = run["motors"].size();
  REQUIRE(motors == 7);
  // At most a frame a slot that starts in it, one a step that lasts a
  // slot (their times add up to the run's), and the events (none here).
  constexpr std::size_t kSlots = 20'000;
  CHECK(frames <= 2 * kSlots + 2);
  std::size_t moves = 0;
  for (const nlohmann::json& m : run["moves"]) {
    CHECK(m["step"].size() <= 2 * frames + 2 * kSlots);  // a jump and a move a frame, two line moves a slot
    moves += m["step"].size();
  }
  // 40 bytes a frame, 64 a motor move, a megabyte for the whole run's chart.
  const std::size_t bound = fixedPart.size() + (1u << 20) + 40 * frames + 64 * moves;
  INFO("page " << html.size() << " bytes, bound " << bound << "; " << frames << " frames, " << moves << " moves");
  CHECK(html.size() <= bound);
  CHECK(html.size() < 32u << 20);

  const long memory = kProcessKiB + recordingKiB(steps, motors) + static_cast<long>(12 * html.size() / 1024);
  INFO("peak " << c.peakKiB << " KiB (wait4: " << c.rusageKiB << "), bound " << memory << " KiB");
  CHECK(c.peakKiB > 0);
  CHECK(c.peakKiB <= memory);
  CHECK(c.rusageKiB <= std::max(memory, before));
}

TEST_CASE("plot of a MOVES loop at the default limits: memory within docs/render.md's bound, exact at its samples",
          "[render][straight][memory]") {
  const rs::testing::TempDir dir;
  const std::string program = writeIrbLoop(dir);
  const std::string svg = (dir.path() / "loop.svg").string();
  const long before = selfPeakKiB();
  const Child c = spawnMeasured({"plot", program, "-o", svg}, dir);
  INFO(c.out);
  REQUIRE(WIFEXITED(c.status));
  CHECK(WEXITSTATUS(c.status) == 1);
  const std::string picture = rs::testing::readBytes(svg);
  CHECK(picture.size() > 10'000);
  CHECK(picture.size() < (2u << 20));
  std::smatch m;
  REQUIRE(std::regex_search(c.out, m, std::regex("\\(1200x[0-9]+ pixels, ([0-9]+) samples")));
  const std::uint64_t samples = std::stoull(m[1]);
  CHECK(samples <= 1002);
  // The log's steps (the time limit ends the run at about 25,000), its
  // thinned lines, and the samples (7 motors, the TCP, 16 lines, 8 bytes each).
  const long memory = kProcessKiB + recordingKiB(30'000, 7) + static_cast<long>(samples * 30 * 8 / 1024);
  INFO("peak " << c.peakKiB << " KiB (wait4: " << c.rusageKiB << "), bound " << memory << " KiB");
  CHECK(c.peakKiB > 0);
  CHECK(c.peakKiB <= memory);
  CHECK(c.rusageKiB <= std::max(memory, before));

  // The CSV of a shorter run of the same loop, against the whole log's
  // own answers at each sample (the default interval, and --every).
  const rs::workcell::Workcell cell = rendertest::cell("irb120-cell");
  for (const std::string every : {"", "0.003"}) {
    INFO("--every " << every);
    std::vector<std::string> args{"plot", program, "--format=csv", "--max-steps", "600"};
    if (!every.empty()) args.insert(args.end(), {"--every", every});
    const Child csv = spawnMeasured(args, dir);
    REQUIRE(WIFEXITED(csv.status));
    rs::runtime::RunSpec spec;
    spec.image = std::make_shared<const rs::vm::Image>(rendertest::compile(program, cell));
    spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
    spec.log = true;
    spec.limits.maxSteps = 600;
    rs::runtime::Run whole(std::move(spec));
    whole.runToEnd();
    const rs::runtime::RunLog& log = *whole.log();
    std::istringstream rows(csv.out);
    std::string row;
    std::getline(rows, row);  // the header
    std::size_t checked = 0;
    while (std::getline(rows, row)) {
      std::vector<std::string> cells;
      std::stringstream fields(row);
      for (std::string f; std::getline(fields, f, ',');) cells.push_back(f);
      REQUIRE(cells.size() > 8);
      const std::size_t dot = cells[0].find('.');
      const rs::vm::Micros t = std::stoll(cells[0].substr(0, dot)) * 1'000'000 + std::stoll(cells[0].substr(dot + 1));
      const rs::runtime::RunState state = rs::runtime::stateAt(log, t);
      for (std::size_t k = 0; k < 7; ++k) REQUIRE(std::stoi(cells[1 + k]) == state.encoders[k]);
      ++checked;
    }
    CHECK(checked > 100);
  }
}
