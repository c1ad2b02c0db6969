// What a teach write does to the files around the program (issue 26): a
// 0600 program and its .bak stay 0600 (both became 0644), a link planted
// at PROG.rsp.tmp is never followed (its target was overwritten), one
// planted at PROG.rsp.bak is replaced rather than followed, a program that
// is a link stays a link, and nothing is left beside the program.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "tests/cli/cli_support.h"
#include "tools/teach/program_file.h"

namespace {

namespace fs = std::filesystem;

unsigned permissionsOf(const std::string& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

std::string addPoint(rs::teach::ProgramFile& file, const std::string& name) {
  const std::vector<std::int32_t> values{1, 2, 3, 4};
  return file.change([&](rs::teach::PointsText& p) { return p.add(name, values); });
}

}  // namespace

TEST_CASE("a teach write keeps a 0600 program 0600, and its .bak too", "[teach][write]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "        END\nPOINTS\n");
  REQUIRE(::chmod(path.c_str(), 0600) == 0);
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
  REQUIRE(file);
  REQUIRE(addPoint(*file, "A").empty());
  REQUIRE(addPoint(*file, "B").empty());
  CHECK(permissionsOf(path) == 0600);
  CHECK(permissionsOf(path + ".bak") == 0600);
  CHECK(rs::testing::readBytes(path + ".bak") == "        END\nPOINTS\n");
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir.path())) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"p.rsp", "p.rsp.bak"});
}

TEST_CASE("teach never follows a link planted at PROG.rsp.tmp or PROG.rsp.bak", "[teach][write]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "        END\nPOINTS\n");
  const std::string victim1 = dir.write("victim1", "precious 1\n");
  const std::string victim2 = dir.write("victim2", "precious 2\n");
  fs::create_symlink(victim1, path + ".tmp");
  fs::create_symlink(victim2, path + ".bak");
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
  REQUIRE(file);
  REQUIRE(addPoint(*file, "A").empty());
  CHECK(rs::testing::readBytes(victim1) == "precious 1\n");
  CHECK(rs::testing::readBytes(victim2) == "precious 2\n");
  CHECK_FALSE(fs::is_symlink(path + ".bak"));
  CHECK(rs::testing::readBytes(path + ".bak") == "        END\nPOINTS\n");
  CHECK(rs::testing::readBytes(path).ends_with("\nA 1 2 3 4\n"));
}

TEST_CASE("a program that is a link stays a link, its target is taught", "[teach][write]") {
  const rs::testing::TempDir dir;
  fs::create_directories(dir.path() / "src");
  const std::string target = dir.write("src/p.rsp", "        END\nPOINTS\n");
  REQUIRE(::chmod(target.c_str(), 0640) == 0);
  fs::create_symlink("src/p.rsp", dir.file("p.rsp"));
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(dir.file("p.rsp"));
  REQUIRE(file);
  REQUIRE(addPoint(*file, "A").empty());
  CHECK(fs::is_symlink(dir.file("p.rsp")));
  CHECK(rs::testing::readBytes(target).ends_with("\nA 1 2 3 4\n"));
  CHECK(permissionsOf(target) == 0640);
}
