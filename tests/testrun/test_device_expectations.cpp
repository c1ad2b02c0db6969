// `robotsim test`'s expectations on a cell's devices (issue 35): a
// sensor's ON edges, a conveyor's parts carried, a feeder's parts fed, a
// sink's parts taken, and a fed part's place at the end by its number.
//
// Worked out by hand from stdlib/workcells/adept-cell.rsd: the infeed
// runs at 100/s while output 1 is ON; the cell's blocks stand at x 0..40
// (object 2) and 150..190 (object 3), AT corners (0, 500, 620) and
// (150, 500, 620); the feeder puts a block (object 5: the cell's own
// objects are 1..4) with its AT corner at (-740, 500, 620) at 0 s; the beam
// is at x = 300. OUTSIG 1 ON; WAITFOR 1 ON: object 3's front (x 190)
// breaks the beam after 110 / 100 = 1.1 s, and the run ends there. So: 1
// ON edge, 1 part fed, none taken; every block on the belt has ridden 110:
// object 3's AT corner at x 260, object 5's at -630.
#include <catch2/catch.hpp>

#include <string>

#include "diag/source_file.h"
#include "tests/cli/cli_support.h"
#include "tools/testrun/expectation.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;
using rs::testrun::Compare;
using rs::testrun::DeviceKind;
using rs::testrun::ExpectKind;

rs::testrun::ParsedExpectations parseDeviceLines(const std::string& text) {
  return rs::testrun::parseExpectations(rs::diag::SourceFile("p.rsp", text));
}

const char* const kFirstBeam =
    "; test: cell adept-cell\n"
    "        OUTSIG 1 ON\n"
    "        WAITFOR 1 ON\n"
    "        END\n";

}  // namespace

TEST_CASE("device expectations: sensor, conveyor, feeder and sink counts are read with their name's column",
          "[testrun][devices]") {
  const auto p = parseDeviceLines(
      "; expect: sensor eye count 10\n"
      "; expect: sink done count >= 3\n"
      "; expect: FEEDER parts count <= 2\n"
      "; expect: conveyor outfeed count = 4\n");
  REQUIRE(p.errors.empty());
  REQUIRE(p.expectations.size() == 4);
  const auto& e = p.expectations;
  for (const auto& one : e) CHECK(one.kind == ExpectKind::DeviceCount);
  CHECK(e[0].device == DeviceKind::Sensor);
  CHECK(e[0].name == "eye");
  CHECK(e[0].nameCol == 18);  // "; expect: sensor " is 17 characters
  CHECK(e[0].compare == Compare::Equal);
  CHECK(e[0].count == 10);
  CHECK(e[1].device == DeviceKind::Sink);
  CHECK(e[1].compare == Compare::AtLeast);
  CHECK(e[1].count == 3);
  CHECK(e[2].device == DeviceKind::Feeder);
  CHECK(e[2].name == "parts");
  CHECK(e[2].compare == Compare::AtMost);
  CHECK(e[2].count == 2);
  CHECK(e[3].device == DeviceKind::Conveyor);
  CHECK(e[3].compare == Compare::Equal);
  CHECK(e[3].count == 4);
}

TEST_CASE("device expectations: a bad line is an error at its word", "[testrun][devices]") {
  const auto p = parseDeviceLines(
      "; expect: sensor eye 10\n"
      "; expect: sink\n"
      "; expect: feeder parts count -1\n"
      "; expect: sensor eye count 3 times\n");
  REQUIRE(p.errors.size() == 4);
  CHECK(p.errors[0].pos.line == 1);
  CHECK(p.errors[0].pos.col == 22);
  CHECK(p.errors[0].message == "expected 'count', got '10'");
  CHECK(p.errors[1].pos.line == 2);
  CHECK(p.errors[1].message.find("a device name") != std::string::npos);
  CHECK(p.errors[2].pos.line == 3);
  CHECK(p.errors[2].message.find("a count") != std::string::npos);
  CHECK(p.errors[3].pos.line == 4);
  CHECK(p.errors[3].pos.col == 30);
}

TEST_CASE("device expectations: counts at the end pass and fail with what the devices counted",
          "[testrun][devices][cli]") {
  const TempDir dir;
  const std::string passing = dir.write("pass.rsp", std::string(kFirstBeam) +
                                                        "; expect: sensor eye count 1\n"
                                                        "; expect: feeder parts count 1\n"
                                                        "; expect: sink done count 0\n"
                                                        "; expect: sink done count <= 0\n"
                                                        "; expect: time = 1.1\n");  // and the implied finished
  const CliResult ok = runCli({"test", passing});
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  CHECK(ok.out.find("PASSED (6 expectations, 1.100 s simulated)") != std::string::npos);

  const std::string failing = dir.write("fail.rsp", std::string(kFirstBeam) +
                                                        "; expect: sensor eye count 2\n"        // line 5
                                                        "; expect: sink done count >= 1\n"      // line 6
                                                        "; expect: feeder parts count <= 0\n"); // line 7
  const CliResult r = runCli({"test", failing});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find("fail.rsp:5:3: error: expected sensor eye count 2 (ON edges) at the end; it is 1 (the run ended "
                   "at line 4, 1.100 s)") != std::string::npos);
  CHECK(r.out.find("fail.rsp:6:3: error: expected sink done count >= 1 (parts taken) at the end; it is 0") !=
        std::string::npos);
  CHECK(r.out.find("fail.rsp:7:3: error: expected feeder parts count <= 0 (parts fed) at the end; it is 1") !=
        std::string::npos);
}

