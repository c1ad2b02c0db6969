// The compiler reads one line's words at a time straight from the lexer
// (LineReader); `robotsim ast --tree` parses the whole file with the
// generated ANTLR parser (ParseTree). Both must give the same AST and the
// same diagnostics for every input, good or bad: this is what shows that
// the compiler may skip the parser (the grammar's `line` rule takes any
// sequence of the lexer's words).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "RobotProgramParser.h"
#include "compiler/program/ast_builder.h"
#include "compiler/program/lexer.h"
#include "compiler/program/line_reader.h"
#include "compiler/program/parse_tree.h"
#include "stdlib/default_robot.h"

namespace {

using namespace rs::compiler;
namespace diag = rs::diag;
using P = rs_grammar::RobotProgramParser;

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every field of every node, written out: two ASTs are equal when these are.
std::string describeParsed(const Program& p) {
  std::ostringstream o;
  auto pos = [&](diag::Pos x) { o << '@' << x.line << ':' << x.col << ' '; };
  auto values = [&](const std::vector<Value>& vs) {
    for (const Value& v : vs) o << v.number << ' ', pos(v.pos);
  };
  for (const Instruction& in : p.instructions) {
    o << '#' << in.number << ' ';
    pos(in.pos);
    o << static_cast<int>(in.op) << ' ' << in.known << " label=" << in.label << ' ';
    pos(in.labelPos);
    values(in.values);
    o << "io=" << in.io.number << ' ';
    pos(in.io.pos);
    o << in.on << ' ' << static_cast<int>(in.compare) << " name=" << in.name << ' ';
    pos(in.namePos);
    o << "value=" << in.value.number << ' ';
    pos(in.value.pos);
    o << "target=" << in.target.number << '/' << in.target.label << ' ';
    pos(in.target.pos);
    o << '\n';
  }
  o << "POINTS ";
  pos(p.pointsHeader);
  o << '\n';
  for (const PointDef& pt : p.points) {
    o << pt.name << ' ';
    pos(pt.pos);
    values(pt.values);
    o << '\n';
  }
  return o.str();
}

std::string describeParsed(const std::vector<diag::Diagnostic>& ds) {
  std::ostringstream o;
  for (const diag::Diagnostic& d : ds)
    o << d.pos.line << ':' << d.pos.col << ' ' << severityName(d.severity) << ' ' << d.message << '\n';
  return o.str();
}

struct Both {
  std::string wholeAst, lineAst, wholeDiagnostics, lineDiagnostics;
};

Both parseBothWays(const std::string& name, const std::string& text) {
  const diag::SourceFile source(name, text);
  const auto motors = rs::stdlib::rhinoScaraMotors();
  Both b;
  {
    diag::Diagnostics d(name);
    ParseTree tree(source, d);
    b.wholeAst = describeParsed(buildAst(tree, motors, d));
    b.wholeDiagnostics = describeParsed(d.sorted());
  }
  {
    diag::Diagnostics d(name);
    LineReader lines(source, d);
    b.lineAst = describeParsed(buildAst(source, lines, motors, d));
    b.lineDiagnostics = describeParsed(d.sorted());
  }
  return b;
}

}  // namespace

TEST_CASE("line-by-line reading gives the whole-file AST for every example", "[compiler][parser]") {
  for (const char* example : {"counted_loop", "first_moves", "nested_subroutines", "pick_and_place",
                              "sensor_branching", "soft_home", "workcell_view"}) {
    INFO(example);
    const std::string text = readFile(std::string(ROBOTSIM_SOURCE_DIR) + "/examples/" + example + ".rsp");
    REQUIRE(text.size() > 50);
    const Both b = parseBothWays(example, text);
    CHECK(b.lineAst == b.wholeAst);
    CHECK(b.lineDiagnostics == b.wholeDiagnostics);
    CHECK(b.lineAst.find("#5 ") != std::string::npos);  // a real program was described
  }
}

TEST_CASE("line-by-line reading gives the whole-file AST and errors for bad input", "[compiler][parser]") {
  const std::vector<std::string> programs = {
      "",
      "\n\n\n",
      "END",                                   // no final newline
      "MOVE 1 2 3 4 5\r\nEND\r\n",             // CR LF
      "a: b: MOVE 1 2 3 4 5\nEND\n",           // two labels
      "MOVE 1 2 : 3\nGOTO nowhere\nEND\n",     // stray colon, missing label
      "3 MOVE\n< > =\nMOVX 1\nEND\n",          // bad line starts, unknown instruction
      "MOVE 1 2 3 4 5 ; comment ; more\n\tEND\nPOINTS\nP1 1 2 3 4 5\nP2 1 2\nPOINTS\n",
      "SET N 1\nADD N 99999999999\nJMPVAR N > x 1\nDELAY 1.2345\nEND\nlabel:\n",
      "END\n@#$\nMOVE + 1\n\xC3\xA9 END\n",     // characters the lexer rejects
  };
  for (const std::string& text : programs) {
    INFO(text);
    const Both b = parseBothWays("bad.rsp", text);
    CHECK(b.lineAst == b.wholeAst);
    CHECK(b.lineDiagnostics == b.wholeDiagnostics);
  }
}

