// `check --strict`: every kind of warning a compile or a run can give fails
// the check (docs/cli.md, "check"). The kinds, from a search of the tree for
// warning severities (compiler/, launch/, runtime/, tools/cli/lib/):
//   compile: unassigned-variable, unreachable-code (compiler/program/translator.cpp),
//            home-collision (compiler/description/library.cpp, when the cell is loaded);
//   run:     collision (--collisions=warn, tools/cli/lib/run_warnings.cpp),
//            gripper-took-nothing (runtime/run/empty_close.cpp).
// For each: without --strict the check passes (exit 0) with a warning; with
// it the same text is an error marked [--strict], a compile warning stops
// everything before the run (exit 2), a run's fails the check (exit 1), and
// the JSON summary says "error".
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

// The library's SCARA on its table beside a post (20 x 200 x 20) that link
// 2 sweeps through when joint E turns to 600 (tests/collision's cell).
constexpr const char* kStrictPostCell = R"(
OBJECT post
  BOX 0 20 200 0 20 0
END
WORKCELL post-cell
  ROBOT rhino-scara  AT 0 750 0
  OBJECT table   AT -500 0 250
  OBJECT post    AT -150 750 120
END
)";

struct StrictCase {
  const TempDir dir;
  const std::string cell = dir.write("post-cell.rsd", kStrictPostCell);
  std::string program(const std::string& name, const std::string& text) const { return dir.write(name, text); }
};

// The check passes with the warning; --strict turns the same line into an
// error and the check fails with `code`; --format=json says so too.
void checkStrict(const std::vector<std::string>& args, const std::string& warning, int code) {
  const CliResult plain = runCli(args);
  INFO(plain.err);
  CHECK(plain.code == 0);
  CHECK(plain.err.find(": warning: " + warning) != std::string::npos);
  std::vector<std::string> strictArgs = args;
  strictArgs.push_back("--strict");
  const CliResult strict = runCli(strictArgs);
  INFO(strict.err);
  CHECK(strict.code == code);
  const std::size_t at = strict.err.find(": error: " + warning);
  REQUIRE(at != std::string::npos);
  CHECK(strict.err.substr(at, strict.err.find('\n', at) - at).ends_with(" [--strict]"));
  CHECK(strict.err.find(": warning: ") == std::string::npos);
  CHECK(strict.out.find(": ok (") == std::string::npos);
  strictArgs.push_back("--format=json");
  const CliResult json = runCli(strictArgs);
  CHECK(json.code == code);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["status"] == "error");
  bool listed = false;
  for (const auto& d : j["diagnostics"])
    listed = listed || (d["severity"] == "error" && d["message"].get<std::string>().starts_with(warning));
  CHECK(listed);
}

}  // namespace

TEST_CASE_METHOD(StrictCase, "check --strict: a variable never assigned", "[cli][strict]") {
  const std::string p = program("unassigned.rsp",
                                "        JMPVAR COUNT > 0 done\n"
                                "done:   END\n");
  checkStrict({"check", p}, "variable 'COUNT' is never assigned by SET or ADD; it is always 0", 2);
  CHECK(runCli({"check", p, "--strict"}).err.find(p + ":1:16: error: variable 'COUNT'") != std::string::npos);
}

TEST_CASE_METHOD(StrictCase, "check --strict: unreachable code", "[cli][strict]") {
  const std::string p = program("unreachable.rsp",
                                "        END\n"
                                "        MOVE 10 0 0 0 0\n");
  checkStrict({"check", p}, "unreachable code: nothing jumps here and END on line 1 does not continue", 2);
  CHECK(runCli({"check", p, "--strict"}).err.find(p + ":2:9: error: unreachable code") != std::string::npos);
}

