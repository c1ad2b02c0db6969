// Formatting never changes a program's meaning and is idempotent: every
// example is formatted, compiled before and after to the same image bytes,
// and formatted again to the same text.
#include <catch2/catch.hpp>

#include <filesystem>

#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/program_analysis.h"
#include "vm/image_file.h"

namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> imageBytes(const std::string& name, const std::string& text, const std::string& cell) {
  rs::launch::ProgramRequest request;
  rs::testing::TempDir dir;
  request.file = dir.write(fs::path(name).filename().string(), text);
  request.cell = cell;
  const rs::launch::LoadedProgram loaded = rs::launch::loadProgram(request);
  REQUIRE(loaded.ok());
  rs::vm::Image image = *loaded.image;
  image.sourceName.clear();  // the temporary file's name
  return rs::vm::writeImage(image);
}

}  // namespace

TEST_CASE("formatting every example keeps its image and is idempotent", "[lsp][formatting]") {
  int formatted = 0;
  for (const auto& entry : fs::recursive_directory_iterator(std::string(ROBOTSIM_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".rsp") continue;
    const std::string path = entry.path().string();
    const std::string before = rs::testing::readBytes(path);
    // The cell robotsim test runs it on ("; test: cell NAME"), if any.
    const std::size_t at = before.find("; test: cell ");
    const std::string cell = at == std::string::npos ? "" : before.substr(at + 13, before.find('\n', at) - at - 13);
    INFO(path);
    rs::launch::ProgramRequest probe;
    probe.file = path;
    probe.cell = cell;
    if (!rs::launch::loadProgram(probe).ok()) continue;  // the examples of failing programs
    const std::optional<std::string> once = rs::lsp::formatProgram(before);
    REQUIRE(once);
    const std::optional<std::string> twice = rs::lsp::formatProgram(*once);
    REQUIRE(twice);
    CHECK(*twice == *once);
    CHECK(imageBytes(path, *once, cell) == imageBytes(path, before, cell));
    ++formatted;
  }
  CHECK(formatted >= 15);
}

TEST_CASE("formatting lays out labels, instructions, comments and points in columns", "[lsp][formatting]") {
  const std::string messy =
      "; title stays\n"
      "start: SET   N 0 ; count\n"
      "                ; continues the comment\n"
      "a_long_label:\tMOVE 1 2 3 4 5\n"
      "   ; in the code column\n"
      "\tGOTO start   ;jump\n"
      "POINTS\n"
      "P 1 -20 300 0 0\n"
      "LONGER -1000 2 3 4 120 ; far\n";
  // Label column: "a_long_label:" (13) + 1 = 14. Points: names 6 wide, the
  // value columns 5, 3, 3, 1 and 3 wide, two blanks before each. Comment
  // column: the longest code with a comment is the LONGER row, 31 + 2 = 33,
  // so the minimum, 36, stands.
  const auto sp = [](std::size_t n) { return std::string(n, ' '); };
  const std::string want = "; title stays\n"
                           "start:" + sp(8) + "SET N 0" + sp(15) + "; count\n" +
                           sp(36) + "; continues the comment\n"
                           "a_long_label: MOVE 1 2 3 4 5\n" +
                           sp(14) + "; in the code column\n" +
                           sp(14) + "GOTO start" + sp(12) + ";jump\n"
                           "POINTS\n"
                           "P" + sp(11) + "1  -20  300  0    0\n"
                           "LONGER  -1000    2    3  4  120" + sp(5) + "; far\n";
  const std::optional<std::string> got = rs::lsp::formatProgram(messy);
  REQUIRE(got);
  CHECK(*got == want);
  CHECK(rs::lsp::formatProgram(want) == want);
}

TEST_CASE("formatting refuses what it cannot keep the meaning of", "[lsp][formatting]") {
  CHECK_FALSE(rs::lsp::formatProgram("END\xFF\n"));
  CHECK_FALSE(rs::lsp::formatProgram("END\rSET N 1\n"));  // a lone CR
  CHECK(rs::lsp::formatProgram("        END\r\n; x\r\n") == std::string("        END\r\n; x\r\n"));
}

namespace {

// LSP edits made to a text (ASCII, LF: characters are bytes).
std::string withEdits(std::string text, const rs::lsp::Json& edits) {
  const auto offset = [&](const rs::lsp::Json& p) {
    std::size_t at = 0;
    for (int l = 0; l < p["line"].get<int>(); ++l) at = text.find('\n', at) + 1;
    return at + p["character"].get<std::size_t>();
  };
  for (auto e = edits.rbegin(); e != edits.rend(); ++e) {  // edits come in order: last first keeps offsets
    const std::size_t from = offset((*e)["range"]["start"]), to = offset((*e)["range"]["end"]);
    text.replace(from, to - from, (*e)["newText"].get<std::string>());
  }
  return text;
}

rs::lsp::Reply formatted(const std::string& text) {
  const rs::lsp::Document doc("file:///f.rsp", rs::lsp::Language::Program, 1, text);
  const rs::lsp::ProgramAnalysis analysis("f.rsp", text, rs::lsp::CellCache().get(""), std::nullopt);
  return rs::lsp::formatting({doc, analysis, rs::lsp::Encoding::Utf16});
}

}  // namespace

TEST_CASE("formatting edits: one a run of changed lines, one in all past a thousand", "[lsp][formatting]") {
  // Lines 1-3 change together, line 5 alone: two edits.
  const std::string few = "END\n  MOVE 1 2 3 4 5\n SET N 1\n   ADD N 1\n        END\n  END\n";
  const rs::lsp::Json two = std::get<rs::lsp::Json>(formatted(few));
  REQUIRE(two.size() == 2);
  CHECK(two[0]["range"] == rs::lsp::Json::parse(R"({"start":{"line":0,"character":0},"end":{"line":3,"character":10}})"));
  CHECK(two[0]["newText"] == "        END\n        MOVE 1 2 3 4 5\n        SET N 1\n        ADD N 1");
  CHECK(two[1]["range"] == rs::lsp::Json::parse(R"({"start":{"line":5,"character":0},"end":{"line":5,"character":5}})"));
  CHECK(withEdits(few, two) == *rs::lsp::formatProgram(few));
  // Every other line changes, 1,500 times: one edit from the first to the last.
  std::string many;
  for (int i = 0; i < 1500; ++i) many += " ADD N 1\n        ADD N 1\n";
  many += "        END\n";
  const rs::lsp::Json one = std::get<rs::lsp::Json>(formatted(many));
  REQUIRE(one.size() == 1);
  CHECK(one[0]["range"]["start"] == rs::lsp::Json::parse(R"({"line":0,"character":0})"));
  CHECK(one[0]["range"]["end"] == rs::lsp::Json::parse(R"({"line":2998,"character":8})"));
  CHECK(withEdits(many, one) == *rs::lsp::formatProgram(many));
}

TEST_CASE("formatting refuses a document over 64 MiB with a message", "[lsp][formatting]") {
  // One comment line: cheap to compile, over the limit.
  const std::string huge = "; " + std::string(rs::lsp::kMaxFormattedBytes, 'x') + "\n        END\n";
  const rs::lsp::Reply reply = formatted(huge);
  REQUIRE(std::holds_alternative<rs::lsp::RpcError>(reply));
  CHECK(std::get<rs::lsp::RpcError>(reply).code == -32803);
  CHECK(std::get<rs::lsp::RpcError>(reply).message ==
        "the document is 64 MiB: robotsim formats programs up to 64 MiB (its answer would be a message larger than "
        "the server accepts)");
}
