// `robotsim render` and `robotsim animate` end to end, in-process.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <fmt/format.h>
#include <sstream>

#include "render_test_util.h"
#include "runtime/render/animation.h"
#include "runtime/render/camera.h"
#include "runtime/render/draw.h"
#include "runtime/render/scene.h"
#include "tools/cli/lib/render_commands.h"

using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

namespace {

const std::string kExamples = rendertest::kSourceDir + "/examples/";

// The model a page embeds, parsed back.
nlohmann::json pageModel(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t a = html.find(open);
  REQUIRE(a != std::string::npos);
  const std::size_t b = html.find("</script>", a);
  REQUIRE(b != std::string::npos);
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

}  // namespace

TEST_CASE("render writes a PNG and an SVG of a library workcell", "[render][cli]") {
  const TempDir dir;
  const auto png = runCli({"render", "scara-pick", "-o", dir.file("cell.png")});
  INFO(png.err);
  REQUIRE(png.code == 0);
  const std::string bytes = readBytes(dir.file("cell.png"));
  const auto d = rs::render::decodePng({bytes.begin(), bytes.end()});
  REQUIRE(d.ok());
  CHECK(d->width == 1024);
  CHECK(d->height == 768);
  REQUIRE(runCli({"render", "scara-pick", "--size", "320x200", "-o", dir.file("small.PNG")}).code == 0);
  const std::string small = readBytes(dir.file("small.PNG"));
  CHECK(rs::render::decodePng({small.begin(), small.end()})->width == 320);
  REQUIRE(runCli({"render", "scara-pick", "--axes", "--view", "0,90,0", "-o", dir.file("cell.svg")}).code == 0);
  CHECK(readBytes(dir.file("cell.svg")).rfind("<?xml", 0) == 0);
}

TEST_CASE("render --dump-lines prints the same lines as text and JSON", "[render][cli]") {
  const auto text = runCli({"render", "puma-cell", "--dump-lines", "--view", "10,20,30", "--zoom", "1.5"});
  const auto json = runCli({"render", "puma-cell", "--dump-lines=json", "--view", "10,20,30", "--zoom", "1.5"});
  REQUIRE(text.code == 0);
  REQUIRE(json.code == 0);
  const auto doc = nlohmann::json::parse(json.out);
  std::istringstream rows(text.out);
  std::string row;
  std::size_t n = 0;
  while (std::getline(rows, row))
    if (row.rfind("robot ", 0) == 0 || row.rfind("object ", 0) == 0) {
      std::istringstream words(row);
      std::string owner, index, name, part, color;
      double u1, v1, u2, v2;
      words >> owner >> index >> name >> part >> color >> u1 >> v1 >> u2 >> v2;
      const auto& l = doc["lines"].at(n++);
      CHECK(l["part"] == part);
      CHECK(l["color"] == color);
      CHECK(l["a"][0].get<double>() == Approx(u1).margin(1e-8));
      CHECK(l["b"][1].get<double>() == Approx(v2).margin(1e-8));
    }
  CHECK(n == doc["lines"].size());
  CHECK(doc["camera"]["zoom"] == 1.5);
  CHECK(doc["tools"].size() == 1);
}

TEST_CASE("render --program --at draws a moment of the run", "[render][cli]") {
  // first_moves.rsp: MOVETO 400 200 0 0 0 takes 1 s (E at 400 units/s).
  const auto half =
      runCli({"render", "scara-pick", "--program", kExamples + "first_moves.rsp", "--at", "0.5", "--dump-lines=json"});
  INFO(half.err);
  REQUIRE(half.code == 0);
  const auto doc = nlohmann::json::parse(half.out);
  CHECK(doc["legend"][0] == "first_moves.rsp on scara-pick   t = 0.500 s");
  CHECK(doc["legend"][1] == "rhino-scara  E=200 D=200 C=0 B=0 A=0");
  // Without --at: the end of the run.
  const auto end = runCli({"render", "scara-pick", "--program", kExamples + "first_moves.rsp", "--dump-lines=json"});
  REQUIRE(end.code == 0);
  CHECK(nlohmann::json::parse(end.out)["legend"][0] == "first_moves.rsp on scara-pick   t = 5.333 s");
  // VIEW and WINDOW executed by the program change the camera from then on.
  const auto viewed =
      runCli({"render", "scara-pick", "--program", kExamples + "workcell_view.rsp", "--at", "3", "--dump-lines=json"});
  REQUIRE(viewed.code == 0);
  const auto cam = nlohmann::json::parse(viewed.out)["camera"];
  CHECK(cam["view"] == nlohmann::json::array({25.0 + 30, -35.0, 45.0}));
  CHECK(cam["window"] == nlohmann::json::array({0.0, -100.0, 50.0}));
}

TEST_CASE("render and animate reject bad options and inputs clearly", "[render][cli]") {
  const TempDir dir;
  const auto expectError = [](const std::vector<std::string>& args, int code, const std::string& message) {
    const auto r = runCli(args);
    INFO(r.err);
    CHECK(r.code == code);
    CHECK(r.err.find(message) != std::string::npos);
  };
  expectError({"render", "scara-pick", "--view", "1,2", "--dump-lines"}, 2, "--view takes three numbers");
  expectError({"render", "scara-pick", "--window", "a,b,c", "--dump-lines"}, 2, "--window: error: value 1 'a' is not a number");
  expectError({"render", "scara-pick", "--zoom", "0", "--dump-lines"}, 2, "--zoom: error: '0' is out of range: a zoom is above 0");
  expectError({"render", "scara-pick", "--size", "10x10", "--dump-lines"}, 2,
              "--size: error: '10' is out of range: a picture's side is a whole number from 16 to 16384");
  expectError({"render", "scara-pick", "--size", "1024", "--dump-lines"}, 2, "--size takes WIDTHxHEIGHT");
  expectError({"render", "scara-pick", "-o", dir.file("x.jpg")}, 2, "must end in .png or .svg");
  expectError({"render", "scara-pick"}, 2, "give -o");
  expectError({"render", "scara-pick", "--at", "1", "--dump-lines"}, 2, "--at needs --program");
  // Every option of a run needs the run.
  expectError({"render", "scara-pick", "--input", "1=ON@0", "--dump-lines"}, 2, "--input needs --program");
  expectError({"render", "scara-pick", "--stimuli", kExamples + "pick_and_place.stim", "--dump-lines"}, 2,
              "--stimuli needs --program");
  expectError({"render", "scara-pick", "--max-steps", "5", "--dump-lines"}, 2, "--max-steps needs --program");
  expectError({"render", "scara-pick", "--max-time", "5", "--dump-lines"}, 2, "--max-time needs --program");
  // Even the default's value, when given.
  expectError({"render", "scara-pick", "--max-time", "3600", "--dump-lines"}, 2, "--max-time needs --program");
  expectError({"render", "no-such-cell", "--dump-lines"}, 2, "no-such-cell");
  expectError({"render", "scara-pick", "--dump-lines=xml"}, 2, "--dump-lines takes text or json");
  expectError({"render", "scara-pick", "--program", kExamples + "first_moves.rsp", "--at", "-1", "--dump-lines"}, 2,
              "--at");
  expectError({"animate", kExamples + "first_moves.rsp", "-o", dir.file("x.html")}, 2, "--cell");
  expectError({"animate", kExamples + "first_moves.rsp", "--cell", "scara-pick", "-o", dir.file("x.png")}, 2,
              "must end in .html");
  CHECK_FALSE(std::filesystem::exists(dir.file("x.png")));
  expectError({"render", "scara-pick", "-o", dir.file("missing/dir/x.png")}, 2, "cannot write");
  CHECK_FALSE(std::filesystem::exists(dir.file("x.jpg")));
  CHECK_FALSE(std::filesystem::exists(dir.file("x.html")));
  // A run that fails before the moment asked for.
  const std::string stuck = dir.write("stuck.rsp", "MOVE 100 0 0 0 0\nWAITFOR 3 ON\nEND\n");
  expectError({"render", "scara-pick", "--program", stuck, "--at", "5", "--dump-lines"}, 1, "never turns ON");
}

TEST_CASE("renderCommand itself checks --dump-lines' value", "[render][cli]") {
  rs::cli::RenderOptions o;
  o.program.cell = "scara-pick";
  o.dump = "xml";
  std::ostringstream out, err;
  CHECK(rs::cli::renderCommand(o, out, err) == 2);
  CHECK(err.str().find("--dump-lines takes text or json, not 'xml'") != std::string::npos);
  CHECK(out.str().empty());
}

TEST_CASE("animate writes one self-contained page with the run in it", "[render][cli]") {
  const TempDir dir;
  const auto r = runCli({"animate", kExamples + "pick_and_place.rsp", "--cell", "scara-pick", "--stimuli",
                         kExamples + "pick_and_place.stim", "-o", dir.file("run.html")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("59 instructions executed") != std::string::npos);
  const std::string html = readBytes(dir.file("run.html"));
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  // Nothing to fetch: no external references, and a policy that forbids them.
  // The chart's SVG declares its XML namespaces, names that are never fetched:
  // those two, as the model's JSON escapes them, are the only http:// allowed.
  std::string fetchable = html;
  for (const std::string ns : {"xmlns=\\\"http://www.w3.org/2000/svg\\\"",
                               "xmlns:xlink=\\\"http://www.w3.org/1999/xlink\\\""})
    for (std::size_t at; (at = fetchable.find(ns)) != std::string::npos;) fetchable.erase(at, ns.size());
  for (const char* ref : {" src=", " href=", "http://", "https://", "@import", "url("})
    CHECK(fetchable.find(ref) == std::string::npos);
  CHECK(html.find("default-src 'none'") != std::string::npos);
  const auto model = pageModel(html);
  CHECK(model["cell"] == "scara-pick");
  CHECK(model["robots"].size() == 1);
  CHECK(model["objects"].size() == 5);
  CHECK(model["run"]["index"].size() == 59);
  CHECK(model["run"]["end"] == 34'900'000);
  CHECK(model["run"]["motors"].size() == 5);
  CHECK(model["run"]["outcome"] == "");
  CHECK(model["program"]["lines"].size() > 30);
  CHECK(model["run"]["inputs"]["at"].size() > 3);
}

// The page draws with the stills' colours and marks, taken from the C++
// constants, and the script keeps no copy of them.
TEST_CASE("animate's page model carries the stills' style", "[render][cli]") {
  const TempDir dir;
  const std::string prog = dir.write("p.rsp", "MOVE 10 0 0 0 0\nEND\n");
  REQUIRE(runCli({"animate", prog, "--cell", "scara-pick", "-o", dir.file("RUN.HTML")}).code == 0);
  const std::string html = readBytes(dir.file("RUN.HTML"));
  const auto style = pageModel(html)["style"];
  REQUIRE(style["palette"].size() == 16);
  CHECK(style["palette"][0] == "#000000");
  CHECK(style["palette"][6] == "#aa5500");
  CHECK(style["palette"][12] == "#ff5555");
  CHECK(style["palette"][15] == "#ffffff");
  CHECK(style["background"] == "#10121c");
  CHECK(style["axisColors"] == nlohmann::json::array({12, 10, 9}));
  CHECK(style["axisLength"] == rs::render::kAxisLength);
  CHECK(style["toolRadius"] == rs::render::kToolRadius);
  CHECK(style["toolLineWidth"] == rs::render::kToolLineWidth);
  CHECK(style["toolColor"] == 15);
  const std::string_view script = rs::render::pageScript();
  for (const char* copy : {"#10121c", "#aa5500", "0.08", "R = 5", "lineWidth = 1.5"}) {
    INFO(copy);
    CHECK(script.find(copy) == std::string_view::npos);
  }
}

TEST_CASE("animate keeps a failed run up to the failure and says why", "[render][cli]") {
  const TempDir dir;
  const std::string stuck = dir.write("stuck.rsp", "MOVE 100 0 0 0 0\nWAITFOR 3 ON\nEND\n");
  const auto r = runCli({"animate", stuck, "--cell", "scara-pick", "-o", dir.file("run.html")});
  CHECK(r.code == 1);
  CHECK(r.err.find("never turns ON") != std::string::npos);
  const auto model = pageModel(readBytes(dir.file("run.html")));
  CHECK(model["run"]["index"].size() == 2);
  CHECK(model["run"]["outcome"].get<std::string>().find("line 2:") == 0);
}

TEST_CASE("animate's listing: the source, or the disassembly of an image", "[render][cli]") {
  const TempDir dir;
  // A </script> in a comment must not end the page's data.
  const std::string prog = dir.write("p.rsp", "; </script><script>alert(1)</script>\nMOVE 10 0 0 0 0\nEND\n");
  REQUIRE(runCli({"animate", prog, "--cell", "scara-pick", "-o", dir.file("a.html")}).code == 0);
  const std::string html = readBytes(dir.file("a.html"));
  CHECK(html.find("alert(1)</script>") == std::string::npos);
  const auto model = pageModel(html);
  CHECK(model["program"]["lines"][0] == "; </script><script>alert(1)</script>");
  CHECK(model["program"]["lineOf"] == nlohmann::json::array({2, 3}));
  // An image carries its cell: no --cell needed.
  REQUIRE(runCli({"compile", prog, "--cell", "scara-pick", "-o", dir.file("p.rsb")}).code == 0);
  const auto r = runCli({"animate", dir.file("p.rsb"), "-o", dir.file("b.html")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto image = pageModel(readBytes(dir.file("b.html")));
  CHECK(image["program"]["lines"].size() == 2);
  CHECK(image["program"]["lines"][0].get<std::string>().find("MOVE") != std::string::npos);
  CHECK(image["cell"] == "scara-pick");
}

TEST_CASE("render says what it wrote: the file, its size in pixels, its format and bytes", "[render][cli]") {
  const TempDir dir;
  const std::string png = dir.file("cell.png");
  const auto r = runCli({"render", "scara-pick", "--size", "320x200", "-o", png});
  REQUIRE(r.code == 0);
  CHECK(r.out == "scara-pick -> " + png + " (320x200 pixels, PNG, " + std::to_string(readBytes(png).size()) +
                     " bytes)\n");
  const std::string svg = dir.file("moment.svg");
  const auto m = runCli({"render", "scara-pick", "--program", kExamples + "first_moves.rsp", "--at", "0.5", "-o", svg});
  REQUIRE(m.code == 0);
  CHECK(m.out == kExamples + "first_moves.rsp on scara-pick -> " + svg + " (1024x768 pixels, SVG, " +
                     std::to_string(readBytes(svg).size()) + " bytes, at 0.500 s)\n");
  // With --dump-lines on stdout, the note goes to stderr.
  const auto both = runCli({"render", "scara-pick", "--dump-lines=json", "-o", png});
  REQUIRE(both.code == 0);
  CHECK(nlohmann::json::accept(both.out));
  CHECK_THAT(both.err, Catch::StartsWith("scara-pick -> " + png + " (1024x768 pixels, PNG, "));
}

namespace {

// The camera and fit of a --dump-lines=json picture, as drawn.
rs::render::Projection projectionOf(const nlohmann::json& doc) {
  rs::render::Camera camera;
  for (int k = 0; k < 3; ++k) {
    camera.view[k] = doc["camera"]["view"][k].get<double>();
    camera.window[k] = doc["camera"]["window"][k].get<double>();
  }
  camera.zoom = doc["camera"]["zoom"].get<double>();
  camera.width = doc["width"].get<int>();
  camera.height = doc["height"].get<int>();
  rs::render::Fit fit;
  for (int k = 0; k < 3; ++k) fit.center[k] = doc["fit"]["center"][k].get<double>();
  fit.radius = doc["fit"]["radius"].get<double>();
  return rs::render::Projection(camera, fit);
}

// Zooming by `zoom` about `pivot`: the pivot keeps its pixel, and every
// endpoint moves `zoom` times as far from that pixel as it was at zoom 1.
void expectZoomAbout(const std::vector<std::string>& args, double zoom, const Eigen::Vector3d& pivot) {
  std::vector<std::string> one = args, more = args;
  one.insert(one.end(), {"--dump-lines=json", "--zoom", "1"});
  more.insert(more.end(), {std::string("--dump-lines=json"), std::string("--zoom"), fmt::format("{}", zoom)});
  const auto a = runCli(one), b = runCli(more);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  const auto docA = nlohmann::json::parse(a.out), docB = nlohmann::json::parse(b.out);
  const Eigen::Vector2d at1 = projectionOf(docA)(pivot), atZ = projectionOf(docB)(pivot);
  CHECK(atZ.x() == Approx(at1.x()).margin(1e-6));
  CHECK(atZ.y() == Approx(at1.y()).margin(1e-6));
  REQUIRE(docA["lines"].size() == docB["lines"].size());
  for (std::size_t i = 0; i < docA["lines"].size(); ++i)
    for (const char* end : {"a", "b"})
      for (int k = 0; k < 2; ++k) {
        const double p1 = docA["lines"][i][end][k].get<double>(), pz = docB["lines"][i][end][k].get<double>();
        CHECK(pz == Approx(at1[k] + zoom * (p1 - at1[k])).margin(1e-6));
      }
}

}  // namespace

TEST_CASE("render --zoom zooms about the robot, or about --center", "[render][cli]") {
  const rs::workcell::Workcell scara = rendertest::cell("scara-pick");
  // The robot's middle as drawn at home, from its lines in the world.
  Eigen::AlignedBox3d box;
  const auto& placed = scara.robots.at(0);
  for (const auto* shape : {&placed.robot.gripper.base, &placed.robot.gripper.finger2, &placed.robot.gripper.finger3})
    for (const auto& s : shape->segments) box.extend(placed.F_world_design * s.a), box.extend(placed.F_world_design * s.b);
  for (const auto& link : placed.robot.links)
    for (const auto& s : link.segments) box.extend(placed.F_world_design * s.a), box.extend(placed.F_world_design * s.b);
  REQUIRE(rs::cli::zoomPivot(scara).has_value());
  CHECK(rs::cli::zoomPivot(scara)->isApprox(box.center()));
  expectZoomAbout({"render", "scara-pick"}, 3.0, box.center());
  expectZoomAbout({"render", "scara-pick", "--view", "10,20,30", "--window", "50,0,-20"}, 2.5, box.center());
  // --center: any world point.
  expectZoomAbout({"render", "scara-pick", "--center", "100,-50,25"}, 4.0, Eigen::Vector3d(100, -50, 25));
  CHECK(runCli({"render", "scara-pick", "--center", "1,2", "-o", "x.png"}).code == 2);
}
