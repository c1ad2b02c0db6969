// The tool centre point's path (runtime/render/tool_path.h): `render
// --program P --path` draws it, and the animation page carries it, so that
// a student sees the straight line a MOVES makes beside the curve of a
// MOVEP between the same two points. Checked against the camera formula of
// docs/render.md worked out here with plain matrices, the points' own
// coordinates, `robotsim where` for home, and the exact path sampled densely
// through the run's log.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include "model/workcell/tool_tracker.h"
#include "render_test_util.h"
#include "runtime/render/draw.h"
#include "runtime/render/palette.h"
#include "runtime/render/tool_path.h"

using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

namespace {

// On xr4-cell: a joint move to A, a joint move to B, and a straight line
// back to A. A and B are the points' own coordinates (inverse kinematics
// rounds them to whole counts: `robotsim ik` says within 0.13 of them).
const std::string kPathProgram =
    "        MOVEP   A\n"
    "        MOVEP   B\n"
    "        MOVES   A\n"
    "        END\n"
    "POINTS\n"
    "A       AT 240 870 -40 APPROACH 0 -1 0 GRIP 0\n"
    "B       AT 0 900 250 APPROACH 0 -1 0 GRIP 0\n";
const Eigen::Vector3d kPathA(240, 870, -40), kPathB(0, 900, 250);

// docs/render.md's camera formula from a --dump-lines=json picture's camera
// and fit: r = Rx·Ry·Rz·(p + window − center), u = W/2 + s·r.x, v = H/2 − s·r.y.
struct PathCamera {
  Eigen::Matrix3d R;
  Eigen::Vector3d shift;
  double s = 1, w = 0, h = 0;
  explicit PathCamera(const nlohmann::json& picture) {
    const auto& cam = picture["camera"];
    const double deg = M_PI / 180;
    const double x = cam["view"][0].get<double>() * deg, y = cam["view"][1].get<double>() * deg,
                 z = cam["view"][2].get<double>() * deg;
    Eigen::Matrix3d Rx, Ry, Rz;
    Rx << 1, 0, 0, 0, std::cos(x), -std::sin(x), 0, std::sin(x), std::cos(x);
    Ry << std::cos(y), 0, std::sin(y), 0, 1, 0, -std::sin(y), 0, std::cos(y);
    Rz << std::cos(z), -std::sin(z), 0, std::sin(z), std::cos(z), 0, 0, 0, 1;
    R = Rx * Ry * Rz;
    for (int i = 0; i < 3; ++i)
      shift[i] = cam["window"][i].get<double>() - picture["fit"]["center"][i].get<double>();
    w = picture["width"].get<double>(), h = picture["height"].get<double>();
    s = cam["zoom"].get<double>() * 0.45 * std::min(w, h) / picture["fit"]["radius"].get<double>();
  }
  Eigen::Vector2d operator()(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d r = R * (p + shift);
    return {w / 2 + s * r.x(), h / 2 - s * r.y()};
  }
};

double toSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

Eigen::Vector2d vertex(const nlohmann::json& v) { return {v[0].get<double>(), v[1].get<double>()}; }

// The pixels of EGA colour `c` in a PNG.
std::size_t pathPixels(const std::string& png, rs::render::Rgb c) {
  const auto decoded = rs::render::decodePng({png.begin(), png.end()});
  REQUIRE(decoded);
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < decoded->rgb.size(); i += 3)
    n += decoded->rgb[i] == c.r && decoded->rgb[i + 1] == c.g && decoded->rgb[i + 2] == c.b;
  return n;
}

}  // namespace

