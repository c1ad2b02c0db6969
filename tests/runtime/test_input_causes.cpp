// Every change of an input is reported with its cause, in the same words
// wherever it shows: the text trace, the JSON trace and the run log name a
// stimulus by its line, a reactive rule by its line, a debugger's set as
// such (a wire from a device, the third cause, comes with the devices).
// The times are the stimuli's own: 0.25 s, the rule's 0.5 s after OUTSIG
// at 0, and 2 s.
#include <catch2/catch.hpp>

#include <memory>
#include <sstream>
#include <string>

#include "../render/render_test_util.h"
#include "compiler/stimuli/stimuli.h"
#include "runtime/run/run.h"
#include "runtime/run/trace.h"

namespace inputcausetest {

constexpr const char* kProgram =
    "        OUTSIG 1 ON\n"
    "        DELAY 1\n"
    "        WAITFOR 4 ON\n"
    "        END\n";
constexpr const char* kStimuli =
    "at 0.25 input 3 on\n"
    "when output 1 on then input 2 on after 0.5\n"
    "at 2 input 4 on\n";

std::unique_ptr<rs::runtime::Run> runOfCauses() {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(rendertest::compileText(kProgram, cell));
  auto stimuli = rs::stimuli::parseStimuli(kStimuli, "causes.rss");
  REQUIRE(stimuli.ok());
  spec.stimuli = std::move(stimuli).value();
  spec.log = true;
  return std::make_unique<rs::runtime::Run>(std::move(spec));
}

std::string traced(rs::runtime::TraceFormat format) {
  auto run = runOfCauses();
  std::ostringstream out;
  rs::runtime::TraceWriter trace(out, format, *run);
  run->observe(trace);
  REQUIRE(run->runToEnd().ok());
  return out.str();
}

}  // namespace inputcausetest

using namespace inputcausetest;

TEST_CASE("the text trace has a line for every input change, at its time, naming its cause", "[run][inputs]") {
  const std::string t = traced(rs::runtime::TraceFormat::Text);
  INFO(t);
  const auto stimulus = t.find("     0.250  input 3 ON: stimulus, line 1\n");
  const auto rule = t.find("     0.500  input 2 ON: rule of line 2\n");
  const auto later = t.find("     2.000  input 4 ON: stimulus, line 3\n");
  REQUIRE(stimulus != std::string::npos);
  REQUIRE(rule != std::string::npos);
  REQUIRE(later != std::string::npos);
  CHECK(stimulus < rule);
  CHECK(rule < later);
  // Each before the row of the step it happened in: the DELAY, the WAITFOR.
  CHECK(t.find("DELAY", rule) != std::string::npos);
  CHECK(t.find("DELAY") > rule);
  CHECK(t.find("WAITFOR") > later);
}

TEST_CASE("the JSON trace says each input change's cause in a word and its line", "[run][inputs]") {
  const std::string t = traced(rs::runtime::TraceFormat::Json);
  INFO(t);
  CHECK(t.find(R"({"event":"input","time":0.25,"input":3,"on":true,"cause":"stimulus","cause_line":1,)"
               R"("text":"input 3 ON: stimulus, line 1"})") != std::string::npos);
  CHECK(t.find(R"({"event":"input","time":0.5,"input":2,"on":true,"cause":"rule","cause_line":2,)"
               R"("text":"input 2 ON: rule of line 2"})") != std::string::npos);
}

TEST_CASE("the run log keeps every input change with its cause and the step it fell in", "[run][inputs]") {
  auto run = runOfCauses();
  REQUIRE(run->runToEnd().ok());
  REQUIRE(run->log());
  const auto& changes = run->log()->inputChanges;
  REQUIRE(changes.size() == 3);
  CHECK(changes[0].at == 250'000);
  CHECK(changes[0].step == 1);  // during the DELAY, the second step
  CHECK(changes[0].cause == rs::runtime::InputCause{rs::runtime::InputCause::Kind::Stimulus, 3, true, 1, {}});
  CHECK(changes[1].at == 500'000);
  CHECK(changes[1].cause.kind == rs::runtime::InputCause::Kind::Rule);
  CHECK(changes[1].cause.line == 2);
  CHECK(changes[2].at == 2'000'000);
  CHECK(changes[2].step == 2);
}

TEST_CASE("an input set from outside the program is reported as set", "[run][inputs]") {
  auto run = runOfCauses();
  rs::runtime::RunUntil one;
  one.moreSteps = 1;
  run->runUntil(one);
  REQUIRE(run->rig().setInput(6, true));
  REQUIRE(run->runToEnd().ok());
  REQUIRE(run->log());
  const auto& changes = run->log()->inputChanges;
  REQUIRE(changes.size() == 4);
  CHECK(changes[0].cause.kind == rs::runtime::InputCause::Kind::Set);
  CHECK(changes[0].cause.input == 6);
  CHECK(rs::runtime::inputChangeText(changes[0].cause) == "input 6 ON: set by the debugger");
}
