// Shapes in descriptions (docs/models.md "LINK and OBJECT — shapes"): BOX
// gives exactly the 12 edges of the documented box, ROTATE and MOVE act on
// what was drawn before them only, colours default as documented. Every
// expected coordinate below was worked out by hand:
//   Rz(90): (x, y, z) -> (-y, x, z);  Rx(90): (x, y, z) -> (x, -z, y);
//   Ry(90): (x, y, z) -> (z, y, -x)   (right-handed, about the global axes).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "compiler/description/description.h"
#include "compiler/description/library.h"
#include "tests/models/models_support.h"

namespace {

using rs::compiler::DescriptionFile;
using rs::diag::Diagnostics;
using rs::diag::SourceFile;
using rs::testing::lines;
using rs::workcell::Color;
using rs::workcell::Segment;

// Endpoints rounded to 1e-9 and ordered, so an edge compares equal whichever
// way it was drawn.
using Edge = std::tuple<std::array<double, 3>, std::array<double, 3>, int>;

std::array<double, 3> rounded(const Eigen::Vector3d& v) {
  std::array<double, 3> r{};
  for (int i = 0; i < 3; ++i) r[static_cast<std::size_t>(i)] = std::round(v[i] * 1e9) / 1e9 + 0.0;
  return r;
}

Edge edge(const Segment& s) {
  auto a = rounded(s.a), b = rounded(s.b);
  if (b < a) std::swap(a, b);
  return {a, b, static_cast<int>(s.color)};
}

Edge edge(std::array<double, 3> a, std::array<double, 3> b, Color c) {
  if (b < a) std::swap(a, b);
  return {a, b, static_cast<int>(c)};
}

std::vector<Edge> sortedEdges(const std::vector<Segment>& segments) {
  std::vector<Edge> e;
  for (const Segment& s : segments) e.push_back(edge(s));
  std::sort(e.begin(), e.end());
  return e;
}

std::vector<Edge> inOrder(const std::vector<Segment>& segments) {
  std::vector<Edge> e;
  for (const Segment& s : segments) e.push_back(edge(s));
  return e;
}

DescriptionFile parseGeometry(const std::string& text) {
  Diagnostics d("g.rsd");
  DescriptionFile f = rs::compiler::parseDescription(std::make_unique<SourceFile>("g.rsd", text), d);
  for (const auto& diag : d.all()) FAIL_CHECK(diag.pos.line << ":" << diag.pos.col << ": " << diag.message);
  return f;
}

}  // namespace

TEST_CASE("geometry: BOX is exactly the 12 edges of the documented box", "[models]") {
  // left -1, right 2, top 3, bottom -4, front 5, back -6:
  // x in {-1, 2}, y in {-4, 3}, z in {-6, 5}.
  const DescriptionFile f = parseGeometry(lines({"LINK b", "  BOX -1 2 3 -4 5 -6 COLOR RED", "END"}));
  REQUIRE(f.links.size() == 1);
  const std::vector<Segment>& s = f.links[0].segments;
  CHECK(s.size() == 12);
  const Color R = Color::Red;
  std::vector<Edge> expected{
      // along x
      edge({-1, -4, -6}, {2, -4, -6}, R), edge({-1, -4, 5}, {2, -4, 5}, R),
      edge({-1, 3, -6}, {2, 3, -6}, R), edge({-1, 3, 5}, {2, 3, 5}, R),
      // along y
      edge({-1, -4, -6}, {-1, 3, -6}, R), edge({-1, -4, 5}, {-1, 3, 5}, R),
      edge({2, -4, -6}, {2, 3, -6}, R), edge({2, -4, 5}, {2, 3, 5}, R),
      // along z
      edge({-1, -4, -6}, {-1, -4, 5}, R), edge({-1, 3, -6}, {-1, 3, 5}, R),
      edge({2, -4, -6}, {2, -4, 5}, R), edge({2, 3, -6}, {2, 3, 5}, R),
  };
  std::sort(expected.begin(), expected.end());
  CHECK(sortedEdges(s) == expected);
}

