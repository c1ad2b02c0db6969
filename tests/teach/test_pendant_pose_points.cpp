// The pendant over points written as tool poses (docs/teach.md, "Points
// written as tool poses"): go to takes the arm where MOVEP takes it, the
// gripper left alone where the point writes no GRIP; re-teach asks pose or
// counts. On xr4-cell, the tool pointing down over its front block
// (x 220..260, z -60..-20). Every pose is checked with `robotsim where`
// (forward kinematics from the counts, no inverse kinematics).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "../render/render_test_util.h"
#include "base/file_io.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/commands.h"
#include "tools/teach/pendant.h"
#include "tools/teach/tui/tui_session.h"

namespace {

using rs::teach::Pendant;
using PoseValues = std::vector<std::int32_t>;

const std::string kPoseProgram =
    "; cell: xr4-cell\n"
    "        MOVEP ABOVE\n"
    "        MOVEP UP\n"
    "        END\n"
    "POINTS\n"
    "ABOVE   AT 240 870 -40 APPROACH 0 -1 0 GRIP 0\n"
    "UP      AT 240 900 -40          ; lifted, the gripper as it is\n"
    "HOME    0 0 0 0 0 0\n";

struct PoseFixture {
  PoseFixture()
      : path(dir.write("pose.rsp", kPoseProgram)),
        cell(std::make_shared<const rs::workcell::Workcell>(rendertest::cell("xr4-cell"))) {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
  }
  std::string text() const { return *rs::base::readFile(path, 1 << 20).bytes; }
  rs::testing::TempDir dir;
  std::string path;
  std::shared_ptr<const rs::workcell::Workcell> cell;
  std::unique_ptr<Pendant> pendant;
};

// `robotsim where` at counts: the tool centre point and the approach.
std::pair<Eigen::Vector3d, Eigen::Vector3d> toolAt(const PoseValues& counts) {
  std::string list;
  for (std::size_t i = 0; i < counts.size(); ++i) list += (i ? "," : "") + std::to_string(counts[i]);
  const auto r = rs::testing::runCli({"where", "xr4-cell", "--encoders", list, "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  Eigen::Vector3d p, a;
  for (int i = 0; i < 3; ++i) {
    p[i] = j["position"][static_cast<std::size_t>(i)].get<double>();
    a[i] = j["matrix"][static_cast<std::size_t>(i)][2].get<double>();
  }
  return {p, a};
}

// The line of `text` that starts with `name`.
std::string pointRow(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(name + " ", 0) == 0) return line;
  return {};
}

constexpr std::size_t kXr4Gripper = 5;

}  // namespace

TEST_CASE("go to a point written as a tool pose goes where MOVEP goes, the gripper as it is", "[teach][pose]") {
  PoseFixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.state().points.size() == 3);
  CHECK(p.state().points[1].pose);
  CHECK_FALSE(p.state().points[2].pose);
  // Close the gripper (on nothing) first: UP writes no GRIP, so it stays closed.
  REQUIRE(p.goTo("HOME").ok);
  REQUIRE(p.gripper(true).ok);
  const rs::teach::Outcome up = p.goTo("UP");
  INFO(up.message);
  REQUIRE(up.ok);
  CHECK(up.message.rfind("went to UP (", 0) == 0);
  const PoseValues at = p.state().encoders;
  CHECK(at[kXr4Gripper] == 115);
  const auto [tcp, approach] = toolAt(at);
  CHECK((tcp - Eigen::Vector3d(240, 900, -40)).norm() < 1.5);  // 0.1 degree a count, about a unit at this reach
  CHECK((approach - Eigen::Vector3d(0, -1, 0)).norm() < 0.01);  // kept from ABOVE, the row above it
  // Where the program's MOVEP UP goes: the same counts, the arm's joints (the gripper is the run's).
  const rs::vm::Image image = rendertest::compileText(kPoseProgram, *f.cell);
  for (std::size_t m = 0; m < kXr4Gripper; ++m) CHECK(at[m] == image.points[1].values[m]);
  // ABOVE writes GRIP 0: the gripper opens.
  REQUIRE(p.goTo("ABOVE").ok);
  CHECK(p.state().encoders[kXr4Gripper] == 0);
}

