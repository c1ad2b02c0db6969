// Issue 37: an exported robot "read back by robotsim gives the same table
// and poses". Through the command line, as a user would: `table` and
// `where` of the library robot against the same of its export. It needs
// robotsim's URDF reader (model/urdf/urdf_read.h), so it is compiled once
// that reader is in the tree; until then there is no test, not a test that
// passes. What it assumes of the reader (docs/models.md, "URDF"): lengths
// in millimetres, URDF's z up stood on the y-up cell's y (the inverse of the
// export's turn), `--tip LINK` choosing the chain's end where the tree has
// several leaves (the fingers beside tool0), and the D-H rows of an export,
// whose link frames are D-H frames, derived equal to the robot's.
#if __has_include("model/urdf/urdf_read.h")

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compiler/description/library.h"
#include "tests/cli/cli_support.h"

namespace {

using nlohmann::json;
using rs::testing::runCli;

struct Readback {
  std::string name;
  double mm = 1;       // --mm-per-unit
  bool zUp = false;    // --up z
};

json jsonOf(const std::vector<std::string>& args) {
  const rs::testing::CliResult r = runCli(args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  return json::parse(r.out);
}


// Every library robot exported and read back: its D-H rows compared with
// the description's (`rows`), its tool centre point at random joint values
// (`poses`).
void readBackLibrary(bool rows, bool poses) {
  rs::testing::TempDir dir;
  std::vector<Readback> robots;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/robots"))
    if (e.path().extension() == ".rsd") {
      const std::string name = e.path().stem().string();
      robots.push_back({name, name == "scorobot" || name == "rhino-scara" ? 2.0 : 1.0, name == "scorobot"});
    }
  REQUIRE(robots.size() == 10);
  std::mt19937_64 rng(37);
  for (const Readback& r : robots) {
    INFO("robot " << r.name);
    const std::string file = dir.file(r.name + ".urdf");
    std::vector<std::string> exportArgs{"export", r.name, "--urdf", "-o", file, "--mm-per-unit", fmt::format("{}", r.mm)};
    if (r.zUp) exportArgs.insert(exportArgs.end(), {"--up", "z"});
    REQUIRE(runCli(exportArgs).code == 0);
    // The table: the same rows, lengths in millimetres.
    const json original = jsonOf({"table", r.name, "--json"});
    const json back = jsonOf({"table", file, "--tip", "tool0", "--json"});
    REQUIRE(back["rows"].size() == original["rows"].size());
    for (std::size_t i = 0; i < original["rows"].size(); ++i) CHECK(back["rows"][i]["type"] == original["rows"][i]["type"]);
    for (std::size_t i = 0; rows && i < original["rows"].size(); ++i) {
      const json &a = original["rows"][i], &b = back["rows"][i];
      INFO("row " << i + 1);
      CHECK(b["type"] == a["type"]);
      CHECK(std::abs(std::remainder(b["alpha"].get<double>() - a["alpha"].get<double>(), 360.0)) <= 1e-9);
      CHECK(std::abs(std::remainder(b["theta"].get<double>() - a["theta"].get<double>(), 360.0)) <= 1e-9);
      // Absolute bounds (Approx's default relative epsilon, 1e-5, would allow
      // millimetres' thousandths on a long link).
      CHECK(std::abs(b["a"].get<double>() - r.mm * a["a"].get<double>()) <= 1e-6);
      CHECK(std::abs(b["d"].get<double>() - r.mm * a["d"].get<double>()) <= 1e-6);
    }
    // Poses: the tool centre point at random joint values (degrees, or
    // length units read back as millimetres).
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    const std::optional<rs::workcell::Robot> robot = library.robot(r.name);
    REQUIRE(robot);
    for (int s = 0; poses && s < 20; ++s) {
      std::string theta, thetaBack;
      for (std::size_t j = 0; j < robot->joints.size(); ++j) {
        const rs::workcell::JointSpec& spec = robot->joints[j];
        const double home = robot->chain->joint(static_cast<int>(j + 1)).home;
        const double q = home + spec.precision * std::uniform_int_distribution<int>(spec.min, spec.max)(rng);
        const bool length = spec.type == rs::kinematics::JointType::Prismatic;
        // The same motion from home: home is the D-H row's own value at
        // encoder 0, which the export's zero pose is (each table says it).
        const double homeBack = back["rows"][j]["home"].get<double>();
        const double moved = q - home;
        theta += fmt::format("{}{}", j ? "," : "", q);
        thetaBack += fmt::format("{}{}", j ? "," : "", homeBack + (length ? moved * r.mm : moved));
      }
      const json a = jsonOf({"where", r.name, "--theta", theta, "--json"});
      const json b = jsonOf({"where", file, "--tip", "tool0", "--theta", thetaBack, "--json"});
      Eigen::Vector3d pa(a["position"][0], a["position"][1], a["position"][2]);
      const Eigen::Vector3d pb(b["position"][0], b["position"][1], b["position"][2]);
      // A z-up drawing exported unturned comes back stood on y: (x, y, z) -> (x, z, -y).
      if (r.zUp) pa = Eigen::Vector3d(pa.x(), pa.z(), -pa.y());
      CHECK((pb - r.mm * pa).norm() < 1e-6);
    }
  }
}

}  // namespace

TEST_CASE("urdf read-back: every library robot's export gives the same tool poses", "[urdf]") {
  readBackLibrary(false, true);
}

// The D-H rows, strictly: the reader keeps the export's link frames, which
// are D-H frames (model/urdf/urdf_dh.h), so the rows come back as the
// description's own, not as another choice of D-H's freedoms. The bounds:
// θ and α to 1e-9 degrees, a and d to 1e-6 mm times the unit. What can
// differ is only the file's rounding: lengths written as the shortest
// decimal of their metres (a relative 1e-16, 1e-13 mm on a metre's arm)
// and rotations as roll, pitch and yaw (1e-15 radians, 1e-13 degrees).
// Each bound is a thousand times or more above that and far below any
// real difference (a turned x_i moves θ by 180 degrees; a d moved along a
// parallel axis moves it by a link's offset, millimetres).
TEST_CASE("urdf read-back: every library robot's export gives the same D-H rows", "[urdf]") {
  readBackLibrary(true, false);
}

#endif