TEST_CASE("geometry: a flat BOX still has 12 edges, some of them points", "[models]") {
  // top = bottom: a rectangle in the plane y = 0, drawn as 12 segments of
  // which the 4 along y have zero length.
  const DescriptionFile f = parseGeometry(lines({"OBJECT plate", "  BOX 0 10 0 0 5 0", "END"}));
  REQUIRE(f.objects.size() == 1);
  const auto& s = f.objects[0].segments;
  CHECK(s.size() == 12);
  const auto zeroLength = std::count_if(s.begin(), s.end(), [](const Segment& g) { return g.a == g.b; });
  CHECK(zeroLength == 4);
  for (const Segment& g : s) {
    CHECK(g.a.y() == 0.0);
    CHECK(g.b.y() == 0.0);
  }
}

TEST_CASE("geometry: ROTATE and MOVE act on everything drawn before them, nothing after", "[models]") {
  const DescriptionFile f = parseGeometry(lines({
      "LINK a",
      "  LINE 1 2 3  4 5 6",              // s0
      "  ROTATE Z 90",                    // s0 -> (-2, 1, 3) (-5, 4, 6)
      "  LINE 1 0 0  0 0 1 COLOR BLUE",   // s1
      "  MOVE 10 20 30",                  // s0 -> (8, 21, 33) (5, 24, 36); s1 -> (11, 20, 30) (10, 20, 31)
      "  LINE 0 0 0  1 1 1",              // s2
      "  ROTATE X 90",                    // s0 (8,-33,21) (5,-36,24); s1 (11,-30,20) (10,-31,20); s2 (0,0,0) (1,-1,1)
      "  ROTATE Y 90",                    // s0 (21,-33,-8) (24,-36,-5); s1 (20,-30,-11) (20,-31,-10); s2 (1,-1,-1)
      "  LINE 7 7 7  8 8 8",              // s3, untouched
      "END",
  }));
  REQUIRE(f.links.size() == 1);
  const Color W = Color::White;
  CHECK(inOrder(f.links[0].segments) == std::vector<Edge>{
                                            edge({21, -33, -8}, {24, -36, -5}, W),
                                            edge({20, -30, -11}, {20, -31, -10}, Color::Blue),
                                            edge({0, 0, 0}, {1, -1, -1}, W),
                                            edge({7, 7, 7}, {8, 8, 8}, W),
                                        });
}

TEST_CASE("geometry: ROTATE turns a BOX about the global axis through the origin", "[models]") {
  // The unit cube x, y, z in [0, 1] turned by Z 90 is x in [-1, 0], y in
  // [0, 1], z in [0, 1]; then MOVE 5 0 0 puts it at x in [4, 5].
  const DescriptionFile turned = parseGeometry(lines({"OBJECT c", "  BOX 0 1 1 0 1 0", "  ROTATE Z 90", "  MOVE 5 0 0", "END"}));
  const DescriptionFile direct = parseGeometry(lines({"OBJECT c", "  BOX 4 5 1 0 1 0", "END"}));
  REQUIRE(turned.objects.size() == 1);
  REQUIRE(direct.objects.size() == 1);
  CHECK(sortedEdges(turned.objects[0].segments) == sortedEdges(direct.objects[0].segments));
  // A ROTATE with nothing drawn yet changes nothing that follows.
  const DescriptionFile early = parseGeometry(lines({"LINK e", "  ROTATE X 45", "  MOVE 1 1 1", "  LINE 0 0 0 1 0 0", "END"}));
  CHECK(inOrder(early.links[0].segments) == std::vector<Edge>{edge({0, 0, 0}, {1, 0, 0}, Color::White)});
  // Negative angles turn the other way: Z -90 takes (1, 0, 0) to (0, -1, 0).
  const DescriptionFile back = parseGeometry(lines({"LINK n", "  LINE 0 0 0 1 0 0", "  rotate z -90", "END"}));
  CHECK(inOrder(back.links[0].segments) == std::vector<Edge>{edge({0, 0, 0}, {0, -1, 0}, Color::White)});
}