TEST_CASE("go to a pose point the arm cannot take is refused in the compiler's words, with the file's line",
          "[teach][pose]") {
  rs::testing::TempDir dir;
  const std::string path = dir.write("far.rsp", "        END\nPOINTS\nNEAR    AT 240 900 -40 APPROACH 0 -1 0\n"
                                                "FAR     AT 2000 900 -40\nBROKEN  AT 1 2\n");
  auto cell = std::make_shared<const rs::workcell::Workcell>(rendertest::cell("xr4-cell"));
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
  REQUIRE(file);
  Pendant p(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
  const PoseValues home = p.state().encoders;
  const rs::teach::Outcome far = p.goTo("FAR");
  INFO(far.message);
  CHECK_FALSE(far.ok);
  CHECK(far.message.rfind("cannot go to FAR: point FAR: the point is ", 0) == 0);
  CHECK(far.message.find("out of the arm's reach") != std::string::npos);
  CHECK(far.message.find("(line 4); nothing moved") != std::string::npos);
  CHECK(p.state().encoders == home);
  // A broken row below it does not stop a point above it.
  const rs::teach::Outcome near = p.goTo("NEAR");
  INFO(near.message);
  CHECK(near.ok);
}

TEST_CASE("re-teach over a pose point asks pose or counts, and writes what it is asked", "[teach][pose]") {
  PoseFixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.goTo("UP").ok);
  REQUIRE(p.jogCartesian(rs::workcell::JogFrame::World, "X", 10).ok);
  const PoseValues here = p.state().encoders;
  const Eigen::Vector3d tcp = toolAt(here).first;
  SECTION("without saying which: a bad request, nothing written") {
    const std::string before = f.text();
    const rs::teach::Outcome o = p.reteach("UP");
    CHECK_FALSE(o.ok);
    CHECK(o.badRequest);
    CHECK(o.message == "point UP is written as a tool pose: re-teach it as a pose or as counts");
    CHECK(f.text() == before);
    const rs::teach::Outcome api = rs::teach::applyCommand(p, nlohmann::json{{"op", "reteach"}, {"name", "UP"}});
    CHECK(api.badRequest);
    CHECK(rs::teach::applyCommand(p, nlohmann::json{{"op", "reteach"}, {"name", "UP"}, {"as", "both"}}).badRequest);
  }
  SECTION("as a pose: AT again, where the tool is, its comment kept, no GRIP; it compiles to these counts") {
    const rs::teach::Outcome o =
        rs::teach::applyCommand(p, nlohmann::json{{"op", "reteach"}, {"name", "UP"}, {"as", "pose"}});
    INFO(o.message);
    REQUIRE(o.ok);
    const std::string row = pointRow(f.text(), "UP");
    INFO(row);
    CHECK(row.rfind("UP      AT ", 0) == 0);
    CHECK(row.find(" APPROACH ") != std::string::npos);
    CHECK(row.find(" NORMAL ") != std::string::npos);
    CHECK(row.find("GRIP") == std::string::npos);
    CHECK(row.find("; lifted, the gripper as it is") != std::string::npos);
    // The numbers written are where the tool is: the jog's exact pose, which the counts round by about a unit.
    std::istringstream words(row.substr(row.find(" AT ") + 4));
    Eigen::Vector3d written;
    words >> written.x() >> written.y() >> written.z();
    CHECK((written - tcp).norm() < 1.0);
    CHECK((written - Eigen::Vector3d(250, 900, -40)).norm() < 1.5);
    // The program still compiles, and UP is the counts the arm stands at.
    const rs::vm::Image image = rendertest::compileText(f.text(), *f.cell);
    for (std::size_t m = 0; m < kXr4Gripper; ++m) CHECK(std::abs(image.points[1].values[m] - here[m]) <= 1);
    CHECK(image.code[1].a == rs::vm::kPointKeepsGripper);  // MOVEP UP leaves the gripper alone still
    // The rest of the file as it was.
    CHECK(pointRow(f.text(), "ABOVE") == "ABOVE   AT 240 870 -40 APPROACH 0 -1 0 GRIP 0");
    CHECK(pointRow(f.text(), "HOME") == "HOME    0 0 0 0 0 0");
  }
  SECTION("as counts: a row of counts laid out like HOME, the comment kept") {
    const rs::teach::Outcome o = p.reteach("UP", Pendant::Reteach::Counts);
    INFO(o.message);
    REQUIRE(o.ok);
    std::string counts;
    for (std::int32_t v : here) counts += " " + std::to_string(v);
    const std::string row = pointRow(f.text(), "UP");
    INFO(row);
    CHECK(row.rfind("UP ", 0) == 0);
    CHECK(row.find(" AT ") == std::string::npos);
    CHECK(row.find("; lifted, the gripper as it is") != std::string::npos);
    CHECK_FALSE(p.state().points[1].pose);
    CHECK(p.state().points[1].values == here);
  }
  SECTION("the terminal pendant asks p or c") {
    rs::teach::tui::TuiSession tui(p);
    REQUIRE(tui.press("PageDown"));  // UP, the second point
    REQUIRE(tui.press("r"));
    bool asked = false;
    for (const std::string& r : tui.screen(80, 24).rows)
      asked = asked || r.find("re-teach UP: p as a pose (AT ...), c as counts") != std::string::npos;
    CHECK(asked);
    REQUIRE(tui.press("p"));
    CHECK(pointRow(f.text(), "UP").rfind("UP      AT ", 0) == 0);
    CHECK(p.state().message.rfind("re-taught UP AT ", 0) == 0);
  }
}
