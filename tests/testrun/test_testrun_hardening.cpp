// `robotsim test` against what students, classmates and their files can
// do to it (issue 26, issue 23): symbolic links out of a submissions folder,
// golden traces outside the test's folder, file names with terminal
// escapes, compile errors that keep the compiler's hint, runs that never
// end under grading, and one expectation line of a million terms.
#include <catch2/catch.hpp>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "diag/source_file.h"
#include "tests/cli/cli_support.h"
#include "tools/testrun/expectation.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;
namespace fs = std::filesystem;

// An assignment any program that ends passes: the grading of what it is
// handed is what these tests look at.
std::string writeAssignment(const TempDir& dir) {
  return dir.write("assignment.rstest", "scenario it ends\nexpect: finished\n");
}

bool hasEscape(const std::string& text) { return text.find('\x1b') != std::string::npos; }

}  // namespace

TEST_CASE(
    "robotsim test --spec refuses a submission's symbolic link that leaves its folder, by name, and grades the "
    "others",
    "[testrun][cli]") {
  const TempDir dir;
  const std::string spec = writeAssignment(dir);
  fs::create_directories(dir.path() / "submissions" / "bob");
  fs::create_directories(dir.path() / "elsewhere");
  dir.write("secret.rsp", "; SECRET-LINE of another student's work\nEND\n");
  dir.write("elsewhere/x.rsp", "; SECRET-FOLDER\nEND\n");
  const std::string ok = dir.write("submissions/alice.rsp", "END\n");
  dir.write("submissions/bob/main.rsp", "END\n");
  const fs::path s = dir.path() / "submissions";
  fs::create_symlink("/etc/passwd", s / "passwd.rsp");
  fs::create_symlink("../secret.rsp", s / "copied.rsp");
  fs::create_symlink("../../secret.rsp", s / "bob" / "deep.rsp");
  fs::create_symlink("alice.rsp", s / "same.rsp");         // inside: graded
  fs::create_symlink("bob/main.rsp", s / "bob_main.rsp");  // inside: graded
  fs::create_symlink("../elsewhere", s / "away");          // a folder outside
  fs::create_symlink("loop.rsp", s / "loop.rsp");          // never ends
  fs::create_symlink("/etc/passwd", s / "\x1b]0;pwned\x07.rsp");

  const CliResult r = runCli({"test", "--spec", spec, s.string()});
  INFO(r.out << r.err);
  CHECK(r.code == 2);  // refused submissions could not start
  // Nothing of what the links point at is read, let alone printed.
  CHECK(r.out.find("root:") == std::string::npos);
  CHECK(r.out.find("SECRET") == std::string::npos);
  CHECK_FALSE(hasEscape(r.out));
  const std::string folder = fs::canonical(s).string();
  for (const std::string& want :
       {s.string() + "/passwd.rsp: error: a symbolic link to /etc/passwd, outside the folder graded (" + folder +
            "): not graded\n",
        s.string() + "/copied.rsp: error: a symbolic link to " + fs::canonical(dir.path() / "secret.rsp").string() +
            ", outside the folder graded",
        s.string() + "/bob/deep.rsp: error: a symbolic link to " + fs::canonical(dir.path() / "secret.rsp").string() +
            ", outside",
        s.string() + "/away: error: a symbolic link to " + fs::canonical(dir.path() / "elsewhere").string() +
            ", outside",
        s.string() + "/loop.rsp: error: a symbolic link that cannot be followed (",
        s.string() + "/\\x1b]0;pwned\\x07.rsp: error: a symbolic link to /etc/passwd",
        std::string("  hint: a submission is graded inside its folder: copy the file there instead of linking to it\n"),
        ok + " [it ends] PASSED", s.string() + "/same.rsp [it ends] PASSED",
        s.string() + "/bob_main.rsp [it ends] PASSED", s.string() + "/bob/main.rsp [it ends] PASSED",
        std::string("4 passed, 0 failed, 6 errors in ")}) {
    INFO(want);
    CHECK(r.out.find(want) != std::string::npos);
  }

  // A file named on the command line (as a shell's glob names them) is
  // confined to its own folder.
  const CliResult named = runCli({"test", "--spec", spec, (s / "passwd.rsp").string(), ok});
  CHECK(named.code == 2);
  CHECK(named.out.find("root:") == std::string::npos);
  CHECK(named.out.find("1 passed, 0 failed, 1 error in ") != std::string::npos);

  // CSV and JSON carry the refusal as the row's problem: no points of the
  // spec's one, its scenario's cells empty.
  const CliResult csv = runCli({"test", "--spec", spec, s.string(), "--format", "csv"});
  CHECK(csv.out.find("\"" + s.string() + "/passwd.rsp\",0,1,0,1,,,\"" + s.string() +
                     "/passwd.rsp: a symbolic link to /etc/passwd, outside the folder graded") != std::string::npos);
  CHECK_FALSE(hasEscape(csv.out));
}