namespace {

// The words of each line, as "text@line:col" joined by spaces, one line each.
std::vector<std::string> linesRead(const std::string& text) {
  const diag::SourceFile source("t.rsp", text);
  diag::Diagnostics d("t.rsp");
  LineReader reader(source, d);
  std::vector<std::string> out;
  for (std::span<const RawToken> words; reader.next(words);) {
    std::string line;
    for (const RawToken& w : words)
      line += (line.empty() ? "" : " ") + text.substr(w.begin, w.end - w.begin) + "@" + std::to_string(w.pos.line) +
              ":" + std::to_string(w.pos.col);
    out.push_back(line);
  }
  return out;
}

}  // namespace

TEST_CASE("a line reader gives each line's words and the lines ANTLR's program rule sees", "[compiler][parser]") {
  using Lines = std::vector<std::string>;
  CHECK(linesRead("MOVE 1 -2\nloop: END\n") == Lines{"MOVE@1:1 1@1:6 -2@1:8", "loop@2:1 :@2:5 END@2:7", ""});
  CHECK(linesRead("END") == Lines{"END@1:1"});  // no line break: one line
  CHECK(linesRead("") == Lines{""});
  CHECK(linesRead("\n\r\n; note\n") == Lines{"", "", "", ""});  // N breaks, N + 1 lines
  CHECK(linesRead("GOTO x ; to x\r\n\tEND") == Lines{"GOTO@1:1 x@1:6", "END@2:2"});
  CHECK(linesRead("JMPVAR N<3 l") == Lines{"JMPVAR@1:1 N@1:8 <@1:9 3@1:10 l@1:12"});
}

TEST_CASE("a line reader is done after the last line, and stays done", "[compiler][parser]") {
  const diag::SourceFile source("t.rsp", "END\n");
  diag::Diagnostics d("t.rsp");
  LineReader reader(source, d);
  std::span<const RawToken> words;
  REQUIRE(reader.next(words));
  CHECK(words.size() == 1);
  REQUIRE(reader.next(words));
  CHECK(words.empty());
  CHECK_FALSE(reader.next(words));
  CHECK_FALSE(reader.next(words));
}

TEST_CASE("a token array holds every token of the file and seeks anywhere", "[compiler][parser]") {
  const std::string text = "GOTO 1\nEND";
  const diag::SourceFile source("t.rsp", text);
  diag::Diagnostics d("t.rsp");
  Lexer lexer(source, d);
  TokenArray tokens(lexer, source.text());
  CHECK(tokens.size() == 5);  // GOTO 1 NEWLINE END EOF
  tokens.seek(3);
  CHECK(tokens.LT(1)->getText() == "END");
  CHECK(tokens.LT(1)->toString() == "[@3,7:9='END',<1>,2:0]");
  tokens.consume();
  CHECK(tokens.LA(1) == antlr4::Token::EOF);
  CHECK(tokens.get(1)->getText() == "1");
  CHECK(tokens.getText() == "GOTO1\nEND");
}

TEST_CASE("a parser token is small and carries no copy of its text", "[compiler][parser]") {
  STATIC_REQUIRE(sizeof(SourceToken) <= 40);
  const std::string text = "WAITFOR 3 ON";
  RawToken raw;
  raw.type = P::NUMBER;
  raw.begin = 8;
  raw.end = 9;
  raw.pos = {1, 9};
  const SourceToken t(text, raw, 7);
  CHECK(t.getText() == "3");
  CHECK(t.getType() == P::NUMBER);
  CHECK(t.getTokenIndex() == 7);
  CHECK(t.getCharPositionInLine() == 8);
}

TEST_CASE("line-by-line reading and whole-file parsing agree on 500 random programs", "[compiler][parser]") {
  // Words from every token type, keywords in both cases, bad characters and
  // line breaks of both kinds; a fixed seed keeps the test reproducible.
  const std::vector<std::string> words = {
      "MOVE", "moveto", "MOVEP", "GOTO", "jmpin", "OUTSIG", "JMPVAR", "GOSUB", "RETURN", "WAITFOR", "ADD",
      "RESET", "WINDOW", "VIEW", "DELAY", "HRDHOME", "SETSOFT", "GOSOFT", "SET", "END", "POINTS", "ON", "off",
      "n", "loop", "P1", "0", "1", "-5", "+7", "100", "2.5", "99999999999", ":", "<", ">", "=", "; note",
      "@", "\t", "\n", "\n", "\n", "\r\n", "\r"};
  std::uint32_t x = 2026;
  auto next = [&x](std::size_t n) { return static_cast<std::size_t>((x = x * 1664525u + 1013904223u) >> 8) % n; };
  int withInstructions = 0, withErrors = 0;
  for (int program = 0; program < 500; ++program) {
    std::string text;
    const std::size_t length = next(60);
    for (std::size_t i = 0; i < length; ++i) text += words[next(words.size())] + (next(3) ? " " : "");
    INFO(text);
    const Both b = parseBothWays("random.rsp", text);
    REQUIRE(b.lineAst == b.wholeAst);
    REQUIRE(b.lineDiagnostics == b.wholeDiagnostics);
    withInstructions += b.lineAst.find("#1 ") != std::string::npos;
    withErrors += !b.lineDiagnostics.empty();
  }
  // The programs exercised both paths: real instructions, and errors.
  CHECK(withInstructions > 250);
  CHECK(withErrors > 250);
}
