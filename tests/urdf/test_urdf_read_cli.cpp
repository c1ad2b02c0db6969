// URDF files wherever a robot is named: table (with its base and tool
// transforms), describe, where, a WORKCELL's ROBOT line, convert (whose
// description gives the same table, matrices and poses), ik and bad input,
// through the whole command (docs/models.md, "Reading URDF").
#include <catch2/catch.hpp>

#include <random>

#include "tests/cli/cli_support.h"
#include "tests/urdf/urdf_read_test_util.h"

namespace {

using rs::testing::runCli;
using Json = nlohmann::json;

std::string data(const std::string& name) { return urdftest::dataRead(name).string(); }

Json jsonOf(const rs::testing::CliResult& r) {
  INFO(r.err);
  REQUIRE(r.code == 0);
  return Json::parse(r.out);
}

}  // namespace

TEST_CASE("urdf cli: table of a URDF file, with where it came from and its base and tool transforms", "[urdf]") {
  const auto text = runCli({"table", data("mixed_arm.urdf")});
  INFO(text.err);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("from URDF file") != std::string::npos);
  CHECK(text.out.find("chain from link base to link tip") != std::string::npos);
  CHECK(text.out.find("BASE:") != std::string::npos);
  CHECK(text.out.find("TOOL:") != std::string::npos);
  const Json j = jsonOf(runCli({"table", data("mixed_arm.urdf"), "--json"}));
  CHECK(j["urdf"]["root"] == "base");
  CHECK(j["urdf"]["tip"] == "tip");
  REQUIRE(j["rows"].size() == 3);
  CHECK(j["rows"][1]["case"] == "skew");
  CHECK(j["tool"].size() == 4);
  CHECK(j["base"].size() == 4);
}

