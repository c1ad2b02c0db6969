// A still drawn inside a carried block's collision (issue 26): every part
// in contact at the moment is drawn in the collision colour, read back from
// the SVG, and that colour can be told from the light red of a block.
//
// The cell: the library's gantry over a pallet, block 1 on it, and a wall
// (60 x 70 x 20) standing on the pallet at x 190..250, y 30..100, z
// 730..750. The program takes the block with the tool centre point at
// (220, 51, 680) as examples/gantry_pick.rsp does (2.8 s over it, 1.8625 s
// down, 0.5 s closing), lifts it 10 mm (0.125 s: the block at y 40..80, z
// 660..700, to 5.2875 s), then carries it 40 mm towards +z (Z 400 counts at
// 1000 counts/s: 0.4 s). Its front face reaches the wall at z 730 after
// 30 mm, 5.5875 s; the fingers (z within 15 of the tool centre point, y
// from 41 up) only after 35 mm, 5.6375 s; the palm and the ram are above
// the wall's top. At 5.61 s the block is 2.25 mm into the wall and the
// fingers 2.75 mm short of it: the block and the wall are in contact, and
// nothing else.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/cli/cli_support.h"

using rs::testing::runCli;
using rs::testing::TempDir;

namespace {

constexpr const char* kWallCell = R"(
OBJECT wall
  BOX 0 60 70 0 20 0 COLOR GREEN
END
WORKCELL wall-cell
  ROBOT gantry   AT 0 1000 0
  OBJECT pallet  AT 150 0 760
  OBJECT block   AT 200 30 700
  OBJECT wall    AT 190 30 750
END
)";

constexpr const char* kCarryIntoWall =
    "MOVETO -2800 2800 0 0\n"
    "MOVE 0 0 1490 0\n"
    "MOVE 0 0 0 100\n"
    "MOVE 0 0 -100 0\n"
    "MOVE 0 400 0 0\n"
    "END\n";

struct SvgSegment {
  double ax, ay, bx, by;
};

// The SVG's stroked paths: for each stroke colour "rgb(...)" and width, its
// segments (cairo writes a path of lines as "M x y L x y" pairs).
std::map<std::string, std::vector<SvgSegment>> svgStrokes(const std::string& svg) {
  std::map<std::string, std::vector<SvgSegment>> out;
  const std::regex path(R"re(stroke-width:([0-9.]+);[^"]*stroke:(rgb\([^)]*\));[^"]*" d="([^"]*)")re");
  const std::regex segment(R"(M ([-0-9.e]+) ([-0-9.e]+) L ([-0-9.e]+) ([-0-9.e]+))");
  for (auto p = std::sregex_iterator(svg.begin(), svg.end(), path); p != std::sregex_iterator(); ++p) {
    const std::string key = (*p)[2].str() + " " + (*p)[1].str(), d = (*p)[3].str();
    for (auto s = std::sregex_iterator(d.begin(), d.end(), segment); s != std::sregex_iterator(); ++s)
      out[key].push_back({std::stod((*s)[1]), std::stod((*s)[2]), std::stod((*s)[3]), std::stod((*s)[4])});
  }
  return out;
}

// Whether one of `segments` is `line` of the dump: cairo keeps coordinates
// in 24.8 fixed point, so the SVG has them to 1/256 px.
bool drawnInSvg(const std::vector<SvgSegment>& segments, const nlohmann::json& line) {
  constexpr double kFixedPoint = 1.0 / 256;
  const double ax = line["a"][0], ay = line["a"][1], bx = line["b"][0], by = line["b"][1];
  for (const SvgSegment& s : segments)
    if (std::abs(s.ax - ax) <= kFixedPoint && std::abs(s.ay - ay) <= kFixedPoint &&
        std::abs(s.bx - bx) <= kFixedPoint && std::abs(s.by - by) <= kFixedPoint)
      return true;
  return false;
}

