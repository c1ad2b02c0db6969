// `robotsim list` (issue 24): the library's robots, grippers, objects and
// workcells, one line each with what it is, and the search path it looked
// in; docs/models.md's table of the library says the same (this test keeps
// the two in step); --lib directories join the path, and a name found
// earlier hides a later one.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "compiler/description/library_listing.h"
#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using rs::testing::CliResult;
using rs::testing::runCli;

const fs::path kListStdlib = fs::path(ROBOTSIM_SOURCE_DIR) / "stdlib";

struct ListedRow {
  std::string kind, name, what;
  bool operator==(const ListedRow&) const = default;
};

// The entry lines of `robotsim list` (after the path), split in columns.
std::vector<ListedRow> listedRows(const std::string& out) {
  std::vector<ListedRow> rows;
  std::istringstream lines(out);
  std::string line;
  bool inPath = false;
  while (std::getline(lines, line)) {
    if (line.rfind("library path", 0) == 0) {
      inPath = true;
      continue;
    }
    if (inPath && line.rfind("  ", 0) == 0) continue;
    inPath = false;
    std::istringstream words(line);
    ListedRow r;
    words >> r.kind >> r.name;
    std::getline(words >> std::ws, r.what);
    rows.push_back(r);
  }
  return rows;
}

// The rows of docs/models.md's table under "## The library".
std::vector<ListedRow> documentedRows() {
  const std::string doc = rs::testing::readBytes((fs::path(ROBOTSIM_SOURCE_DIR) / "docs" / "models.md").string());
  const std::size_t section = doc.find("\n## The library\n");
  REQUIRE(section != std::string::npos);
  std::istringstream lines(doc.substr(section + 1, doc.find("\n## ", section + 1) - section));
  std::vector<ListedRow> rows;
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| kind", 0) == 0) continue;
    std::vector<std::string> cells;
    std::size_t at = 1;
    for (std::size_t bar; (bar = line.find(" |", at)) != std::string::npos; at = bar + 2) {
      std::string cell = line.substr(at, bar - at);
      cell.erase(0, cell.find_first_not_of(' '));
      cells.push_back(cell);
    }
    REQUIRE(cells.size() == 3);
    std::string name = cells[1];
    if (name.size() > 2 && name.front() == '`' && name.back() == '`') name = name.substr(1, name.size() - 2);
    rows.push_back({cells[0], name, cells[2]});
  }
  return rows;
}

}  // namespace

TEST_CASE("robotsim list: every library file, one line each, and the path searched", "[cli][list]") {
  ::unsetenv("ROBOTSIM_PATH");
  const CliResult r = runCli({"list"});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.rfind("library path (searched in this order):\n  " + kListStdlib.string() + "\n", 0) == 0);
  const std::vector<ListedRow> rows = listedRows(r.out);
  // Every .rsd of the library's kind folders is there, under its kind.
  std::map<std::string, std::string> kinds{
      {"robots", "robot"}, {"grippers", "gripper"}, {"objects", "object"}, {"workcells", "workcell"}};
  std::size_t files = 0;
  for (const auto& [folder, kind] : kinds)
    for (const auto& e : fs::directory_iterator(kListStdlib / folder)) {
      if (e.path().extension() != ".rsd") continue;
      ++files;
      const std::string name = e.path().stem().string();
      INFO(kind << " " << name);
      const std::string& kindWord = kind;  // a lambda cannot capture a structured binding before C++20's clang 16
      CHECK(std::count_if(rows.begin(), rows.end(), [&](const ListedRow& row) {
              return row.kind == kindWord && row.name == name && !row.what.empty();
            }) == 1);
    }
  CHECK(rows.size() == files);
  CHECK(std::find(rows.begin(), rows.end(),
                  ListedRow{"object", "block", "a 40 mm cube, the part the library's workcells pick and place."}) !=
        rows.end());
}

TEST_CASE("docs/models.md's table of the library is what robotsim list prints", "[cli][list][docs]") {
  ::unsetenv("ROBOTSIM_PATH");
  const CliResult r = runCli({"list"});
  const std::vector<ListedRow> listed = listedRows(r.out);
  const std::vector<ListedRow> documented = documentedRows();
  REQUIRE(documented.size() == listed.size());
  for (std::size_t i = 0; i < listed.size(); ++i) {
    INFO("row " << i + 1 << ": " << listed[i].kind << " " << listed[i].name);
    CHECK(documented[i] == listed[i]);
  }
}