TEST_CASE(
    "robotsim test --spec: a submission's cell directive names a library cell or a file in its own folder, and no byte of "
    "anything else is read or printed",
    "[testrun][cli]") {
  const TempDir dir;
  const std::string spec = writeAssignment(dir);  // sets no 'test: cell'
  fs::create_directories(dir.path() / "submissions" / "eve");
  fs::create_directories(dir.path() / "submissions" / "other");
  dir.write("submissions/other/secret.rsd", "SECRET-OTHER one two\nSECRET-OTHER three\n");
  dir.write("submissions/eve/notes.txt", "SECRET-NOTES: not a description\n");
  dir.write("submissions/eve/mine.rsd", "WORKCELL mine\n  ROBOT rhino-scara AT 0 0 0\nEND\n");
  // A file of the submission's own folder named .rsd but holding other text:
  // at most its offending token is quoted, cut, never a line of it.
  dir.write("submissions/eve/diary.rsd", "diary private words\n" + std::string(1000, 'W') + " more private\n");
  const fs::path eve = dir.path() / "submissions" / "eve";
  fs::create_symlink("/etc/passwd", eve / "pw.rsd");
  const auto submit = [&](const std::string& name, const std::string& cell) {
    return dir.write("submissions/eve/" + name + ".rsp", "; cell: " + cell + "\nEND\n");
  };
  const std::string passwd = submit("passwd", "/etc/passwd");
  const std::string environ = submit("environ", "/proc/self/environ");
  const std::string up = submit("up", "../other/secret.rsd");
  const std::string link = submit("link", "pw.rsd");
  const std::string notes = submit("notes", "notes.txt");
  const std::string escaped = submit("escaped", "\x1b]0;pwned\x07");
  const std::string library = submit("library", "scara-pick");
  const std::string own = submit("own", "mine.rsd");
  submit("diary", "diary.rsd");

  const CliResult r = runCli({"test", "--spec", spec, eve.string()});
  INFO(r.out << r.err);
  for (const std::string& leak : {std::string("root:"), std::string("PATH="), std::string("HOME="), std::string("SECRET"),
                                 std::string("\x1b"), std::string("private"), std::string(65, 'W')}) {
    INFO(leak);
    CHECK(r.out.find(leak) == std::string::npos);
    CHECK(r.err.find(leak) == std::string::npos);
  }
  for (const std::string& want :
       {passwd + ":1:9: error: the cell '/etc/passwd' is refused: it is an absolute path\n",
        environ + ":1:9: error: the cell '/proc/self/environ' is refused: it is an absolute path\n",
        up + ":1:9: error: the cell '../other/secret.rsd' is refused: it leads outside the submission's folder\n",
        link + ":1:9: error: the cell 'pw.rsd' is refused: it leads outside the submission's folder\n",
        escaped + ":1:9: error: the cell '\\x1b]0;pwned\\x07' is refused",
        (eve / "notes.txt").string() + ": error: not a robot or workcell description",
        std::string("  hint: a submission's '; cell:' names a library robot or cell (robotsim list) or a .rsd file in "
                    "its own folder\n"),
        library + " [it ends] PASSED", own + " [it ends] PASSED",
        (eve / "diary.rsd").string() + ":1:1: error: expected LINK, OBJECT, GRIPPER, ROBOT or WORKCELL, found 'diary'\n",
        (eve / "diary.rsd").string() + ":2:1: error: expected LINK, OBJECT, GRIPPER, ROBOT or WORKCELL, found '" +
            std::string(64, 'W') + "\u2026'\n"}) {
    INFO(want);
    CHECK(r.out.find(want) != std::string::npos);
  }

  // Outside grading the directive is the author's own: a file that is not a
  // description is still refused whole, never quoted line by line.
  const CliResult run = runCli({"check", passwd});
  CHECK(run.code == 2);
  CHECK(run.err.find("/etc/passwd: error: not a robot or workcell description") != std::string::npos);
  CHECK(run.err.find("root:") == std::string::npos);
  const CliResult cell = runCli({"check", library, "--cell", "/proc/self/environ"});
  CHECK(cell.code == 2);
  CHECK(cell.err.find("PATH=") == std::string::npos);
}

