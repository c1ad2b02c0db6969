// The main binary and its helper executables (tools/cli/lib/helpers.h): the main
// binary loads none of the libraries the helpers need (ldd, checked against
// the helper's own list so that the check can fail; a static build's loads
// no shared library at all), a command run by a
// helper gives the same bytes as the whole command run in-process, a
// missing helper is a clear error, and an installed layout finds its helper.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/helpers.h"

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
  command += " </dev/null >" + helperQuoted(out) + " 2>" + helperQuoted(err);
  const int status = std::system(command.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readBytes(out);
  r.err = readBytes(err);
  return r;
}

const fs::path kHelpersMainBinary = ROBOTSIM_BINARY;
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
  CHECK((main.out.find("statically linked") != std::string::npos) == bool(ROBOTSIM_STATIC_COMMAND));
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