TEST_CASE("render --path: a MOVES line beside the curve of a MOVEP between the same points",
          "[render][path][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("path.rsp", kPathProgram);
  // Zoomed in on the two points (the dump's fit is the zoomed one).
  const std::vector<std::string> camera{"--zoom", "2.5", "--center", "100,900,100"};
  std::vector<std::string> args{"render", "xr4-cell", "--program", prog, "--path", "--dump-lines=json", "-o",
                                dir.file("path.png")};
  args.insert(args.end(), camera.begin(), camera.end());
  const auto r = runCli(args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json picture = nlohmann::json::parse(r.out);
  REQUIRE(picture.contains("path"));
  REQUIRE(picture["path"].size() == 1);  // one stretch: nothing jumped
  const nlohmann::json& path = picture["path"][0];
  REQUIRE(path.size() > 10);
  const PathCamera project(picture);

  // It starts where `robotsim where` puts the tool at home, and ends at the
  // tool mark, at A.
  const auto home = runCli({"where", "xr4-cell", "--encoders", "0,0,0,0,0,0", "--json"});
  REQUIRE(home.code == 0);
  const auto tcp = nlohmann::json::parse(home.out)["position"];
  const Eigen::Vector2d start = project({tcp[0].get<double>(), tcp[1].get<double>(), tcp[2].get<double>()});
  CHECK((vertex(path.front()) - start).norm() < 1e-6);
  CHECK((vertex(path.back()) - vertex(picture["tools"][0]["at"])).norm() < 1e-9);
  const Eigen::Vector2d a = project(kPathA), b = project(kPathB);
  CHECK((vertex(path.back()) - a).norm() < 0.5);

  // The vertex at B, and the first at A (the end of the first MOVEP).
  std::size_t atB = 0, atA = 0;
  for (std::size_t i = 0; i < path.size(); ++i)
    if ((vertex(path[i]) - b).norm() < (vertex(path[atB]) - b).norm()) atB = i;
  for (std::size_t i = 0; i < atB; ++i)
    if ((vertex(path[i]) - a).norm() < (vertex(path[atA]) - a).norm()) atA = i;
  CHECK((vertex(path[atB]) - b).norm() < 0.5);
  CHECK((vertex(path[atA]) - a).norm() < 0.5);
  REQUIRE(atA < atB);
  // MOVEP A -> B: a curve, far from the straight line between its ends.
  double bow = 0;
  for (std::size_t i = atA; i <= atB; ++i) bow = std::max(bow, toSegment(vertex(path[i]), a, b));
  CHECK(bow > 20);
  CHECK(atB - atA > 5);  // drawn as a curve, not as a chord
  // MOVES B -> A: on the straight line, within the rounding of its knots.
  for (std::size_t i = atB; i < path.size(); ++i) {
    INFO("vertex " << i);
    CHECK(toSegment(vertex(path[i]), a, b) < 0.5);
  }

  // Drawn in cyan, which the cell has nowhere else.
  CHECK(pathPixels(readBytes(dir.file("path.png")), rs::render::rgb(rs::render::kPathColor)) > 200);
  std::vector<std::string> plainArgs{"render", "xr4-cell", "--program", prog, "-o", dir.file("plain.png")};
  plainArgs.insert(plainArgs.end(), camera.begin(), camera.end());
  const auto plain = runCli(plainArgs);
  REQUIRE(plain.code == 0);
  CHECK(pathPixels(readBytes(dir.file("plain.png")), rs::render::rgb(rs::render::kPathColor)) == 0);
  const auto text = runCli({"render", "xr4-cell", "--program", prog, "--path", "--dump-lines"});
  CHECK(text.out.find("\npath 0 ") != std::string::npos);
}

TEST_CASE("render --path --at: the path up to the moment drawn, ending at the tool", "[render][path][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("path.rsp", kPathProgram);
  const auto whole = runCli({"render", "xr4-cell", "--program", prog, "--path", "--dump-lines=json"});
  const auto part = runCli({"render", "xr4-cell", "--program", prog, "--path", "--at", "3", "--dump-lines=json"});
  REQUIRE(whole.code == 0);
  REQUIRE(part.code == 0);
  const nlohmann::json w = nlohmann::json::parse(whole.out), p = nlohmann::json::parse(part.out);
  const nlohmann::json& upTo = p["path"][0];
  CHECK(upTo.size() < w["path"][0].size());
  CHECK((vertex(upTo.back()) - vertex(p["tools"][0]["at"])).norm() < 1e-9);
  // Every vertex but the last (the tool at 3 s, in the middle of MOVEP B) is the whole path's.
  for (std::size_t i = 0; i + 1 < upTo.size(); ++i) CHECK((vertex(upTo[i]) - vertex(w["path"][0][i])).norm() < 1e-9);
  // Without --program there is no path to draw.
  const auto refused = runCli({"render", "xr4-cell", "--path", "-o", dir.file("x.png")});
  CHECK(refused.code == 2);
  CHECK(refused.err.find("--path needs --program") != std::string::npos);
}

TEST_CASE("toolPathOf: within its tolerance where every move starts and ends, and broken at a RESET", "[render][path]") {
  SECTION("where every move starts and ends, the tool is within the tolerance of the path") {
    // Between those moments the motors step count by count, each at its own
    // time, so the tool's own path zig-zags by up to a count's worth about
    // the line the path draws (on this arm about 0.9 at most).
    const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
    const rs::vm::Image image = rendertest::compileText(kPathProgram, cell);
    const auto run = rendertest::runOf(image, &cell, {}, /*log=*/true);
    REQUIRE(run->runToEnd().ok());
    const rs::runtime::RunLog& log = *run->log();
    const double tolerance = 0.5;
    const std::vector<rs::render::PathPoint> path = rs::render::toolPathOf(log, *cell.drivenRobot(), tolerance);
    REQUIRE(path.size() >= 2);
    for (std::size_t i = 1; i < path.size(); ++i) CHECK(path[i].at >= path[i - 1].at);
    CHECK(path.back().at == log.end);
    std::vector<rs::vm::Micros> moments;
    std::size_t moves = 0;
    for (const auto& list : log.moves)
      for (const rs::runtime::MotorMove& m : list) moments.push_back(m.start), moments.push_back(m.end), ++moves;
    std::sort(moments.begin(), moments.end());
    moments.erase(std::unique(moments.begin(), moments.end()), moments.end());
    REQUIRE(moments.size() > 100);
    rs::workcell::ToolTracker tracker(*cell.drivenRobot());
    double worst = 0;
    for (const rs::vm::Micros t : moments) {
      const std::array<double, 3> q = tracker.tcp(rs::runtime::stateAt(log, t).encoders);
      const Eigen::Vector3d exact(q[0], q[1], q[2]);
      // The segments of the path around t: a point left out lies between the two kept around it.
      const auto after = std::lower_bound(path.begin(), path.end(), t,
                                          [](const rs::render::PathPoint& p, rs::vm::Micros v) { return p.at < v; });
      const std::size_t k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - path.begin() - 1, 0));
      double nearest = INFINITY;
      for (std::size_t j = k; j + 1 < path.size() && j <= k + 1; ++j) {
        const Eigen::Vector3d ab = path[j + 1].p - path[j].p;
        const double s = ab.squaredNorm() > 0 ? std::clamp((exact - path[j].p).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0;
        nearest = std::min(nearest, (exact - (path[j].p + s * ab)).norm());
      }
      worst = std::max(worst, nearest);
    }
    CHECK(worst <= tolerance + 1e-9);
    // Thinned: far fewer points than the run's moves.
    CHECK(path.size() * 4 < moves);
  }
  SECTION("a RESET jumps: the path is broken there") {
    // gantry-cell: the tool centre point at (500 + X/10, 200 - Y/10, 400 + Z/10), X and Z at 1000 counts/s.
    const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
    const rs::vm::Image image = rendertest::compileText("MOVE 1000 0 0 0\nRESET\nMOVE 0 1000 0 0\nEND\n", cell);
    const auto run = rendertest::runOf(image, &cell, {}, /*log=*/true, rs::runtime::CollisionMode::Off);
    REQUIRE(run->runToEnd().ok());
    const std::vector<rs::render::PathPoint> path = rs::render::toolPathOf(*run->log(), *cell.drivenRobot(), 0.01);
    // Out along x to (600, 200, 400) by 1 s, back home at once, along z to (500, 200, 500) by 2 s.
    const auto jump = std::find_if(path.begin(), path.end(), [](const rs::render::PathPoint& p) { return p.jump; });
    REQUIRE(jump != path.end());
    REQUIRE(jump != path.begin());
    CHECK(std::count_if(path.begin(), path.end(), [](const rs::render::PathPoint& p) { return p.jump; }) == 1);
    CHECK(jump->at == 1'000'000);
    CHECK((jump->p - Eigen::Vector3d(500, 200, 400)).norm() < 1e-9);
    CHECK(((jump - 1)->p - Eigen::Vector3d(600, 200, 400)).norm() < 1e-9);
    CHECK((path.front().p - Eigen::Vector3d(500, 200, 400)).norm() < 1e-9);
    CHECK((path.back().p - Eigen::Vector3d(500, 200, 500)).norm() < 1e-9);
    for (auto p = path.begin(); p != path.end(); ++p) {
      const bool out = p < jump;
      CHECK(p->p.y() == Approx(200).margin(1e-9));
      CHECK((out ? p->p.z() : p->p.x()) == Approx(out ? 400 : 500).margin(1e-9));
    }
    // A straight move keeps few of its 250 pieces.
    CHECK(path.size() < 20);
  }
}

