// The main binary and its helper executables (tools/cli/lib/helpers.h): the main
// binary loads none of the libraries the helpers need (ldd, checked against
// the helper's own list so that the check can fail; a static build's loads
// no shared library at all), a command run by a
// helper gives the same bytes as the whole command run in-process, a
// missing helper is a clear error, and an installed layout finds its helper.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/helper_handshake.h"
#include "tools/cli/lib/helpers.h"
#include "tests/support/build_facts.h"

namespace {

namespace fs = std::filesystem;
using rs::testing::CliResult;
using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

std::string helperQuoted(const std::string& word) { return "'" + word + "'"; }

// `program args...` as a process, its streams captured in `dir`.
CliResult runProcess(const TempDir& dir, const std::string& program, const std::vector<std::string>& args) {
  std::string command = helperQuoted(program);
  for (const std::string& a : args) command += " " + helperQuoted(a);
  const std::string out = dir.file("process.out"), err = dir.file("process.err");
  // Bounded: before, a helper linked back to robotsim exec'd itself for ever.
  command = "timeout 60 " + command + " </dev/null >" + helperQuoted(out) + " 2>" + helperQuoted(err);
  const int status = std::system(command.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readBytes(out);
  r.err = readBytes(err);
  return r;
}

const fs::path kHelpersMainBinary = rs::testing::robotsimBinary();
const fs::path kHelpersRender = kHelpersMainBinary.parent_path() / "libexec" / "robotsim" / "robotsim-render";

}  // namespace

TEST_CASE("the main binary links none of the libraries only the helpers use", "[cli][helpers]") {
  TempDir dir;
  const CliResult main = runProcess(dir, "ldd", {kHelpersMainBinary.string()});
  const CliResult helper = runProcess(dir, "ldd", {kHelpersRender.string()});
  REQUIRE(main.code == 0);
  REQUIRE(helper.code == 0);
  INFO("ldd robotsim:\n" << main.out);
  // ROBOTSIM_STATIC (the default outside the sanitizer build): static-pie.
  CHECK((main.out.find("statically linked") != std::string::npos) == rs::testing::staticCommand());
  for (const char* library : {"libcairo", "libssl", "libncurses", "libedit.", "libbrotli", "libcpp-httplib", "libX11"}) {
    CAPTURE(library);
    CHECK(main.out.find(library) == std::string::npos);
  }
  // The same words in the helper's list: the check above can fail.
  INFO("ldd robotsim-render:\n" << helper.out);
  for (const char* library : {"libcairo", "libssl", "libncurses", "libedit.", "libbrotli"}) {
    CAPTURE(library);
    CHECK(helper.out.find(library) != std::string::npos);
  }
}

TEST_CASE("a command run by its helper gives the bytes the whole command gives in-process", "[cli][helpers]") {
  TempDir dir;
  // A picture, an animation page, a bad input and a help page: output
  // files, both streams and the exit code.
  const std::vector<std::vector<std::string>> commands{
      {"render", "scara-pick", "-o", "@.svg"},
      {"animate", ROBOTSIM_SOURCE_DIR "/examples/stack_blocks.rsp", "--cell", "scara-pick", "-o", "@.html"},
      {"render", "no-such-cell", "-o", "@.png"},
      {"teach", "--help"},
      {"debug", "--help"},
  };
  for (const std::vector<std::string>& words : commands) {
    std::vector<std::string> viaHelper, inProcess;
    for (const std::string& w : words) {
      if (w.rfind('@', 0) == 0) {
        viaHelper.push_back(dir.file("helper" + w.substr(1)));
        inProcess.push_back(dir.file("inprocess" + w.substr(1)));
      } else {
        viaHelper.push_back(w);
        inProcess.push_back(w);
      }
    }
    CAPTURE(words);
    CliResult a = runProcess(dir, kHelpersMainBinary.string(), viaHelper);
    const CliResult b = runCli(inProcess);
    // The summary line names the output file, which differs by name only.
    for (std::size_t at = 0; (at = a.out.find(dir.file("helper"), at)) != std::string::npos;)
      a.out.replace(at, dir.file("helper").size(), dir.file("inprocess"));
    CHECK(a.code == b.code);
    CHECK(a.out == b.out);
    CHECK(a.err == b.err);
    const std::string& last = words.back();
    if (last.rfind('@', 0) == 0) {
      const std::string made = readBytes(dir.file("helper" + last.substr(1)));
      CHECK(made == readBytes(dir.file("inprocess" + last.substr(1))));
      if (words[1] == "no-such-cell") {
        CHECK(a.code == 2);
        CHECK(made.empty());
      } else {
        CHECK(a.code == 0);
        CHECK(!made.empty());
      }
    }
  }
}

TEST_CASE("a missing helper names the files looked for and how to get them", "[cli][helpers]") {
  TempDir dir;
  fs::create_directories(dir.path() / "bin");
  const fs::path copy = dir.path() / "bin" / "robotsim";
  fs::copy_file(kHelpersMainBinary, copy);
  const CliResult r = runProcess(dir, copy.string(), {"render", "scara-pick", "-o", dir.file("missing.png")});
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  INFO(r.err);
  CHECK(r.err.rfind("robotsim: error: 'render' runs in a helper program that is missing", 0) == 0);
  for (const fs::path& looked : rs::cli::helperCandidates(copy, "render")) CHECK(r.err.find(looked.string()) != std::string::npos);
  CHECK(r.err.find((dir.path() / "bin" / "libexec" / "robotsim" / "robotsim-render").string()) != std::string::npos);
  CHECK(r.err.find("hint: reinstall robotsim") != std::string::npos);
  CHECK(!fs::exists(dir.file("missing.png")));
  // The commands of the main binary itself still run.
  const CliResult help = runProcess(dir, copy.string(), {"help", "END"});
  CHECK(help.code == 0);
  CHECK(help.out == runCli({"help", "END"}).out);
}

TEST_CASE("an installed robotsim finds its helper in LIBEXECDIR/robotsim", "[cli][helpers]") {
  TempDir dir;
  fs::create_directories(dir.path() / "bin");
  const fs::path copy = dir.path() / "bin" / "robotsim";
  fs::copy_file(kHelpersMainBinary, copy);
  const fs::path installed = rs::cli::helperCandidates(copy, "teach").front();
  // The installed layout's place, not the build tree's.
  CHECK(installed.parent_path() != copy.parent_path() / "libexec" / "robotsim");
  fs::create_directories(installed.parent_path());
  fs::create_symlink(kHelpersRender, installed);
  const CliResult r = runProcess(dir, copy.string(), {"teach", "--help"});
  CHECK(r.code == 0);
  CHECK(r.out == runCli({"teach", "--help"}).out);
  CHECK(r.err.empty());
}

TEST_CASE("only the main binary's table leaves rows to helpers", "[cli][helpers]") {
  const char* const argv[] = {"robotsim", "render", "scara-pick"};
  // The tests' table is the helpers' (every row has its function).
  CHECK(rs::cli::commandLeftToHelper(rs::cli::commandTable(), 3, argv) == nullptr);
  const rs::cli::Command rows[] = {{"render", "draws", nullptr, nullptr, true}, {"check", "checks", nullptr, nullptr}};
  CHECK(rs::cli::commandLeftToHelper(rows, 3, argv) == &rows[0]);
  const char* const check[] = {"robotsim", "check"};
  CHECK(rs::cli::commandLeftToHelper(rows, 2, check) == nullptr);
  CHECK(rs::cli::commandLeftToHelper(rows, 1, argv) == nullptr);
  bool anyInHelper = false;
  for (const rs::cli::Command& row : rs::cli::commandTable()) anyInHelper = anyInHelper || row.inHelper;
  CHECK(anyInHelper);
}

namespace {

// A copy of the main binary at `exe`, alone (a static-pie: no library needed).
void copyMainBinary(const fs::path& exe) {
  fs::create_directories(exe.parent_path());
  fs::copy_file(kHelpersMainBinary, exe);
}

// A shell script at `path` that leaves `marker` behind when it runs, and
// says `says` (a planted helper).
void plantScript(const fs::path& path, const fs::path& marker, const std::string& says = "") {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "#!/bin/sh\necho ran >> '" << marker.string() << "'\n" << (says.empty() ? "" : "echo '" + says + "'\n");
  fs::permissions(path, fs::perms::owner_all);
}

}  // namespace

TEST_CASE("a lone robotsim in D/x/ never runs D/libexec/robotsim's programs", "[cli][helpers]") {
  // Before: `D/x/robotsim render` ran D/x/../libexec/robotsim/robotsim-render,
  // a folder that is no part of a lone copy (as root: "PLANTED HELPER RAN").
  TempDir dir;
  const fs::path lone = dir.path() / "x" / "robotsim";
  copyMainBinary(lone);
  const fs::path marker = dir.path() / "planted-ran";
  plantScript(dir.path() / "libexec" / "robotsim" / "robotsim-render", marker);
  const CliResult r = runProcess(dir, lone.string(), {"render", "scara-pick", "-o", dir.file("p.png")});
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(!fs::exists(marker));
  CHECK(r.err.rfind("robotsim: error: 'render' runs in a helper program that is missing: looked for\n  " +
                        (dir.path() / "x" / "libexec" / "robotsim" / "robotsim-render").string() + "\n  hint:",
                    0) == 0);
  CHECK(rs::cli::helperCandidates(lone, "render") ==
        std::vector<fs::path>{dir.path() / "x" / "libexec" / "robotsim" / "robotsim-render"});
}

TEST_CASE("a program at a helper's name that is not robotsim's own helper is refused, the command not run",
          "[cli][helpers]") {
  // Before: /bin/true there gave exit 0 and no output, as if the picture
  // had been drawn.
  TempDir dir;
  const fs::path exe = dir.path() / "bin" / "robotsim";
  copyMainBinary(exe);
  const fs::path helper = rs::cli::helperCandidates(exe, "render").front();
  fs::create_directories(helper.parent_path());
  const auto refusal = [&] {
    const CliResult r = runProcess(dir, exe.string(), {"render", "scara-pick", "-o", dir.file("p.png")});
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(!fs::exists(dir.file("p.png")));
    CHECK(r.err.find("hint: reinstall robotsim") != std::string::npos);
    return r.err;
  };
  fs::create_symlink("/bin/true", helper);
  CHECK(refusal() == "robotsim: error: 'render' runs in a helper program, and " + helper.string() +
                         " did not answer robotsim's handshake (it printed nothing and exited with status 0)\n"
                         "  hint: reinstall robotsim (its helpers are part of it); in a build tree, `cmake --build "
                         "BUILD --target robotsim` builds them; a copied robotsim needs the libexec/robotsim folder at "
                         "one of those places\n");
  // One that answers like a helper of another build, or prints something else.
  fs::remove(helper);
  const fs::path marker = dir.path() / "ran";
  plantScript(helper, marker, "robotsim-helper 0.0.1 0123456789ab Debug");
  CHECK_THAT(refusal(), Catch::Contains("is the helper of another build of robotsim (it says 'robotsim-helper 0.0.1 "
                                        "0123456789ab Debug'; this robotsim is 'robotsim-helper "));
  CHECK(rs::testing::readBytes(marker.string()) == "ran\n");  // asked once, never run with the command's arguments
  fs::remove(helper);
  plantScript(helper, marker, "\x1b[2J hello");
  const std::string garbage = refusal();
  CHECK_THAT(garbage, Catch::Contains("did not answer robotsim's handshake (it printed "));
  CHECK(garbage.find('\x1b') == std::string::npos);
  // Not a file at all: a FIFO there is refused without waiting on it.
  fs::remove(helper);
  REQUIRE(::mkfifo(helper.c_str(), 0700) == 0);
  CHECK_THAT(refusal(), Catch::Contains(helper.string() + " is a FIFO (a named pipe), not a regular file"));
}

TEST_CASE("a helper linked back to robotsim is refused, not exec'd for ever", "[cli][helpers]") {
  // Before: 1,398 execve in 3 s, and no end.
  TempDir dir;
  const fs::path exe = dir.path() / "bin" / "robotsim";
  copyMainBinary(exe);
  const fs::path helper = rs::cli::helperCandidates(exe, "teach").front();
  fs::create_directories(helper.parent_path());
  fs::create_symlink(exe, helper);
  const std::string expected = "robotsim: error: 'teach' runs in a helper program, and " + helper.string() +
                               " is robotsim itself (a link back to it?), not its helper\n";
  CliResult r = runProcess(dir, exe.string(), {"teach", "--help"});
  CHECK(r.code == 2);
  CHECK(r.err.rfind(expected, 0) == 0);
  // A hard link is the same file by another name.
  fs::remove(helper);
  fs::create_hard_link(exe, helper);
  r = runProcess(dir, exe.string(), {"teach", "--help"});
  CHECK(r.code == 2);
  CHECK(r.err.rfind(expected, 0) == 0);
}

TEST_CASE("the helper handshake: the helper answers with this build's line, the main binary never does",
          "[cli][helpers]") {
  TempDir dir;
  const CliResult helper = runProcess(dir, kHelpersRender.string(), {std::string(rs::cli::kHelperHandshakeWord)});
  CHECK(helper.code == 0);
  CHECK(helper.out == rs::cli::helperHandshakeLine());
  CHECK(helper.out.rfind("robotsim-helper ", 0) == 0);
  const CliResult main = runProcess(dir, kHelpersMainBinary.string(), {std::string(rs::cli::kHelperHandshakeWord)});
  CHECK(main.code == 2);
  CHECK(main.out.empty());
}