TEST_CASE("geometry: colours default to WHITE and follow COLOR, per-line COLOR wins", "[models]") {
  const DescriptionFile f = parseGeometry(lines({
      "LINK c",
      "  LINE 0 0 0 1 0 0",            // WHITE: the default
      "  COLOR lightred",              // names in any case
      "  LINE 0 0 0 2 0 0",            // LIGHTRED
      "  LINE 0 0 0 3 0 0 COLOR 1",    // BLUE, this line only
      "  LINE 0 0 0 4 0 0",            // LIGHTRED again
      "  COLOR 0",                     // BLACK by number
      "  BOX 0 1 1 0 1 0",             // 12 x BLACK
      "  BOX 0 1 1 0 1 0 COLOR Yellow",  // 12 x YELLOW
      "END",
      "OBJECT o",                      // a new block starts WHITE again
      "  LINE 0 0 0 5 0 0",
      "  COLOR 15",
      "  LINE 0 0 0 6 0 0",
      "END",
  }));
  REQUIRE(f.links.size() == 1);
  REQUIRE(f.objects.size() == 1);
  const auto& s = f.links[0].segments;
  REQUIRE(s.size() == 4 + 24);
  CHECK(s[0].color == Color::White);
  CHECK(s[1].color == Color::LightRed);
  CHECK(s[2].color == Color::Blue);
  CHECK(s[3].color == Color::LightRed);
  for (std::size_t i = 4; i < 16; ++i) CHECK(s[i].color == Color::Black);
  for (std::size_t i = 16; i < 28; ++i) CHECK(s[i].color == Color::Yellow);
  CHECK(f.objects[0].segments[0].color == Color::White);
  CHECK(f.objects[0].segments[1].color == Color::White);
}

TEST_CASE("geometry: the 16 EGA colours by name and by number", "[models]") {
  const std::array<const char*, 16> names{"BLACK",    "BLUE",      "GREEN",      "CYAN",      "RED",      "MAGENTA",
                                          "BROWN",    "LIGHTGRAY", "DARKGRAY",   "LIGHTBLUE", "LIGHTGREEN",
                                          "LIGHTCYAN", "LIGHTRED", "LIGHTMAGENTA", "YELLOW",  "WHITE"};
  for (int i = 0; i < 16; ++i) {
    const auto c = static_cast<Color>(i);
    CHECK(rs::compiler::colorByName(names[static_cast<std::size_t>(i)]) == c);
    CHECK(rs::compiler::colorByName(std::to_string(i)) == c);
    CHECK(rs::compiler::colorName(c) == names[static_cast<std::size_t>(i)]);
  }
  CHECK_FALSE(rs::compiler::colorByName("16"));
  CHECK_FALSE(rs::compiler::colorByName("-1"));
  CHECK_FALSE(rs::compiler::colorByName("GREY"));
  CHECK_FALSE(rs::compiler::colorByName("LIGHT_RED"));
  CHECK(rs::compiler::colorByName("yellow") == Color::Yellow);
}

TEST_CASE("geometry: a robot's links keep their design coordinates, a placed object its shape", "[models]") {
  rs::testing::TempDir dir;
  dir.write("w.rsd", lines({
                         "OBJECT crate",
                         "  BOX 0 10 20 0 30 0 COLOR BROWN",
                         "  ROTATE Y 90",
                         "END",
                         "WORKCELL w",
                         "  OBJECT crate AT 100 0 0",
                         "END",
                     }));
  rs::compiler::Library lib({dir.path()});
  const auto cell = lib.workcell(dir.file("w.rsd"));
  REQUIRE(cell);
  REQUIRE(cell->objects.size() == 1);
  // The box x in [0, 10], y in [0, 20], z in [0, 30] turned by Y 90:
  // x in [0, 30], y in [0, 20], z in [-10, 0].
  const auto& segs = cell->objects[0].shape.segments;
  REQUIRE(segs.size() == 12);
  Eigen::Vector3d lo = segs[0].a, hi = segs[0].a;
  for (const Segment& g : segs)
    for (const Eigen::Vector3d& p : {g.a, g.b}) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  CHECK(lo.isApprox(Eigen::Vector3d(0, 0, -10), 1e-12));
  CHECK((hi - Eigen::Vector3d(30, 20, 0)).norm() < 1e-12);
  for (const Segment& g : segs) CHECK(g.color == Color::Brown);
}

