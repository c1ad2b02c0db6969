// Bad URDF input: every file of tests/urdf/data_read that is not a robot is
// answered with one positioned error (line and column of the XML element)
// and a hint, never a crash (docs/models.md, "Reading URDF", "Bad input").
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <fstream>

#include "model/urdf/urdf_read_remote.h"
#include "tests/cli/cli_support.h"
#include "tests/urdf/urdf_read_test_util.h"

namespace {

struct Bad {
  const char* file;
  unsigned line, col;
  const char* says;
};

}  // namespace

TEST_CASE("urdf read bad: a positioned error with a hint for each kind of bad file", "[urdf]") {
  const Bad cases[] = {
      {"not_urdf.urdf", 2, 1, "its root element is <svg>, not <robot>"},
      {"bad_xml.urdf", 2, 1, "not well-formed XML"},
      {"xacro.urdf", 2, 1, "run xacro first"},
      {"unknown_type.urdf", 4, 3, "unknown type 'screw'"},
      {"loop.urdf", 5, 3, "the joints make a loop: joint 'ba' leads back to link 'a'"},
      {"two_roots.urdf", 2, 3, "Two root links"},
      {"missing_parent.urdf", 5, 3, "parent link [nowhere]"},
      {"zero_axis.urdf", 4, 3, "axis of zero length"},
      {"not_finite.urdf", 6, 5, "'nan' is not a finite number"},
      {"floating.urdf", 3, 3, "joint 'free' is floating"},
      {"planar.urdf", 3, 3, "joint 'slide' is planar"},
      {"mimic_bad.urdf", 4, 3, "joint 'j2' mimics 'j1' with multiplier 2"},
      {"not_a_mesh.urdf", 2, 3, "not a mesh robotsim can read"},
  };
  for (const Bad& c : cases) {
    INFO(c.file);
    const rs::urdf::UrdfRead read = urdftest::readData(c.file);
    CHECK_FALSE(read.robot);
    REQUIRE(read.diagnostics.size() >= 1);
    const rs::diag::Diagnostic& d = read.diagnostics.front();
    INFO(d.message);
    CHECK(d.severity == rs::diag::Severity::Error);
    CHECK(d.pos.line == c.line);
    CHECK(d.pos.col == c.col);
    CHECK((d.message + " " + d.hint).find(c.says) != std::string::npos);
    CHECK_FALSE(d.hint.empty());
    CHECK(d.file == urdftest::dataRead(c.file).string());
  }
}

// The issue's "a 100 MB URDF": 100,000,000 bytes, made sparse (its size
// set, no byte written), refused by its size before a byte is read, with
// urdf_read.h's one error and a hint. 100,000,000 / 2^20 = 95.37: "95.4
// MiB". That the refusal costs no time is measured in bench/ (`robotsim_bench
// urdf`), not here.
TEST_CASE("urdf read bad: a 100 MB URDF file is refused by its size, with a hint", "[urdf]") {
  rs::testing::TempDir dir;
  const std::string big = dir.write("big.urdf", "<robot name=\"big\">\n");
  std::filesystem::resize_file(big, 100'000'000);
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfFile(big, {});
  CHECK_FALSE(read.robot);
  REQUIRE(read.diagnostics.size() == 1);
  const rs::diag::Diagnostic& d = read.diagnostics[0];
  CHECK(d.severity == rs::diag::Severity::Error);
  CHECK(d.code == "urdf-size");
  CHECK(d.file == big);
  CHECK(d.pos.line == 0);  // the whole file: no line of it was read
  CHECK(d.message == "the URDF file is 95.4 MiB (100000000 bytes), more than the 64 MiB a URDF file may be: it is not read");
  CHECK(d.hint.find("check that this is the robot's URDF file") != std::string::npos);
}

// An editor's unsaved text over the limit (the language server's overlay)
// is refused before the helper is run: the helper would stop reading at the
// limit and robotsim's writing of the rest would find no reader (SIGPIPE).
// A MiB over the limit, more than a pipe holds.
TEST_CASE("urdf read bad: a text over the limit is refused in this process, the helper not run", "[urdf]") {
  const std::string text(rs::urdf::kMaxUrdfBytes + (std::size_t{1} << 20), ' ');
  const rs::urdf::UrdfRead direct = rs::urdf::readUrdfText(text, "buffer.urdf", {});
  const rs::urdf::UrdfRead helped = rs::urdf::readUrdfInHelper("buffer.urdf", {}, &text);
  for (const rs::urdf::UrdfRead* read : {&direct, &helped}) {
    CHECK_FALSE(read->robot);
    REQUIRE(read->diagnostics.size() == 1);
    CHECK(read->diagnostics[0].code == "urdf-size");
    CHECK(read->diagnostics[0].message.find("(68157440 bytes), more than the 64 MiB") != std::string::npos);
    CHECK_FALSE(read->diagnostics[0].hint.empty());
  }
}

TEST_CASE("urdf read bad: a FIFO is refused, not waited on", "[urdf]") {
  const std::filesystem::path fifo = std::filesystem::temp_directory_path() / "robotsim-test-urdf.fifo.urdf";
  std::filesystem::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfFile(fifo, {});
  std::filesystem::remove(fifo);
  CHECK_FALSE(read.robot);
  CHECK(read.diagnostics.size() == 1);
}

TEST_CASE("urdf read bad: a link that is two joints' child is an error at the second joint", "[urdf]") {
  const std::string text = R"(<robot name="r">
  <link name="a"/><link name="b"/>
  <joint name="one" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="two" type="fixed"><parent link="a"/><child link="b"/></joint>
</robot>
)";
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfText(text, "two_parents.urdf", {});
  CHECK_FALSE(read.robot);
  REQUIRE(read.diagnostics.size() == 1);
  CHECK(read.diagnostics[0].pos == rs::diag::Pos{4, 3});
  CHECK(read.diagnostics[0].message == "link 'b' is the child of joints 'one' and 'two'");
}
