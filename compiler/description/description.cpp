#include "compiler/description/description.h"

#include <array>
#include <fmt/format.h>

#include "RobotModelLexer.h"
#include "base/ascii.h"
#include "compiler/program/compiler.h"
#include "compiler/description/description_parser.h"

namespace rs::compiler {

namespace description_detail {

namespace {

using MP = rs_grammar::RobotModelLexer;  // its token types

std::string_view blockName(Block b) {
  switch (b) {
    case Block::Link: return "LINK";
    case Block::Object: return "OBJECT";
    case Block::Gripper: return "GRIPPER";
    case Block::Robot: return "ROBOT";
    case Block::Workcell: return "WORKCELL";
    case Block::None: break;
  }
  return "";
}

}  // namespace

// A line with an error damages the definition it belongs to (and, in a
// robot, the link or joint it was about): see ShapeDef.
void Parser::line(const std::vector<Word>& words, diag::Pos lineEnd) {
  const Block before = block_;
  const std::size_t errors = diag_.errorCount();
  readLine(words, lineEnd);
  if (diag_.errorCount() > errors) markDamaged(before == Block::None ? block_ : before);
}

void Parser::markDamaged(Block b) {
  switch (b) {
    case Block::Link: if (!f_.links.empty()) f_.links.back().damaged = true; break;
    case Block::Object: if (!f_.objects.empty()) f_.objects.back().damaged = true; break;
    case Block::Gripper: if (!f_.grippers.empty()) f_.grippers.back().damaged = true; break;
    case Block::Workcell: if (!f_.workcells.empty()) f_.workcells.back().damaged = true; break;
    case Block::Robot:
      if (f_.robots.empty()) break;
      f_.robots.back().damaged = true;
      if (robotItem_ == Item::Joint) f_.robots.back().joints.back().damaged = true;
      if (robotItem_ == Item::Link) f_.robots.back().links.back().damaged = true;
      if (robotItem_ == Item::Tool) f_.robots.back().tool->damaged = true;
      break;
    case Block::None: break;
  }
}

void Parser::readLine(const std::vector<Word>& words, diag::Pos lineEnd) {
  if (words.empty()) return;
  // Any character but in a ROBOT line's PROGRAM file name (its words after
  // PROGRAM, written together: Cursor::path).
  bool inPath = false;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const Word& w = words[i];
    if (inPath && i > 0 && w.pos.line == words[i - 1].pos.line &&
        w.pos.col == words[i - 1].pos.col + words[i - 1].text.size())
      continue;
    inPath = block_ == Block::Workcell && w.type == MP::NAME && base::sameName(w.text, "PROGRAM");
    if (inPath) {
      // The first word of the path may itself be a character ('.', '/').
      if (i + 1 < words.size()) ++i;
      continue;
    }
    if (w.type == MP::OTHER)
      return diag_.error(w.pos, fmt::format("unexpected character '{}'", diag::excerpt(w.text)),
                         diag::Hint{"a description line holds keywords, names and numbers; a comment starts with ';'"});
  }
  Cursor c(words, lineEnd, diag_);
  if (block_ == Block::None) return open(c, words[0]);
  if (c.keyword("END")) {
    if (!c.atEnd()) diag_.error(c.pos(), fmt::format("END takes nothing after it, found '{}'", diag::excerpt(c.peek().text)));
    block_ = Block::None;
    return;
  }
  while (!c.atEnd()) {
    bool ok = false;
    switch (block_) {
      case Block::Link: ok = shapeClause(c, f_.links.back()); break;
      case Block::Object: ok = shapeClause(c, f_.objects.back()); break;
      case Block::Gripper: ok = gripperClause(c, f_.grippers.back()); break;
      case Block::Robot: ok = robotClause(c, f_.robots.back()); break;
      case Block::Workcell: ok = workcellClause(c, f_.workcells.back()); break;
      case Block::None: break;
    }
    if (!ok) return;
  }
}

void Parser::open(Cursor& c, const Word& head) {
  static constexpr std::array<Block, 5> kinds{Block::Link, Block::Object, Block::Gripper, Block::Robot, Block::Workcell};
  Block kind = Block::None;
  for (Block k : kinds)
    if (c.keyword(blockName(k))) kind = k;
  if (kind == Block::None) {
    constexpr std::string_view kBlockKinds = "LINK, OBJECT, GRIPPER, ROBOT or WORKCELL";
    diag_.error(head.pos, fmt::format("expected {}, found '{}'", kBlockKinds, diag::excerpt(head.text)),
                diag::Hint{head.type == MP::NAME ? didYouMean(head.text, kBlockKinds) : std::string()});
    return;
  }
  // Without a name the block still opens (the error is reported), so the
  // lines inside it are read as what they are, not as stray text.
  NameRef name;
  if (!c.name(name, fmt::format("a name for the {}", blockName(kind)))) {
  } else if (!c.atEnd()) {
    diag_.error(c.pos(), fmt::format("unexpected '{}' after the {} name (statements go on the next lines)",
                                     diag::excerpt(c.peek().text), blockName(kind)));
  }
  block_ = kind;
  blockPos_ = head.pos;
  robotItem_ = Item::None;
  color_ = Color::White;
  switch (kind) {
    case Block::Link: f_.links.emplace_back(), f_.links.back().name = name.name, f_.links.back().pos = head.pos; break;
    case Block::Object: f_.objects.emplace_back(), f_.objects.back().name = name.name, f_.objects.back().pos = head.pos; break;
    case Block::Gripper: f_.grippers.push_back({}), f_.grippers.back().name = name.name, f_.grippers.back().pos = head.pos; break;
    case Block::Robot: f_.robots.push_back({}), f_.robots.back().name = name.name, f_.robots.back().pos = head.pos; break;
    case Block::Workcell: f_.workcells.push_back({name.name, head.pos, {}}); break;
    case Block::None: break;
  }
}

void Parser::finish() {
  if (block_ != Block::None)
    diag_.error(blockPos_, fmt::format("{} has no END", blockName(block_)));
}

}  // namespace description_detail