TEST_CASE("robotsim test: a golden trace lives under its test's folder, for reading and for --update",
          "[testrun][cli]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "tests");
  fs::create_directories(dir.path() / "elsewhere");
  const std::string outside = dir.write("elsewhere/t.trace", "SECRET-TRACE-LINE\n");
  const std::string absolute = dir.write("tests/absolute.rsp", "; expect: trace " + outside + "\nEND\n");
  const std::string up = dir.write("tests/up.rsp", "; expect: trace ../elsewhere/t.trace\nEND\n");
  fs::create_symlink("../elsewhere", dir.path() / "tests" / "golden");
  const std::string linked = dir.write("tests/linked.rsp", "; expect: trace golden/new.trace\nEND\n");

  ::unsetenv("CI");
  const CliResult r = runCli({"test", (dir.path() / "tests").string(), "--update"});
  INFO(r.out);
  CHECK(r.code == 2);
  CHECK(r.out.find("SECRET-TRACE-LINE") == std::string::npos);
  CHECK(r.out.find(absolute +
                   ":1:17: error: a golden trace lives under the test's folder: name it relative to the "
                   "folder, without '..' leading out, not '" +
                   outside + "'\n") != std::string::npos);
  CHECK(r.out.find(up + ":1:17: error: a golden trace lives under the test's folder") != std::string::npos);
  CHECK(r.out.find(linked + ":1:3: error: the golden trace " + (dir.path() / "tests/golden/new.trace").string() +
                   " leads out of the test's folder (to " +
                   (fs::canonical(dir.path() / "elsewhere") / "new.trace").string() + "): refused\n") !=
        std::string::npos);
  CHECK(r.out.find("updated") == std::string::npos);
  CHECK_FALSE(fs::exists(dir.path() / "elsewhere" / "new.trace"));  // --update wrote nothing out there
  CHECK(rs::testing::readBytes(outside) == "SECRET-TRACE-LINE\n");

  // Under the folder, in a subfolder: written by --update, then checked.
  fs::create_directories(dir.path() / "tests" / "traces");
  const std::string inside = dir.write("tests/inside.rsp", "; expect: trace traces/inside.trace\nSET N 1\nEND\n");
  CHECK(runCli({"test", inside, "--update"}).code == 0);
  CHECK(rs::testing::readBytes(dir.file("tests/traces/inside.trace")).find("N=1") != std::string::npos);
  CHECK(runCli({"test", inside}).code == 0);
}