TEST_CASE_METHOD(StrictCase, "check --strict: a robot that overlaps an object at home", "[cli][strict]") {
  // The post moved onto link 2, which lies along -x at home; collisions off,
  // so that the run itself has nothing to say.
  std::string text = kStrictPostCell;
  text.replace(text.find("AT -150 750 120"), 15, "AT -150 750 10 ");
  const std::string homeCell = dir.write("home-cell.rsd", text);
  const std::string p = program("still.rsp", "        DELAY 1\n        END\n");
  checkStrict({"check", p, "--cell", homeCell, "--collisions=off"},
              "robot 'rhino-scara' collides at its home pose: link 2 (rhino_scara_link2) overlaps object 2 (post)", 2);
  const CliResult strict = runCli({"check", p, "--cell", homeCell, "--collisions=off", "--strict"});
  CHECK(strict.err.find(homeCell + ":6:9: error: robot 'rhino-scara' collides") != std::string::npos);
  CHECK(strict.out.empty());  // nothing ran
}

TEST_CASE_METHOD(StrictCase, "check --strict: a collision the run went on after (--collisions=warn)", "[cli][strict]") {
  const std::string p = program("swing.rsp",
                                "        MOVETO 600 0 0 0 0\n"
                                "        MOVETO 0 0 0 0 0\n"
                                "        END\n");
  checkStrict({"check", p, "--cell", cell, "--collisions=warn"}, "collision at ", 1);
  // Both moves, each at its line, with the parts; the summary lists them.
  const CliResult strict = runCli({"check", p, "--cell", cell, "--collisions=warn", "--strict"});
  CHECK(strict.err.find(p + ":1:9: error: collision at ") != std::string::npos);
  CHECK(strict.err.find(p + ":2:9: error: collision at ") != std::string::npos);
  CHECK(strict.err.find("link 2 (rhino_scara_link2) hits object 2 (post), ") != std::string::npos);
  CHECK(strict.err.find(" deep (--collisions=warn: the run went on) [--strict]") != std::string::npos);
  CHECK(strict.out.find("  collisions      line 1, ") != std::string::npos);
  // In error mode the collision is the run's error, not a warning as well.
  const CliResult error = runCli({"check", p, "--cell", cell});
  CHECK(error.code == 1);
  CHECK(error.err.find("warning") == std::string::npos);
}

TEST_CASE_METHOD(StrictCase, "check --strict: a gripper that never took anything", "[cli][strict]") {
  const std::string p = program("grip.rsp",
                                "        MOVE 0 0 0 0 120\n"
                                "        END\n");
  checkStrict({"check", p, "--cell", cell}, "the gripper closed once but never took an object", 1);
  const CliResult strict = runCli({"check", p, "--cell", cell, "--strict"});
  CHECK(strict.err.find(p + ":1:9: error: the gripper closed once") != std::string::npos);
  // The run happened: the summary follows, with its gripper line.
  CHECK(strict.out.find("run of ") != std::string::npos);
  CHECK(strict.out.find("  gripper         closed once, took nothing") != std::string::npos);
}

TEST_CASE_METHOD(StrictCase, "a run's warning after compile warnings cut by --max-errors: the cut is noted once",
                 "[cli][strict]") {
  const std::string p = program("three.rsp",
                                "        JMPVAR A > 0 done\n"
                                "        JMPVAR B > 0 done\n"
                                "        JMPVAR C > 0 done\n"
                                "        MOVE 0 0 0 0 120\n"
                                "done:   END\n");
  const CliResult r = runCli({"check", p, "--cell", cell, "--max-errors", "1"});
  INFO(r.err);
  CHECK(r.code == 0);
  const std::string note = "robotsim: note: 2 more warnings not shown; --max-errors 0 shows all\n";
  const std::size_t at = r.err.find(note);
  REQUIRE(at != std::string::npos);
  CHECK(r.err.find(note, at + 1) == std::string::npos);
  CHECK(r.err.find(": warning: the gripper closed once") != std::string::npos);
}

TEST_CASE_METHOD(StrictCase, "check --strict passes a program without warnings", "[cli][strict]") {
  const std::string p = program("clean.rsp",
                                "        MOVETO 0 0 0 0 0\n"
                                "        END\n");
  const CliResult r = runCli({"check", p, "--cell", cell, "--strict"});
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find(": ok (") != std::string::npos);
}
