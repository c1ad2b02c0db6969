// The cairo drawing: PNG files decoded again and checked for the lines'
// colours in the lines' places; SVG from the same drawing code.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "render_test_util.h"
#include "runtime/render/draw.h"
#include "runtime/render/palette.h"
#include "runtime/render/picture.h"

using rs::render::Decoded;
using rs::render::Picture;
using rs::render::Rgb;

namespace {

Picture picture(const std::string& cellName, rs::render::Camera camera = {}) {
  static std::vector<rs::workcell::Workcell> cells;  // the poser keeps a pointer
  cells.push_back(rendertest::cell(cellName));
  rs::render::CellPoser poser(cells.back());
  return rs::render::makePicture(poser, camera, rs::render::fitView(poser.homePoints(), camera), {cellName, 1.5});
}

Rgb pixel(const Decoded& d, int x, int y) {
  const std::size_t k =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(d.width) + static_cast<std::size_t>(x));
  return {d.rgb[k], d.rgb[k + 1], d.rgb[k + 2]};
}

double colorDistance(Rgb a, Rgb b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

bool inLegend(double x, double y) { return x < 420 && y < 60; }

}  // namespace

TEST_CASE("A PNG still shows each line in its EGA colour where the line is", "[render]") {
  for (const std::string name : {"scara-pick", "puma-cell", "scorobot-cell"}) {
    INFO(name);
    const Picture pic = picture(name);
    const auto png = rs::render::encodePicture(pic, rs::render::ImageFormat::Png);
    REQUIRE(png.ok());
    REQUIRE(png->size() > 8);
    CHECK(std::string(png->begin() + 1, png->begin() + 4) == "PNG");
    const auto decoded = rs::render::decodePng(*png);
    REQUIRE(decoded.ok());
    const Decoded& d = *decoded;
    REQUIRE(d.width == 1024);
    REQUIRE(d.height == 768);
    // The background where nothing is drawn.
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{1023, 767}, {1023, 0}, {0, 767}})
      CHECK(pixel(d, x, y) == rs::render::kBackground);

    // Each line longer than 12 pixels has a pixel of its colour within one
    // pixel of its midpoint (a few may be covered by lines drawn later).
    int lines = 0, found = 0;
    for (const rs::render::Line2& l : pic.lines) {
      if ((l.b - l.a).norm() < 12 || l.color == rs::workcell::Color::Black) continue;
      const Eigen::Vector2d m = 0.5 * (l.a + l.b);
      if (inLegend(m.x(), m.y()) || m.x() < 1 || m.y() < 1 || m.x() > 1022 || m.y() > 766) continue;
      ++lines;
      bool hit = false;
      for (int dy = -1; dy <= 1 && !hit; ++dy)
        for (int dx = -1; dx <= 1 && !hit; ++dx)
          hit = colorDistance(pixel(d, static_cast<int>(m.x()) + dx, static_cast<int>(m.y()) + dy),
                              rs::render::rgb(l.color)) < 60;
      found += hit;
    }
    CHECK(lines > 50);
    CHECK(found >= lines * 9 / 10);

    // Every pixel of exactly an EGA colour lies near a line of that colour
    // (or in the legend, or on a tool mark for WHITE).
    std::array<Eigen::AlignedBox2d, 16> boxes;
    for (const rs::render::Line2& l : pic.lines) {
      boxes[static_cast<std::size_t>(l.color)].extend(l.a);
      boxes[static_cast<std::size_t>(l.color)].extend(l.b);
    }
    for (const rs::render::ToolMark& t : pic.tools) {
      boxes[15].extend(t.at - Eigen::Vector2d(11, 11));
      boxes[15].extend(t.at + Eigen::Vector2d(11, 11));
    }
    int colored = 0, stray = 0;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) {
        const Rgb p = pixel(d, x, y);
        for (std::size_t c = 1; c < 16; ++c)
          if (p == rs::render::kEga[c]) {
            ++colored;
            const Eigen::Vector2d at(x + 0.5, y + 0.5);
            if (!inLegend(at.x(), at.y()) && (boxes[c].isEmpty() || boxes[c].exteriorDistance(at) > 2.5)) ++stray;
          }
      }
    CHECK(colored > 500);
    CHECK(stray == 0);
  }
}

TEST_CASE("The legend is drawn at the top left", "[render]") {
  const Picture pic = picture("scara-pick");
  REQUIRE(pic.legend.size() == 2);
  CHECK(pic.legend[0] == "scara-pick   t = 1.500 s");
  CHECK(pic.legend[1] == "rhino-scara  E=0 D=0 C=0 B=0 A=0");
  const Decoded d = rs::render::decodePng(rs::render::encodePicture(pic, rs::render::ImageFormat::Png).value()).value();
  int text = 0;
  for (int y = 8; y < 40; ++y)
    for (int x = 8; x < 200; ++x) text += colorDistance(pixel(d, x, y), rs::render::kEga[7]) < 90;
  CHECK(text > 50);
}

TEST_CASE("SVG comes from the same drawing code", "[render]") {
  const Picture pic = picture("scara-pick");
  const auto svg = rs::render::encodePicture(pic, rs::render::ImageFormat::Svg);
  REQUIRE(svg.ok());
  const std::string text(svg->begin(), svg->end());
  CHECK(text.rfind("<?xml", 0) == 0);
  CHECK(text.find("<svg") != std::string::npos);
  CHECK(text.find("width=\"1024") != std::string::npos);
  CHECK(text.find("</svg>") != std::string::npos);
  // Each used colour appears as a stroke: cairo writes rgb(R%, G%, B%).
  CHECK(text.find("stroke:rgb(") != std::string::npos);
}

TEST_CASE("Sizes, formats and undecodable bytes", "[render]") {
  rs::render::Camera small;
  small.width = 64;
  small.height = 48;
  const Decoded d =
      rs::render::decodePng(rs::render::encodePicture(picture("scorobot", small), rs::render::ImageFormat::Png).value())
          .value();
  CHECK(d.width == 64);
  CHECK(d.height == 48);
  CHECK(rs::render::formatFromPath("a/b.PNG") == rs::render::ImageFormat::Png);
  CHECK(rs::render::formatFromPath("x.svg") == rs::render::ImageFormat::Svg);
  CHECK_FALSE(rs::render::formatFromPath("x.jpg"));
  CHECK_FALSE(rs::render::formatFromPath("png"));
  const auto notPng = rs::render::decodePng({'n', 'o', 't'});
  REQUIRE_FALSE(notPng.ok());
  CHECK(notPng.failure().message.rfind("cairo: ", 0) == 0);
  Picture bad;
  bad.width = 0;
  const auto refused = rs::render::encodePicture(bad, rs::render::ImageFormat::Png);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.failure().message == "image size out of range (1..16384 pixels)");
}