TEST_CASE("robotsim test: a golden trace compared as the run writes it, wherever the two first differ",
          "[testrun][cli]") {
  const TempDir dir;
  const std::string program = dir.write("t.rsp", "; expect: trace t.trace\nSET N 1\nSET N 2\nEND\n");
  const CliResult traced = runCli({"run", program, "--trace"});
  const std::string trace = traced.out.substr(0, traced.out.find("run of "));
  std::vector<std::string> lines;  // the header, SET, SET, END
  for (std::size_t at = 0, nl; (nl = trace.find('\n', at)) != std::string::npos; at = nl + 1)
    lines.push_back(trace.substr(at, nl - at));
  REQUIRE(lines.size() == 4);
  const std::string last = lines[3];

  // The golden file one line longer: the trace ends where it goes on.
  dir.write("t.trace", trace + "EXTRA\n");
  CHECK(runCli({"test", program}).out.find("at its line 5: expected 'EXTRA', got ''") != std::string::npos);
  // One line shorter: the trace goes on where it ends.
  dir.write("t.trace", trace.substr(0, trace.size() - last.size() - 1));
  CHECK(runCli({"test", program}).out.find("at its line 4: expected '', got '" + last + "'") != std::string::npos);
  // Its last newline missing: the same line, as far as the text goes.
  dir.write("t.trace", trace.substr(0, trace.size() - 1));
  CHECK(runCli({"test", program}).out.find("at its line 4: expected '" + last + "', got '" + last + "'") !=
        std::string::npos);
  // A byte changed in the middle of line 2.
  std::string changed = trace;
  const std::size_t second = lines[0].size() + 1;
  changed[second + lines[1].size() / 2] ^= 1;
  dir.write("t.trace", changed);
  CHECK(runCli({"test", program})
            .out.find("at its line 2: expected '" + changed.substr(second, lines[1].size()) + "', got '" + lines[1] +
                      "'") != std::string::npos);
  dir.write("t.trace", trace);
  CHECK(runCli({"test", program}).code == 0);
}

TEST_CASE("robotsim test: file and scenario names with terminal escapes are printed escaped", "[testrun][cli]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "s");
  const std::string name = "\x1b[31mred\x1b[0m.rsp";
  dir.write("s/" + name, "; expect: time = 1\nEND\n");  // fails: the run takes no time
  const std::string spec = dir.write("a.rstest", "scenario \x1b[1mbold\x1b[0m runs\nexpect: finished\n");
  const std::string shown = (dir.path() / "s").string() + "/\\x1b[31mred\\x1b[0m.rsp";

  const CliResult plain = runCli({"test", (dir.path() / "s").string(), "--coverage"});
  INFO(plain.out);
  CHECK_FALSE(hasEscape(plain.out));
  CHECK(plain.out.find(shown + " FAILED\n") != std::string::npos);
  CHECK(plain.out.find("coverage of " + shown + ":") != std::string::npos);

  const CliResult graded = runCli({"test", "--spec", spec, (dir.path() / "s").string()});
  INFO(graded.out);
  CHECK_FALSE(hasEscape(graded.out));
  CHECK(graded.out.find(shown + " [\\x1b[1mbold\\x1b[0m runs] PASSED") != std::string::npos);
  CHECK(graded.out.find(shown + "     1/1") != std::string::npos);  // the table
  CHECK_FALSE(hasEscape(runCli({"test", "--spec", spec, (dir.path() / "s").string(), "--format", "csv"}).out));
}