TEST_CASE("robotsim list --lib: the directory joins the path, and a name found first hides a later one", "[cli][list]") {
  ::unsetenv("ROBOTSIM_PATH");
  const rs::testing::TempDir dir;
  std::filesystem::create_directories(dir.path() / "objects");
  dir.write("objects/crate.rsd", "; crate: a wooden crate\n; for parts.\n\nOBJECT crate\n  BOX 0 10 0 10 10 0\nEND\n");
  dir.write("objects/block.rsd", "; block: my own block. Bigger.\nOBJECT block\n  BOX 0 50 0 50 50 0\nEND\n");
  dir.write("notes.rsd", "; not named after what it defines\nOBJECT other\n  BOX 0 1 0 1 1 0\nEND\n");
  const std::string missing = (dir.path() / "nowhere").string();
  const CliResult r = runCli({"list", "--lib", dir.path().string(), "--lib", missing});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.out.find("  " + kListStdlib.string() + "\n  " + dir.path().string() + "\n  " + missing + "\n") !=
        std::string::npos);
  const std::vector<ListedRow> rows = listedRows(r.out);
  CHECK(std::find(rows.begin(), rows.end(), ListedRow{"object", "crate", "a wooden crate for parts."}) != rows.end());
  const auto block = std::find_if(rows.begin(), rows.end(), [](const ListedRow& row) { return row.name == "block"; });
  REQUIRE(block != rows.end());
  CHECK(block->what.find("hidden") == std::string::npos);  // the library's comes first ...
  REQUIRE(block + 1 != rows.end());
  CHECK((block + 1)->name == "block");  // ... the --lib one after it, hidden
  CHECK((block + 1)->what == "my own block. (hidden by the block above; from " +
                                 (dir.path() / "objects" / "block.rsd").string() + ")");
  CHECK(std::none_of(rows.begin(), rows.end(), [](const ListedRow& row) { return row.name == "other" || row.name == "notes"; }));
}

TEST_CASE("list: a header's first sentence, its lines joined, without NAME: before it", "[list]") {
  using rs::compiler::headerSummary;
  CHECK(headerSummary("; cell: a table\n; and a robot. More.\n", "cell") == "a table and a robot.");
  CHECK(headerSummary("; Big Arm: six axes (R R R).\n;\n; Later.\n", "big-arm") == "Big Arm: six axes (R R R).");
  CHECK(headerSummary("; no full stop\n\n; elsewhere. x\n", "x") == "no full stop");
  CHECK(headerSummary("OBJECT x\nEND\n", "x").empty());
  CHECK(headerSummary("; v1.5 of it. Then\n", "y") == "v1.5 of it.");
  CHECK(headerSummary("; arm: of the paper's Figs. 4-7 (its Fig. 2 kind). Lengths\n", "arm") ==
        "of the paper's Figs. 4-7 (its Fig. 2 kind).");
}

TEST_CASE("robotsim list: a file over 4 MiB is listed as the readers read it, one over their limit is named",
          "[cli][list]") {
  // Before, list read at most 4 MiB of a file and left a larger one out
  // without a word, while every command reads up to 64 MiB: an entry the
  // commands used was missing, and a name the path hid showed as active.
  ::unsetenv("ROBOTSIM_PATH");
  const rs::testing::TempDir dir;
  fs::create_directories(dir.path() / "objects");
  const std::string padding(std::size_t{5} << 20, ' ');  // 5 MiB of blanks after the block
  dir.write("objects/slab.rsd", "; slab: a big one.\nOBJECT slab\n  BOX 0 10 0 10 10 0\nEND\n" + padding + "\n");
  // Over the readers' limit: its size alone refuses it (a sparse file).
  const std::string huge = dir.write("objects/huge.rsd", "; huge: too big.\nOBJECT huge\n  BOX 0 1 0 1 1 0\nEND\n");
  fs::resize_file(huge, rs::compiler::kMaxDescriptionBytes + (std::size_t{1} << 20));
  const CliResult r = runCli({"list", "--lib", dir.path().string()});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  const std::vector<ListedRow> rows = listedRows(r.out);
  CHECK(std::find(rows.begin(), rows.end(), ListedRow{"object", "slab", "a big one."}) != rows.end());
  CHECK(std::none_of(rows.begin(), rows.end(), [](const ListedRow& row) { return row.name == "huge"; }));
  CHECK(r.err == huge + ": warning: not listed: file is 65 MiB; the limit is 64 MiB\n");
  // The same file is what `render` refuses, with the same reason.
  const CliResult render = runCli({"render", huge, "--dump-lines"});
  CHECK(render.code == 2);
  CHECK(render.err.find("file is 65 MiB; the limit is 64 MiB") != std::string::npos);
}