namespace {

// Each statement of a shape block re-parsed alone, so that a test can tell
// the segments of one LINE or BOX from the others.
struct Statement {
  std::string keyword;  // "LINE", "BOX", ...
  std::string text;
  std::vector<Segment> segments;
};

std::vector<std::pair<std::string, std::vector<Statement>>> shapeStatements(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::pair<std::string, std::vector<Statement>>> blocks;
  bool inBlock = false, inShape = false;
  for (std::string line; std::getline(in, line);) {
    const std::string code = line.substr(0, line.find(';'));
    std::istringstream words(code);
    std::string first, name;
    if (!(words >> first)) continue;
    for (char& ch : first) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    if (!inBlock) {
      inBlock = true;
      inShape = first == "LINK" || first == "OBJECT";
      words >> name;
      if (inShape) blocks.push_back({name, {}});
    } else if (first == "END") {
      inBlock = inShape = false;
    } else if (inShape) {
      const DescriptionFile one = parseGeometry(lines({"LINK t", code, "END"}));
      blocks.back().second.push_back({first, code, one.links.empty() ? std::vector<Segment>{} : one.links[0].segments});
    }
  }
  return blocks;
}

}  // namespace

TEST_CASE("geometry: stdlib scorobot's boxes enclose the lines they are drawn around", "[models]") {
  // A BOX is "left right top bottom front back", with y up (bottom..top)
  // and z front/back (docs/models.md). The SCOROBOT file's links are drawn
  // with z up (its D-H frames rise along z: the shoulder at z = 1220), so it
  // turns its boxes up with ROTATE X 90, which (x, y, z) -> (x, -z, y); a
  // link's LINE (its centre line, written after the ROTATE) must then lie
  // inside that link's turned boxes.
  const std::string path = std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/robots/scorobot.rsd";
  for (const auto& [link, statements] : shapeStatements(path)) {
    std::vector<Eigen::Vector3d> corners;
    for (const Statement& s : statements) {
      if (s.keyword == "BOX")
        for (const Segment& g : s.segments) corners.push_back(g.a), corners.push_back(g.b);
      if (s.keyword == "ROTATE") {
        REQUIRE(s.text.find("ROTATE X 90") != std::string::npos);  // the only turn this file uses
        for (Eigen::Vector3d& c : corners) c = Eigen::Vector3d(c.x(), -c.z(), c.y());
      }
    }
    if (corners.empty()) continue;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
    for (const Eigen::Vector3d& c : corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    for (const Statement& s : statements) {
      if (s.keyword != "LINE") continue;
      for (const Segment& g : s.segments)
        for (const Eigen::Vector3d& p : {g.a, g.b}) {
          INFO(link << ": " << s.text << " endpoint (" << p.transpose() << ") outside its boxes (" << lo.transpose()
                    << ") .. (" << hi.transpose() << ")");
          CHECK(((p.array() >= lo.array() - 1e-9).all() && (p.array() <= hi.array() + 1e-9).all()));
        }
    }
  }
}

TEST_CASE("geometry: stdlib scorobot's gripper is drawn at its tool centre point", "[models]") {
  // The TCP is (757, 0, 1397) (the NORMAL and APPROACH start); the palm and
  // fingers must be drawn around it, not 1400 units away.
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  const auto robot = lib.robot("scorobot");
  REQUIRE(robot);
  REQUIRE(robot->hasGripper);
  const Eigen::Vector3d tcp(757, 0, 1397);
  CHECK((robot->gripper.model.F_G_E.translation() - tcp).norm() < 1e-9);
  double nearest = 1e300;
  for (const rs::workcell::Shape* s : {&robot->gripper.base, &robot->gripper.finger2, &robot->gripper.finger3})
    for (const Segment& g : s->segments) nearest = std::min({nearest, (g.a - tcp).norm(), (g.b - tcp).norm()});
  CHECK(nearest < 100);
}