TEST_CASE("robotsim test --shard: every part's names, and a bad --shard itself, are printed escaped",
          "[testrun][cli]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "s");
  // Eight files, which fall four in each part of two (FNV-1a's lowest bit
  // is the parity of its bytes' lowest bits: here the digit's); each fails,
  // so its problem is printed too.
  std::vector<std::string> shown;
  for (int i = 0; i < 8; ++i) {
    dir.write("s/\x1b[31mp" + std::to_string(i) + ".rsp", "; expect: time = 1\nEND\n");
    shown.push_back((dir.path() / "s").string() + "/\\x1b[31mp" + std::to_string(i) + ".rsp");
  }
  const std::string spec = writeAssignment(dir);
  std::size_t seen = 0, graded = 0;
  for (const char* part : {"1/2", "2/2"}) {
    const CliResult plain = runCli({"test", "--shard", part, (dir.path() / "s").string()});
    INFO(part << "\n" << plain.out << plain.err);
    CHECK(plain.code == 1);
    CHECK_FALSE(hasEscape(plain.out + plain.err));
    for (const std::string& name : shown)
      if (plain.out.find(name + " FAILED\n" + name + ":1:3: error: expected the run's simulated time") !=
          std::string::npos)
        ++seen;
    for (const char* format : {"text", "csv"}) {
      const CliResult g =
          runCli({"test", "--spec", spec, "--shard", part, "--format", format, (dir.path() / "s").string()});
      INFO(format << "\n" << g.out << g.err);
      CHECK(g.code == 0);
      CHECK_FALSE(hasEscape(g.out + g.err));
      for (const std::string& name : shown) graded += g.out.find(name) != std::string::npos;
    }
  }
  CHECK(seen == shown.size());        // each name once, escaped, over the two parts
  CHECK(graded == 2 * shown.size());  // and once in each format

  // The part asked for is quoted back escaped too, with a hint.
  const CliResult bad = runCli({"test", "--shard", "1/\x1b[2J", (dir.path() / "s").string()});
  CHECK(bad.code == 2);
  CHECK(bad.err ==
        "robotsim: error: --shard takes K/N with 1 <= K <= N, e.g. 2/4, not '1/\\x1b[2J'\n"
        "  hint: K is this job's part and N how many parts: --shard 2/4 is the second of four\n");
  CHECK(bad.out.empty());
}

TEST_CASE(
    "robotsim test: a compile error keeps the compiler's hint, the expect-error hint only for a negative "
    "example, never when grading",
    "[testrun][cli]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "s");
  const std::string student = dir.write("s/student.rsp", "        GOTO PIKC\nPICK:   END\n");
  const std::string spec = writeAssignment(dir);
  // What `robotsim check` says.
  const CliResult check = runCli({"check", student});
  REQUIRE(check.err.find("  hint: did you mean 'PICK'?\n") != std::string::npos);

  const CliResult graded = runCli({"test", "--spec", spec, (dir.path() / "s").string()});
  INFO(graded.out);
  CHECK(graded.out.find(student + ":1:14: error: undefined label 'PIKC'") != std::string::npos);
  CHECK(graded.out.find("  hint: did you mean 'PICK'?\n") != std::string::npos);
  CHECK(graded.out.find("expect-error") == std::string::npos);
  CHECK(graded.out.find("unexpected") == std::string::npos);

  const CliResult own = runCli({"test", student});
  CHECK(own.out.find("  hint: did you mean 'PICK'?\n") != std::string::npos);
  CHECK(own.out.find("expect-error") == std::string::npos);

  // A negative example with an error it does not expect: the compiler's
  // hint when it has one, else how to expect the error.
  const std::string negative = dir.write("n.rsp",
                                         "        GOTO 9              ; expect-error: undefined label\n"
                                         "        GOTO PIKC           ; expect-error: undefined label 'PIKC'\n"
                                         "        MOVX 1 2 3 4 5\n"
                                         "PICK:   END\n");
  const CliResult n = runCli({"test", negative});
  INFO(n.out);
  CHECK(n.out.find(negative + ":1:14: error: unexpected compile error: line number 9 does not exist") !=
        std::string::npos);
  CHECK(n.out.find("  hint: mark an error a negative example must have with '; expect-error: TEXT' on its line\n") !=
        std::string::npos);
  CHECK(n.out.find(negative + ":3:9: error: unexpected compile error: unknown instruction 'MOVX' (did you mean "
                              "MOVE?)") != std::string::npos);
}

