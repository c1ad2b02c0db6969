// robotsim --version and robotsim version: each fact checked against its
// own source, read here independently: the version against CMakeLists.txt's
// project() line, the build type against the build's CMakeCache.txt, the
// commit against git, the library against the tree's stdlib/; and the VS
// Code extension's version against the same project() line.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/support/build_facts.h"

namespace {

namespace fs = std::filesystem;
using rs::testing::runCli;

std::string versionFileText(const fs::path& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// CMakeLists.txt's `project(robotsim VERSION x.y.z ...)`.
std::string versionOfProject() {
  const std::string text = versionFileText(fs::path(ROBOTSIM_SOURCE_DIR) / "CMakeLists.txt");
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex(R"(project\(robotsim VERSION ([0-9]+\.[0-9]+\.[0-9]+))")));
  return m[1];
}

// The build type the tree running this test was configured with.
std::string buildTypeOfThisBuild() {
  const fs::path cache = fs::path(rs::testing::robotsimBinary()).parent_path() / "CMakeCache.txt";
  const std::string text = versionFileText(cache);
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex(R"(CMAKE_BUILD_TYPE:[A-Z]+=([A-Za-z]*))")));
  return m[1];
}

// Whether git knows `hash` as a commit of the source tree's repository
// (false without git): the commit a build names need not be HEAD, when
// commits were made since the last build.
bool isCommitOfSourceTree(const std::string& hash) {
  const std::string command = std::string("git -C '") + ROBOTSIM_SOURCE_DIR + "' rev-parse --verify --quiet '" + hash +
                              "^{commit}' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

bool gitWorks() {
  return std::system((std::string("git -C '") + ROBOTSIM_SOURCE_DIR + "' rev-parse HEAD >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace

TEST_CASE("robotsim version --format json: version, commit, build type, library", "[cli][version]") {
  const auto r = runCli({"version", "--format", "json"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j.at("version") == versionOfProject());
  CHECK(j.at("buildType") == buildTypeOfThisBuild());
  std::string commit = j.at("commit");
  if (!gitWorks()) {
    CHECK(commit == "unknown");
  } else {
    const std::string suffix = "-modified";
    if (commit.size() > suffix.size() && commit.ends_with(suffix)) commit.resize(commit.size() - suffix.size());
    CHECK(std::regex_match(commit, std::regex("[0-9a-f]{12}")));
    CHECK(isCommitOfSourceTree(commit));
  }
  // This test binary runs from the build tree, whose share/robotsim/stdlib
  // is the source's stdlib/.
  REQUIRE(j.at("library").is_string());
  CHECK(fs::equivalent(fs::path(j.at("library").get<std::string>()), fs::path(ROBOTSIM_SOURCE_DIR) / "stdlib"));
}

TEST_CASE("robotsim --version is robotsim version, in text and in json", "[cli][version]") {
  const auto text = runCli({"version"});
  REQUIRE(text.code == 0);
  CHECK(runCli({"--version"}).out == text.out);
  CHECK(runCli({"--version", "--format=json"}).out == runCli({"version", "--format=json"}).out);
  const nlohmann::json j = nlohmann::json::parse(runCli({"version", "--format=json"}).out);
  // The text form says the same facts, one a line, the first as programs say it.
  std::istringstream lines(text.out);
  std::string line;
  std::getline(lines, line);
  CHECK(line == "robotsim " + j.at("version").get<std::string>());
  std::getline(lines, line);
  CHECK(line == "commit: " + j.at("commit").get<std::string>());
  std::getline(lines, line);
  CHECK(line == "build type: " + j.at("buildType").get<std::string>());
  std::getline(lines, line);
  CHECK(line == "library: " + j.at("library").get<std::string>());
  CHECK(!std::getline(lines, line));
}

TEST_CASE("robotsim version: a bad --format is exit 2 with the choices", "[cli][version]") {
  const auto r = runCli({"--version", "--format", "yaml"});
  CHECK(r.code == 2);
  CHECK(r.err.find("yaml") != std::string::npos);
  CHECK(r.err.find("json") != std::string::npos);
  CHECK(r.out.empty());
}

TEST_CASE("the VS Code extension's version is the project's", "[cli][version]") {
  const nlohmann::json manifest =
      nlohmann::json::parse(versionFileText(fs::path(ROBOTSIM_SOURCE_DIR) / "editors/vscode/package.json"));
  // A release changes project(VERSION) in CMakeLists.txt and these fields together.
  CHECK(manifest.at("version") == versionOfProject());
  const nlohmann::json lock =
      nlohmann::json::parse(versionFileText(fs::path(ROBOTSIM_SOURCE_DIR) / "editors/vscode/package-lock.json"));
  CHECK(lock.at("version") == versionOfProject());
  CHECK(lock.at("packages").at("").at("version") == versionOfProject());
}

TEST_CASE("robotsim --version prints the library's path and the places looked in with control bytes escaped",
          "[cli][version]") {
  // A folder whose name holds ESC [ 2 J (clear the screen) and a BEL: before,
  // both lines printed them raw to the terminal.
  const rs::testing::TempDir dir;
  const fs::path prefix = dir.path() / "x\x1b[2Jy\x07z";
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "robotsim" / "stdlib");  // an empty library is still one
  const fs::path found = prefix / "bin" / "robotsim";
  fs::copy_file(rs::testing::robotsimBinary(), found);
  // The same escape in a folder with no library near it: "not found (looked in ...)".
  fs::create_directories(prefix / "alone" / "x");
  const fs::path alone = prefix / "alone" / "x" / "robotsim";
  fs::copy_file(rs::testing::robotsimBinary(), alone);
  const std::string shown = (dir.path() / "x\\x1b[2Jy\\x07z").string();
  for (const fs::path& exe : {found, alone}) {
    for (const char* format : {"text", "json"}) {
      CAPTURE(exe.string(), format);
      const std::string out = dir.file("version.out");
      const std::string command = "'" + exe.string() + "' --version --format " + format + " >'" + out + "' 2>&1";
      REQUIRE(std::system(command.c_str()) == 0);
      const std::string printed = rs::testing::readBytes(out);
      INFO(printed);
      CHECK(printed.find('\x1b') == std::string::npos);
      CHECK(printed.find('\x07') == std::string::npos);
      if (std::string_view(format) == "text") {
        CHECK(printed.find(exe == found ? "library: " + shown : "library: not found (looked in " + shown) !=
              std::string::npos);
      } else {
        const nlohmann::json j = nlohmann::json::parse(printed);
        if (exe == found) {
          REQUIRE(j.at("library").is_string());
          CHECK(j.at("library").get<std::string>().rfind(shown, 0) == 0);
        } else {
          REQUIRE(j.at("libraryLookedIn").is_array());
          CHECK(j.at("libraryLookedIn").at(0).get<std::string>().rfind(shown, 0) == 0);
        }
      }
    }
  }
}