// CIEDE2000 colour difference of two sRGB colours (D65), written from the
// CIE's formulas: about 2 is the least a viewer notices side by side.
struct CieLab {
  double L, a, b;
};
CieLab cieLabOf(double r, double g, double b) {
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  r = linear(r), g = linear(g), b = linear(b);
  const double X = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047, Y = 0.2126 * r + 0.7152 * g + 0.0722 * b,
               Z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; };
  return {116 * f(Y) - 16, 500 * (f(X) - f(Y)), 200 * (f(Y) - f(Z))};
}
double deltaE2000(const CieLab& p, const CieLab& q) {
  const double deg = M_PI / 180;
  const double C7 = std::pow((std::hypot(p.a, p.b) + std::hypot(q.a, q.b)) / 2, 7);
  const double G = 0.5 * (1 - std::sqrt(C7 / (C7 + std::pow(25.0, 7))));
  const double a1 = (1 + G) * p.a, a2 = (1 + G) * q.a;
  const double C1 = std::hypot(a1, p.b), C2 = std::hypot(a2, q.b);
  const auto hue = [](double b, double a) {
    return a == 0 && b == 0 ? 0.0 : std::fmod(std::atan2(b, a) / (M_PI / 180) + 360, 360);
  };
  const double h1 = hue(p.b, a1), h2 = hue(q.b, a2);
  double dh = C1 * C2 == 0 ? 0 : h2 - h1;
  if (dh > 180) dh -= 360;
  if (dh < -180) dh += 360;
  const double dL = q.L - p.L, dC = C2 - C1, dH = 2 * std::sqrt(C1 * C2) * std::sin(dh / 2 * deg);
  const double L = (p.L + q.L) / 2, C = (C1 + C2) / 2;
  double h = h1 + h2;
  if (C1 * C2 != 0)
    h = std::abs(h1 - h2) <= 180 ? (h1 + h2) / 2 : h1 + h2 < 360 ? (h1 + h2 + 360) / 2 : (h1 + h2 - 360) / 2;
  const double T = 1 - 0.17 * std::cos((h - 30) * deg) + 0.24 * std::cos(2 * h * deg) +
                   0.32 * std::cos((3 * h + 6) * deg) - 0.20 * std::cos((4 * h - 63) * deg);
  const double SL = 1 + 0.015 * (L - 50) * (L - 50) / std::sqrt(20 + (L - 50) * (L - 50)), SC = 1 + 0.045 * C,
               SH = 1 + 0.015 * C * T;
  const double RT = -std::sin(2 * 30 * std::exp(-std::pow((h - 275) / 25, 2)) * deg) * 2 *
                    std::sqrt(std::pow(C, 7) / (std::pow(C, 7) + std::pow(25.0, 7)));
  return std::sqrt(std::pow(dL / SL, 2) + std::pow(dC / SC, 2) + std::pow(dH / SH, 2) + RT * (dC / SC) * (dH / SH));
}

// "rgb(66.666667%,0%,0%)" -> CieLab.
CieLab labOfSvg(const std::string& rgb) {
  std::smatch m;
  REQUIRE(std::regex_search(rgb, m, std::regex(R"(rgb\(([0-9.]+)%,([0-9.]+)%,([0-9.]+)%\))")));
  return cieLabOf(std::stod(m[1]) / 100, std::stod(m[2]) / 100, std::stod(m[3]) / 100);
}

// Draws the cell with the program at `args` as an SVG and as the dump of
// its lines, and checks that the lines of objects 1 (the block) and 2 (the
// wall), and no others, are drawn in one wide colour that is not light red.
void checkMarked(const std::vector<std::string>& args, int code) {
  const TempDir dir;
  const std::string cell = dir.write("wall-cell.rsd", kWallCell), program = dir.write("carry.rsp", kCarryIntoWall);
  std::vector<std::string> svgArgs = {"render", cell, "--program", program};
  svgArgs.insert(svgArgs.end(), args.begin(), args.end());
  std::vector<std::string> dumpArgs = svgArgs;
  svgArgs.insert(svgArgs.end(), {"-o", dir.file("still.svg")});
  dumpArgs.push_back("--dump-lines=json");
  const auto picture = runCli(svgArgs);
  INFO(picture.err);
  REQUIRE(picture.code == code);
  const auto dump = runCli(dumpArgs);
  REQUIRE(dump.code == code);
  const nlohmann::json lines = nlohmann::json::parse(dump.out)["lines"];
  const auto paths = svgStrokes(rs::testing::readBytes(dir.file("still.svg")));

  // The colour the block and the wall are drawn in, read from the SVG.
  std::string marked;
  for (const auto& [key, segments] : paths)
    for (const nlohmann::json& line : lines)
      if (line["owner"] == "object" && line["index"] == 1 && drawnInSvg(segments, line)) marked = key;
  REQUIRE(!marked.empty());
  INFO("marked: " << marked);
  CHECK(marked.ends_with(" 2.5"));  // twice the other lines' 1.25 px
  std::size_t inContact = 0;
  for (const nlohmann::json& line : lines) {
    const bool part = line["owner"] == "object" && (line["index"] == 1 || line["index"] == 2);
    INFO(line.dump());
    CHECK(drawnInSvg(paths.at(marked), line) == part);
    inContact += part;
  }
  CHECK(inContact == 24);  // two boxes of 12 edges
  CHECK(paths.at(marked).size() == inContact);
  // Not the block's own light red (255, 85, 85), nor near it.
  const CieLab lightRed = cieLabOf(1.0, 85.0 / 255, 85.0 / 255);
  CHECK(deltaE2000(labOfSvg(marked), lightRed) > 20);
  for (const auto& [key, segments] : paths)
    if (key.starts_with("rgb(100%,33.333333%,33.333333%)")) CHECK(segments.empty());
}

}  // namespace

TEST_CASE("CIEDE2000 as written here gives the published differences", "[render][collision]") {
  // Sharma, Wu and Dalal's test pairs 1 and 17 (CieLab given, ΔE00 2.0425 and 27.1492).
  CHECK(deltaE2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}) == Approx(2.0425).margin(1e-4));
  CHECK(deltaE2000({50, 2.5, 0}, {73, 25, -18}) == Approx(27.1492).margin(1e-4));
}

TEST_CASE("a still inside a carried block's collision draws the block and what it hits, and nothing else, marked",
          "[render][collision][cli]") {
  checkMarked({"--collisions=warn", "--at", "5.61"}, 0);
}

TEST_CASE("a still of a run stopped by a carried block's collision draws it at that moment, marked",
          "[render][collision][cli]") {
  checkMarked({}, 1);  // --collisions=error: drawn where the run stopped, exit 1
}