TEST_CASE(
    "robotsim test --spec: a submission that never ends stops at the grading limits, which a scenario may "
    "raise",
    "[testrun][cli]") {
  const TempDir dir;
  fs::create_directories(dir.path() / "s");
  // 0.25 s a round trip of E (50 units at 400 a second, each way): the
  // time limit comes first: after 480 rounds, at 120 s, the next move
  // passes it and ends at 120.125 s.
  dir.write("s/moves.rsp", "LOOP:   MOVE 50 0 0 0 0\n        MOVE -50 0 0 0 0\n        GOTO LOOP\n");
  // 1 ms a round of 10 instructions: the step limit comes first, after
  // 100,000 rounds (1,000,000 instructions), at 100 s.
  std::string spins = "LOOP:   DELAY 0.001\n";
  for (int i = 0; i < 8; ++i) spins += "        ADD N 1\n";
  dir.write("s/spins.rsp", spins + "        GOTO LOOP\n");
  // No time at all: stopped after 100,000 instructions at one instant.
  dir.write("s/polls.rsp", "LOOP:   JMPIN 1 ON DONE\n        GOTO LOOP\nDONE:   END\n");
  const std::string spec = writeAssignment(dir);
  const CliResult r = runCli({"test", "--spec", spec, (dir.path() / "s").string()});
  INFO(r.out);
  CHECK(r.code == 1);
  CHECK(r.out.find("expected the run to end: finished; it ended: time limit at line 1, 120.125 s") !=
        std::string::npos);
  CHECK(r.out.find("  hint: grading stops a run at 120 simulated seconds; a scenario that needs longer says 'test: "
                   "max-time SECONDS'\n") != std::string::npos);
  CHECK(r.out.find("expected the run to end: finished; it ended: step limit at line 1, 100.000 s") !=
        std::string::npos);
  CHECK(r.out.find("expected the run to end: finished; it ended: clock standing still at line 1, 0.000 s: 100000 "
                   "instructions ran at 0.000 s without the simulated clock moving") != std::string::npos);
  CHECK(r.out.find("  hint: give the loop a DELAY, a move or a WAITFOR, or a way out\n") != std::string::npos);
  CHECK(r.out.find("  hint: grading stops a run after 1000000 instructions; a scenario that needs more says 'test: "
                   "max-steps N'\n") != std::string::npos);

  // The scenario's own limits replace the grading ones (and get no hint).
  const std::string longer =
      dir.write("longer.rstest", "scenario long\ntest: max-time 130\ntest: max-steps 2000\nexpect: finished\n");
  const CliResult l = runCli({"test", "--spec", longer, (dir.path() / "s").string()});
  INFO(l.out);
  CHECK(l.out.find("time limit at line 1, 130.125 s") != std::string::npos);
  CHECK(l.out.find("step limit at line 1, 0.200 s") != std::string::npos);  // 2,000: 200 rounds
  CHECK(l.out.find("hint: grading stops") == std::string::npos);
  // Plain `robotsim test` keeps its own defaults: 3,600 s.
  const CliResult own = runCli({"test", (dir.path() / "s/moves.rsp").string()});
  CHECK(own.out.find("time limit at line 1, 3600.125 s") != std::string::npos);
}

