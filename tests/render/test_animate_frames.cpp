// `robotsim animate` of a run of a million steps (issue 26: a 43.7 MB page
// at a 397 MB peak): the page holds the frames a screen can show, every
// event among them (docs/render.md, "Frames").
//
// The program: 200 rounds of 1,249 back-and-forth moves of motor E by one
// count (2.5 ms each at 400 counts/s: 6.245 s a round), then output 1 ON
// and OFF. Steps: 200 · (1,249 · 4 + 5) + END = 1,000,201; time 200 ·
// 6.245 s = 1,249 s, so each of the default rule's 20,000 slots is
// 1,249 s / 20,000 = 62.45 ms.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

using rs::testing::runCli;
using rs::testing::TempDir;

namespace {

const char* const kMillion =
    "loop:   MOVE 1 0 0 0 0\n"
    "        MOVE -1 0 0 0 0\n"
    "        ADD M 1\n"
    "        JMPVAR M < 1249 loop\n"
    "        SET M 0\n"
    "        OUTSIG 1 ON\n"
    "        OUTSIG 1 OFF\n"
    "        ADD N 1\n"
    "        JMPVAR N < 200 loop\n"
    "        END\n";

// The page's model: the JSON in its <script id="robotsim-model">.
nlohmann::json pageModelOf(const std::string& html) {
  const std::string open = "id=\"robotsim-model\">";
  const std::size_t at = html.find(open);
  REQUIRE(at != std::string::npos);
  const std::size_t from = at + open.size();
  return nlohmann::json::parse(html.substr(from, html.find("</script>", from) - from));
}

}  // namespace

TEST_CASE("animate of a million steps writes a page of bounded frames with every output change",
          "[render][frames][cli]") {
  const TempDir dir;
  const std::string program = dir.write("million.rsp", kMillion), page = dir.file("million.html");
  const auto r =
      runCli({"animate", program, "--cell", "scara-pick", "--collisions=off", "--max-steps", "2000000", "-o", page});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("(1000201 instructions executed, 1249.000 s simulated; the page shows ") != std::string::npos);
  CHECK(r.out.find(" frames: every event, and the first instruction to start in each 0.062 s)") != std::string::npos);
  const std::string html = rs::testing::readBytes(page);
  CHECK(html.size() < 2'000'000);  // was 37.8 MB
  const nlohmann::json run = pageModelOf(html)["run"];
  CHECK(run["frames"]["steps"] == 1000201);
  CHECK(run["frames"]["slot"] == 62450);
  CHECK(run["end"] == 1'249'000'000);
  // At most a frame per slot and one per step as long as a slot (none here),
  // the 400 output changes, the first and the last step.
  const std::size_t frames = run["index"].size();
  CHECK(frames <= 20'001 + 400 + 2);
  CHECK(frames >= 20'000);          // every slot has a step starting in it
  CHECK(run["index"].back() == 9);  // END
  // Every output change, at its instruction and its time: round r's ON
  // (instruction 6, 0-based 5) when its 2,498 moves are over, r · 6.245 s.
  const nlohmann::json& outputs = run["outputs"];
  REQUIRE(outputs["step"].size() == 400);
  for (std::size_t i = 0; i < 400; ++i) {
    const std::size_t frame = outputs["step"][i];
    const bool on = i % 2 == 0;
    INFO("change " << i);
    CHECK(outputs["mask"][i] == (on ? 1 : 0));
    CHECK(run["index"][frame] == (on ? 5 : 6));
    CHECK(run["start"][frame] == static_cast<std::int64_t>(i / 2 + 1) * 6'245'000);
  }
}