using description_detail::Color;
using description_detail::kColorNames;
using description_detail::Parser;
using description_detail::Word;
using MP = rs_grammar::RobotModelLexer;  // its token types

std::optional<workcell::Color> colorByName(std::string_view word) {
  for (std::size_t i = 0; i < kColorNames.size(); ++i)
    if (base::sameName(word, kColorNames[i]) || word == std::to_string(i)) return static_cast<Color>(i);
  return std::nullopt;
}

std::string_view colorName(workcell::Color color) { return kColorNames[static_cast<std::size_t>(color)]; }

bool looksLikeDescription(std::string_view text) {
  text = diag::withoutByteOrderMark(text);
  std::size_t i = 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n' || text[i] == ';'))
    if (text[i] == ';')
      while (i < text.size() && text[i] != '\n') ++i;
    else
      ++i;
  if (i == text.size()) return true;
  // A word as the lexer's NAME reads it: the keyword must be all of it.
  const auto nameChar = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
  };
  std::size_t end = i;
  while (end < text.size() && nameChar(text[end])) ++end;
  const std::string_view word = text.substr(i, end - i);
  for (const std::string_view block : {"LINK", "OBJECT", "GRIPPER", "ROBOT", "WORKCELL"})
    if (base::sameName(word, block)) return true;
  return false;
}

DescriptionFile parseDescription(std::unique_ptr<diag::SourceFile> source, diag::Diagnostics& diagnostics) {
  DescriptionFile file;
  file.source = std::move(source);
  if (auto bad = checkEncoding(*file.source, "descriptions")) {
    diagnostics.add(bad->pos, bad->severity, bad->message);
    return file;
  }
  // A line at a time through ANTLR's lexer, as the grammar's `line` rule
  // reads it: the rule takes any words, so the generated parser's tree (a
  // rule context, a token and a node per line and per word, all held to
  // the end) changed nothing but the memory, which was 25 bytes a byte of
  // input for lines of comments and 180 for empty ones (issue 32). Now only
  // the current line's words are held. A line of blanks or a comment alone
  // holds no word and is not lexed.
  const std::string_view text = file.source->text();
  antlr4::ANTLRInputStream input;
  rs_grammar::RobotModelLexer lexer(&input);
  lexer.removeErrorListeners();  // OTHER matches any character: no lexer errors
  Parser p(file, diagnostics);
  std::vector<Word> words;
  std::uint32_t lineNumber = 0;
  for (std::size_t at = 0; at <= text.size(); ++lineNumber) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == ';') continue;
    input.load(std::string(line));
    lexer.setInputStream(&input);
    words.clear();
    for (std::unique_ptr<antlr4::Token> t = lexer.nextToken(); t->getType() != antlr4::Token::EOF; t = lexer.nextToken())
      words.push_back({t->getType(), t->getText(),
                       {lineNumber + 1, static_cast<std::uint32_t>(t->getCharPositionInLine() + 1)}});
    const diag::Pos lineEnd = words.empty() ? diag::Pos{} : diag::Pos{words.back().pos.line,
                                                  words.back().pos.col + static_cast<std::uint32_t>(words.back().text.size())};
    p.line(words, lineEnd);
  }
  p.finish();
  return file;
}

}  // namespace rs::compiler