TEST_CASE("animate: the page carries the tool's path from home to the run's end", "[render][path][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("path.rsp", kPathProgram);
  const auto r = runCli({"animate", prog, "--cell", "xr4-cell", "-o", dir.file("run.html")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string html = readBytes(dir.file("run.html"));
  CHECK(html.find("id=\"path\" checked") != std::string::npos);  // the page's "path" box, ticked
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t a = html.find(open), b = html.find("</script>", a);
  REQUIRE(a != std::string::npos);
  const auto model = nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
  REQUIRE(model.contains("path"));
  const auto& path = model["path"];
  const std::size_t n = path["at"].size();
  REQUIRE(n > 10);
  REQUIRE(path["pts"].size() == 3 * n);
  CHECK(path["jump"].empty());
  CHECK(path["at"][0] == 0);
  CHECK(path["at"][n - 1] == model["run"]["end"]);
  const Eigen::Vector3d last(path["pts"][3 * n - 3].get<double>(), path["pts"][3 * n - 2].get<double>(),
                             path["pts"][3 * n - 1].get<double>());
  CHECK((last - kPathA).norm() < 0.2);  // MOVES A ends at A's counts, within the rounding
  CHECK(model["style"]["pathColor"] == static_cast<int>(rs::render::kPathColor));
}
