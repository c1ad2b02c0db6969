// Bad URDF input: every file of tests/urdf/data_read that is not a robot is
// answered with one positioned error (line and column of the XML element)
// and a hint, never a crash (docs/models.md, "Reading URDF", "Bad input").
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <fstream>

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

TEST_CASE("urdf read bad: a file above the size limit is refused before it is parsed", "[urdf]") {
  const std::filesystem::path big = std::filesystem::temp_directory_path() / "robotsim-test-big.urdf";
  {
    std::ofstream out(big, std::ios::binary);
    const std::string line(1023, ' ');
    for (std::size_t i = 0; i < (rs::urdf::kMaxUrdfBytes >> 10) + 1; ++i) out << line << '\n';
  }
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfFile(big, {});
  std::filesystem::remove(big);
  CHECK_FALSE(read.robot);
  REQUIRE(read.diagnostics.size() == 1);
  CHECK(read.diagnostics[0].message.find("limit") != std::string::npos);
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