TEST_CASE("expectations: one line of a million motor terms is read in linear time, each column right", "[testrun]") {
  // 1,000,000 terms E=0 D=1 C=2 ... (5 letters), the last one bad: the
  // error must be at its column, counted here independently.
  std::string line = "; expect: motors";
  const char letters[] = {'E', 'D', 'C', 'B', 'A'};
  for (int i = 0; i < 999'999; ++i) line += " " + std::string(1, letters[i % 5]) + "=" + std::to_string(i % 7);
  const std::size_t badColumn = line.size() + 2;  // after the blank, 1-based
  line += " E=x\n";
  const std::clock_t started = std::clock();  // CPU time: a loaded machine's waits do not count
  const rs::testrun::ParsedExpectations p = rs::testrun::parseExpectations(rs::diag::SourceFile("m.rsp", line));
  const double seconds = static_cast<double>(std::clock() - started) / CLOCKS_PER_SEC;
  REQUIRE(p.errors.size() == 1);
  CHECK(p.errors[0].pos == rs::diag::Pos{1, static_cast<std::uint32_t>(badColumn)});
  CHECK(p.errors[0].message == "expected a motor and its encoder value, e.g. E=100, got 'E=x'");
  // Linear: well under a second in Release; the quadratic reader took hours. The
  // bound is loose on purpose (sanitizers, a loaded machine): the figure is
  // benchmark 11 in docs/performance.md.
  CHECK(seconds < 10);
}

TEST_CASE("robotsim test: a million motor terms, all of them checked", "[testrun][cli]") {
  const TempDir dir;
  std::string line = "; expect: motors";
  for (int i = 0; i < 1'000'000; ++i) line += i % 2 ? " D=0" : " E=100";
  const std::string pass = dir.write("pass.rsp", line + "\nMOVE 100 0 0 0 0\nEND\n");
  const std::string fail = dir.write("fail.rsp", line + " D=1\nMOVE 100 0 0 0 0\nEND\n");
  const std::clock_t started = std::clock();  // CPU time: a loaded machine's waits do not count
  const CliResult p = runCli({"test", pass});
  const double seconds = static_cast<double>(std::clock() - started) / CLOCKS_PER_SEC;
  CHECK(p.code == 0);
  CHECK(p.out.find(pass + " PASSED (2 expectations,") != std::string::npos);
  CHECK(seconds < 10);
  const CliResult f = runCli({"test", fail});
  CHECK(f.code == 1);
  // At the failing term's own column, counted from the text (all ASCII): the blank, then D.
  CHECK(f.out.find(fail + ":1:" + std::to_string(line.size() + 2) +
                   ": error: expected motor D at 1 at the end; it is at 0 at line 3, 0.250 s\n") != std::string::npos);
}

TEST_CASE("robotsim test: times written with more than three decimals are printed as written", "[testrun][cli]") {
  // Before: `during 0..0.0005` was printed `0.000..0.001 s`, a window the
  // test never wrote, and a moment inside it `0.000 s`.
  const TempDir dir;
  const std::string program = dir.write("t.rsp",
                                        "; test: input 1=ON@0.0003\n"                      // 1
                                        "; expect: input 1 off during 0.0001..0.0005\n"    // 2: ON at 0.0003
                                        "; expect: input 1 on at 0.0002\n"                 // 3: still OFF
                                        "; expect: time <= 0.0005\n"                       // 4: ends at 1 s
                                        "        DELAY 1\n"                                // 5
                                        "        END\n");                                  // 6
  const CliResult r = runCli({"test", program});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  for (const std::string& want :
       {program + ":2:3: error: expected input 1 OFF during 0.0001..0.0005 s; it was ON at 0.0003 s (line 5 running; "
        "ON since 0.0003 s: stimulus)\n",
        program + ":3:3: error: expected input 1 ON at 0.0002 s; it was OFF then (line 5 running)\n",
        program + ":4:3: error: expected the run's simulated time <= 0.0005 s; it ended at line 6, 1.000 s\n"}) {
    CAPTURE(want);
    CHECK(r.out.find(want) != std::string::npos);
  }
}

TEST_CASE("robotsim test: a motor of a long `expect: motors` line is reported at its own column", "[testrun][cli]") {
  // Before: at column 3 (the `expect`), whichever of a thousand terms it was.
  const TempDir dir;
  std::string line = "; expect: motors";
  for (int i = 0; i < 1000; ++i) line += i % 2 ? " D=0" : " E=100";
  line += " Q=5 D=7";
  // Columns counted here from the text (1-based; all ASCII).
  const std::size_t unknownCol = line.find("Q=5") + 1, wrongCol = line.rfind("D=7") + 1;
  const std::string program = dir.write("m.rsp", line + "\n        MOVE 100 0 0 0 0\n        END\n");
  const CliResult r = runCli({"test", program});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find(program + ":1:" + std::to_string(unknownCol) + ": error: the robot has no motor Q (its motors: ") !=
        std::string::npos);
  CHECK(r.out.find(program + ":1:" + std::to_string(wrongCol) + ": error: expected motor D at 7 at the end; it is at 0") !=
        std::string::npos);
  CHECK(r.out.find(program + ":1:3:") == std::string::npos);
}