TEST_CASE("device expectations: a device the cell lacks is an error at its name with the cell's devices",
          "[testrun][devices][cli]") {
  const TempDir dir;
  const std::string program = dir.write("p.rsp", std::string(kFirstBeam) +
                                                     "; expect: conveyor belt count 1\n"  // line 5, name at 20
                                                     "; expect: sink eye count 1\n");     // a sensor's name, not a sink's
  const CliResult r = runCli({"test", program});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  const std::string hint =
      "  hint: the workcell's devices: sensor eye, conveyor infeed, conveyor outfeed, feeder parts, sink done\n";
  CHECK(r.out.find("p.rsp:5:20: error: the workcell has no conveyor 'belt'\n") != std::string::npos);
  CHECK(r.out.find("p.rsp:6:16: error: the workcell has no sink 'eye'\n") != std::string::npos);
  std::size_t hints = 0;
  for (std::size_t at = r.out.find(hint); at != std::string::npos; at = r.out.find(hint, at + 1)) ++hints;
  CHECK(hints == 2);

  // A cell without devices says so.
  const std::string plain = dir.write("q.rsp", "; test: cell scara-pick\n; expect: sensor eye count 0\n  END\n");
  const CliResult q = runCli({"test", plain});
  INFO(q.out << q.err);
  CHECK(q.code == 1);
  CHECK(q.out.find("q.rsp:2:18: error: the workcell has no sensor 'eye'") != std::string::npos);
  CHECK(q.out.find("hint: the workcell scara-pick has no devices") != std::string::npos);
}

TEST_CASE("device expectations: a fed part's place at the end by its number, and a number not in the cell",
          "[testrun][devices][cli]") {
  const TempDir dir;
  const std::string passing = dir.write("pass.rsp", std::string(kFirstBeam) +
                                                        "; expect: object 5 at -630 500 620\n"
                                                        "; expect: object 3 at 260 500 620\n"
                                                        "; expect: object 5 not held\n");
  const CliResult ok = runCli({"test", passing});
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);

  const std::string failing = dir.write("fail.rsp", std::string(kFirstBeam) +
                                                        "; expect: object 5 at -740 500 620\n"  // line 5: it rode 110
                                                        "; expect: object 6 at 0 0 0\n");       // line 6: never fed
  const CliResult r = runCli({"test", failing});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find("fail.rsp:5:3: error: expected object 5 (block) at (-740.00, 500.00, 620.00) within 0.5 at the "
                   "end; it is at (-630.00, 500.00, 620.00)") != std::string::npos);
  CHECK(r.out.find("fail.rsp:6:3: error: the workcell has no object 6 at the end: a part a sink took, or one never "
                   "fed, is not in the cell (the run ended at line 4, 1.100 s)") != std::string::npos);
}

TEST_CASE("device expectations: objects by name are the ones in the cell, not a feeder's empty slots",
          "[testrun][devices][cli]") {
  // Three blocks in the cell at the end (objects 2, 3 and 5); a failure
  // names those three and their places, none of the feeder's parked slots.
  const TempDir dir;
  const std::string program = dir.write("p.rsp", std::string(kFirstBeam) + "; expect: object block at 0 0 0\n");
  const CliResult r = runCli({"test", program});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find("expected objects 2, 3, 5 (block) at (0.00, 0.00, 0.00) within 0.5 at the end; they are at "
                   "(110.00, 500.00, 620.00), (260.00, 500.00, 620.00), (-630.00, 500.00, 620.00)") !=
        std::string::npos);
}

TEST_CASE("device expectations: an object by the name AS gives it, and the summary says both names",
          "[testrun][devices][cli]") {
  // adept-cell: OBJECT conveyor AT -750 0 750 AS infeed (object 1), and
  // AT -750 0 -450 AS outfeed (object 4); fixtures, so still there.
  const TempDir dir;
  const std::string program = dir.write("p.rsp", std::string(kFirstBeam) +
                                                     "; expect: object outfeed at -750 0 -450\n"
                                                     "; expect: object infeed at -750 0 750\n"
                                                     "; expect: object conveyor at -750 0 -450\n");
  const CliResult ok = runCli({"test", program});
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  // The outfeed is not where the infeed is: the name picks the one object.
  const std::string wrong = dir.write("w.rsp", std::string(kFirstBeam) + "; expect: object outfeed at -750 0 750\n");
  const CliResult r = runCli({"test", wrong});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find("expected object 4 (conveyor) at (-750.00, 0.00, 750.00)") != std::string::npos);
  const CliResult summary = runCli({"run", program, "--cell", "adept-cell"});
  CHECK(summary.out.find("object 4        conveyor AS outfeed at (-750, 0, -450)") != std::string::npos);
  const CliResult json = runCli({"run", program, "--cell", "adept-cell", "--format", "json"});
  CHECK(json.out.find(R"("as":"outfeed")") != std::string::npos);
}