TEST_CASE("urdf cli: describe says the URDF file, root and tip links", "[urdf]") {
  const auto r = runCli({"describe", data("ur5_dh.urdf")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("from URDF file " + data("ur5_dh.urdf") + ": the chain from root link base_link to tip link tool0") !=
        std::string::npos);
}

TEST_CASE("urdf cli: convert writes a description with the same table, matrices and poses", "[urdf]") {
  rs::testing::TempDir dir;
  for (const char* file : {"ur5_dh.urdf", "mixed_arm.urdf", "mimic_arm.urdf"}) {
    INFO(file);
    const std::string rsd = (dir.path() / (std::string(file) + ".rsd")).string();
    const auto converted = runCli({"convert", data(file), "-o", rsd});
    INFO(converted.err);
    REQUIRE(converted.code == 0);
    const Json a = jsonOf(runCli({"table", data(file), "--json"})), b = jsonOf(runCli({"table", rsd, "--json"}));
    REQUIRE(a["rows"].size() == b["rows"].size());
    for (std::size_t i = 0; i < a["rows"].size(); ++i)
      for (const char* k : {"theta", "alpha", "a", "d", "home"})
        CHECK(a["rows"][i][k].get<double>() == Approx(b["rows"][i][k].get<double>()).margin(1e-9));
    const int n = static_cast<int>(a["rows"].size());
    std::mt19937 random(1);
    for (int sample = 0; sample < 5; ++sample) {
      std::string encoders;
      for (int i = 0; i < n; ++i) encoders += (i ? "," : "") + std::to_string(static_cast<int>(random() % 2001) - 1000);
      if (std::string(file) == "mimic_arm.urdf") encoders = encoders.substr(0, encoders.rfind(',')) + ",0";
      const Json wa = jsonOf(runCli({"where", data(file), "--encoders", encoders, "--json"}));
      const Json wb = jsonOf(runCli({"where", rsd, "--encoders", encoders, "--json"}));
      for (int k = 0; k < 3; ++k) CHECK(wa["position"][k].get<double>() == Approx(wb["position"][k].get<double>()).margin(1e-9));
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
          CHECK(wa["matrix"][r][c].get<double>() == Approx(wb["matrix"][r][c].get<double>()).margin(1e-9));
      const Json ma = jsonOf(runCli({"matrix", data(file), "0", std::to_string(n), "--encoders", encoders, "--json"}));
      const Json mb = jsonOf(runCli({"matrix", rsd, "0", std::to_string(n), "--encoders", encoders, "--json"}));
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
          CHECK(ma["matrix"][r][c].get<double>() == Approx(mb["matrix"][r][c].get<double>()).margin(1e-9));
    }
  }
}

TEST_CASE("urdf cli: a WORKCELL's ROBOT x.urdf, named relative to the cell, its root link at AT", "[urdf]") {
  rs::testing::TempDir dir;
  std::filesystem::copy_file(data("ur5_dh.urdf"), dir.path() / "ur5_dh.urdf");
  const std::string cell = (dir.path() / "cell.rsd").string();
  {
    std::ofstream out(cell);
    out << "WORKCELL ur5_cell\n  ROBOT ur5_dh.urdf AT 0 750 0\nEND\n";
  }
  const Json alone = jsonOf(runCli({"where", data("ur5_dh.urdf"), "--json"}));
  const Json placed = jsonOf(runCli({"where", cell, "--json"}));
  CHECK(placed["cell"] == "ur5_cell");
  // By hand: the UR5's flange at home (x = -817.25, y = d1 - d5, z = d4 + d6
  // in mm, y up), lifted by 750.
  CHECK(alone["position"][0].get<double>() == Approx(-817.25).margin(1e-9));
  CHECK(placed["position"][0].get<double>() == Approx(-817.25).margin(1e-9));
  CHECK(placed["position"][1].get<double>() == Approx(750 + 89.159 - 94.65).margin(1e-9));
  CHECK(placed["position"][2].get<double>() == Approx(109.15 + 82.3).margin(1e-9));
}

TEST_CASE("urdf cli: a bad URDF file is a positioned error, exit 2", "[urdf]") {
  const auto r = runCli({"table", data("unknown_type.urdf")});
  CHECK(r.code == 2);
  CHECK(r.err.find(data("unknown_type.urdf") + ":4:3: error: joint 'hinge' has unknown type 'screw'") != std::string::npos);
}

// The "a 100 MB URDF" through the command, as a user meets it: a
// sparse file of 100,000,000 bytes. `table` says why and what to do, exit
// 2; `convert` writes nothing: an earlier description at -o is left as it
// was, and none is made where there was none.
TEST_CASE("urdf cli: a 100 MB URDF file is an error with a hint, exit 2, and convert writes nothing", "[urdf]") {
  rs::testing::TempDir dir;
  const std::string big = dir.write("big.urdf", "<robot name=\"big\">\n");
  std::filesystem::resize_file(big, 100'000'000);
  const auto table = runCli({"table", big});
  CHECK(table.code == 2);
  CHECK(table.out.empty());
  CHECK(table.err.find(big + ": error: the URDF file is 95.4 MiB (100000000 bytes), more than the 64 MiB") !=
        std::string::npos);
  CHECK(table.err.find("  hint: ") != std::string::npos);
  const std::string kept = dir.write("kept.rsd", "; an earlier description\n");
  const auto over = runCli({"convert", big, "-o", kept});
  CHECK(over.code == 2);
  CHECK(over.err.find("95.4 MiB") != std::string::npos);
  CHECK(rs::testing::readBytes(kept) == "; an earlier description\n");
  const std::string fresh = dir.file("fresh.rsd");
  CHECK(runCli({"convert", big, "-o", fresh}).code == 2);
  CHECK_FALSE(std::filesystem::exists(fresh));
  // Nothing else was left in the folder (no temporary file of a write).
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  CHECK(entries == 2);  // big.urdf, kept.rsd
}

TEST_CASE("urdf cli: run a program on a URDF cell - render it - list shows URDF files on the library path", "[urdf]") {
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", "        MOVETO 1000 2000 0 0\n        END\n");
  const auto run = runCli({"run", program, "--cell", data("scara.urdf")});
  INFO(run.err);
  CHECK(run.code == 0);
  // Four motors: the SCARA's (A B C D), as the URDF's four moving joints.
  CHECK(run.out.find("A=1000") != std::string::npos);
  const auto wrong = runCli({"run", dir.write("q.rsp", "        MOVETO 1 2 3\n        END\n"), "--cell", data("scara.urdf")});
  CHECK(wrong.code == 2);
  // A picture of it: its links' lines (a box, a cylinder, a sphere) drawn.
  const std::string svg = (dir.path() / "arm.svg").string();
  const auto render = runCli({"render", data("mixed_arm.urdf"), "-o", svg});
  INFO(render.err);
  CHECK(render.code == 0);
  CHECK(rs::testing::readBytes(svg).find("<path") != std::string::npos);
  std::filesystem::create_directories(dir.path() / "lib" / "robots");
  std::filesystem::copy_file(data("mixed_arm.urdf"), dir.path() / "lib" / "robots" / "mixed_arm.urdf");
  const auto list = runCli({"list", "--lib", (dir.path() / "lib").string()});
  INFO(list.err);
  REQUIRE(list.code == 0);
  CHECK(list.out.find("mixed_arm.urdf") != std::string::npos);
  CHECK(list.out.find("a URDF file, robot mixed_arm.") != std::string::npos);
  // The name list gives finds the file.
  CHECK(runCli({"table", "mixed_arm.urdf", "--lib", (dir.path() / "lib").string()}).code == 0);
}

TEST_CASE("urdf cli: ik uses a closed form where the URDF arm is one of the families, else says none applies", "[urdf]") {
  const auto scara = runCli({"ik", data("scara.urdf"), "--frame", "robot", "--", "526.8", "300", "-176.8"});
  INFO(scara.err);
  CHECK(scara.code == 0);
  CHECK(scara.out.find("POINTS") != std::string::npos);
  const auto ur5 = runCli({"ik", data("ur5_dh.urdf"), "--frame", "robot", "--", "-600", "100", "200"});
  CHECK(ur5.code == 2);
  CHECK(ur5.err.find("no closed-form inverse kinematics applies") != std::string::npos);
}

TEST_CASE("urdf cli: an image compiled for a URDF cell carries its tool frame", "[urdf]") {
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", "        MOVETO 100 200 300\n        END\n");
  const std::string image = (dir.path() / "p.rsb").string();
  const auto compiled = runCli({"compile", program, "--cell", data("mixed_arm.urdf"), "-o", image});
  INFO(compiled.err);
  REQUIRE(compiled.code == 0);
  // The same tool centre point from the image (its cell section, version 2)
  // as from the URDF file.
  const auto fromImage = runCli({"run", image, "--format=json"});
  const auto fromUrdf = runCli({"run", program, "--cell", data("mixed_arm.urdf"), "--format=json"});
  INFO(fromImage.err);
  REQUIRE(fromImage.code == 0);
  REQUIRE(fromUrdf.code == 0);
  const Json a = Json::parse(fromImage.out), b = Json::parse(fromUrdf.out);
  REQUIRE(a.contains("tcp"));
  CHECK(a["tcp"] == b["tcp"]);
}
