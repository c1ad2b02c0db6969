// `robotsim run --profile`: the time the robot waited for an input, by
// input and by what ended the wait (issue 35): a wire from a sensor, a
// stimulus, a reactive rule; "already ON" for a wait that did not wait;
// "nothing" for the wait a run stopped in.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "../cli/cli_support.h"

namespace {

using Json = nlohmann::json;

std::int64_t microsOf(const Json& seconds) { return std::llround(seconds.get<double>() * 1e6); }

// The profile's entry for `input` and `driver`, or null.
const Json* inputWait(const Json& profile, int input, const std::string& driver) {
  for (const Json& w : profile.at("input_waits"))
    if (w.at("input") == input && w.at("driver") == driver) return &w;
  return nullptr;
}

}  // namespace

TEST_CASE("profile: adept_production's wait for input 1 is what the trace's WAITFOR steps took", "[profile][devices]") {
  const rs::testing::CliResult r =
      rs::testing::runCli({"run", std::string(ROBOTSIM_SOURCE_DIR) + "/examples/adept_production.rsp", "--cell",
                           "adept-cell", "--trace=json", "--format=json", "--profile"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  // The JSON trace: a line per step (its "time" is the step's end, so a
  // step starts at the one before it ends) and per event; the summary last.
  std::istringstream lines(r.out);
  std::string line, last;
  std::int64_t previousEnd = 0, waited = 0, firstWait = -1;
  int waits = 0, endedByTheEye = 0;
  std::vector<std::int64_t> waitEnds;
  std::vector<std::int64_t> eyeInputs;  // input 1 turned ON by the wire from sensor eye
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    last = line;
    const Json j = Json::parse(line);
    if (j.contains("event")) {
      if (j.at("event") == "input" && j.at("input") == 1 && j.at("on") == true && j.at("source") == "sensor eye")
        eyeInputs.push_back(microsOf(j.at("time")));
      continue;
    }
    if (!j.contains("op")) continue;
    const std::int64_t end = microsOf(j.at("time"));
    if (j.at("op") == "WAITFOR") {
      REQUIRE(j.at("text") == "WAITFOR 1 ON");
      waited += end - previousEnd, ++waits;
      if (firstWait < 0) firstWait = end - previousEnd;
      waitEnds.push_back(end);
    }
    previousEnd = end;
  }
  for (std::int64_t end : waitEnds)
    for (std::int64_t on : eyeInputs) endedByTheEye += on == end;
  const Json summary = Json::parse(last);
  const Json& profile = summary.at("profile");
  CHECK(waits == 10);
  CHECK(endedByTheEye == 10);  // every wait ended as the eye turned input 1 ON
  // By hand: the first block (x 150..190) breaks the beam at x = 300 after
  // 110 at 100/s, the robot waiting from 0 s: 1.1 s.
  CHECK(firstWait == 1'100'000);
  REQUIRE(profile.at("input_waits").size() == 1);
  const Json* eye = inputWait(profile, 1, "wire from sensor eye");
  REQUIRE(eye != nullptr);
  CHECK(eye->at("waits") == 10);
  CHECK(eye->at("waiting_us").get<std::int64_t>() == waited);
  // Every WAITFOR is a wait: the profile's waiting is them and nothing else (no DELAY).
  CHECK(profile.at("waiting_us").get<std::int64_t>() == waited);
}

TEST_CASE("profile: waits ended by a stimulus and by a rule, a wait that did not wait, the wait a run stopped in",
          "[profile]") {
  // Default robot. Line 1 waits for input 2, which the stimulus turns ON
  // at 1.5 s: 1.5 s by "stimulus". Line 2 finds it ON: "already ON", 0 s.
  // OUTSIG 1 ON (line 3, at 1.5 s) makes the rule turn input 3 ON 0.25 s
  // later: line 4 waits 0.25 s by "rule". Line 5 waits for input 4, which
  // nothing turns ON: a deadlock there, "nothing (the run stopped waiting)".
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp",
                                        "        WAITFOR 2 ON\n"
                                        "        WAITFOR 2 ON\n"
                                        "        OUTSIG 1 ON\n"
                                        "        WAITFOR 3 ON\n"
                                        "        WAITFOR 4 ON\n"
                                        "        END\n");
  const std::string stimuli = dir.write("p.stim",
                                        "at 1.5 input 2 on\n"
                                        "when output 1 on then input 3 on after 0.25\n");
  const rs::testing::CliResult r =
      rs::testing::runCli({"run", program, "--stimuli", stimuli, "--format=json", "--profile"});
  INFO(r.out << r.err);
  const Json j = Json::parse(r.out);
  CHECK(j.at("diagnostics")[0].at("code") == "deadlock");
  const Json& p = j.at("profile");
  REQUIRE(p.at("input_waits").size() == 4);
  const Json* stimulus = inputWait(p, 2, "stimulus");
  const Json* already = inputWait(p, 2, "already ON");
  const Json* rule = inputWait(p, 3, "rule");
  const Json* nothing = inputWait(p, 4, "nothing (the run stopped waiting)");
  REQUIRE(stimulus);
  REQUIRE(already);
  REQUIRE(rule);
  REQUIRE(nothing);
  CHECK(stimulus->at("waits") == 1);
  CHECK(stimulus->at("waiting_us") == 1'500'000);
  CHECK(already->at("waits") == 1);
  CHECK(already->at("waiting_us") == 0);
  CHECK(rule->at("waits") == 1);
  CHECK(rule->at("waiting_us") == 250'000);
  CHECK(nothing->at("waits") == 1);
  // In input order, then by driver's words.
  CHECK(p.at("input_waits")[0].at("driver") == "already ON");
  CHECK(p.at("input_waits")[1].at("driver") == "stimulus");

  const rs::testing::CliResult text = rs::testing::runCli({"run", program, "--stimuli", stimuli, "--profile"});
  CHECK(text.out.find("  waiting for inputs (by what ended the wait)") != std::string::npos);
  // Each row: 4 blanks, the input and driver in 46 columns, the time in 11, the waits in 7.
  const std::string stimulusRow = "    input 2: stimulus" + std::string(46 - 17 + 1 + 4, ' ') + "1.500 s" +
                                  std::string(7, ' ') + "1\n";
  const std::string ruleRow = "    input 3: rule" + std::string(46 - 13 + 1 + 4, ' ') + "0.250 s" + std::string(7, ' ') + "1\n";
  CHECK(text.out.find(stimulusRow) != std::string::npos);
  CHECK(text.out.find(ruleRow) != std::string::npos);
}
