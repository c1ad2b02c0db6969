// textDocument/semanticTokens/full: the compiler's lexer gives the words,
// the index says what each name is; comments are what follows ';'.
#include "compiler/program/compiler.h"
#include "compiler/program/lexer.h"
#include "base/ascii.h"
#include "tools/lsp/features/features.h"

namespace rs::lsp {

namespace {

enum TokenType { kKeyword, kLabel, kFunction, kVariable, kNumber, kOperator, kComment, kEnumMember };
enum Modifier { kDeclaration = 1, kReadonly = 2 };

struct Token {
  Position at;
  std::uint32_t length = 0;
  int type = 0;
  int modifiers = 0;
};

}  // namespace

Json semanticTokensLegend() {
  return {{"tokenTypes", {"keyword", "label", "function", "variable", "number", "operator", "comment", "enumMember"}},
          {"tokenModifiers", {"declaration", "readonly"}}};
}

Json semanticTokens(const ProgramContext& p) {
  std::vector<Token> tokens;
  const ProgramIndex& index = p.analysis.index();
  const diag::SourceFile& source = p.analysis.source();
  if (!compiler::checkEncoding(source)) {
    diag::Diagnostics ignored(source.name(), 1);
    compiler::Lexer lexer(source, ignored);
    for (compiler::RawToken t = lexer.scan(); t.type != antlr4::Token::EOF; t = lexer.scan()) {
      const std::string_view type = compiler::tokenTypeName(t.type);
      if (type == "NEWLINE" || type == "COLON") continue;
      const std::string_view text = std::string_view(source.text()).substr(t.begin, t.end - t.begin);
      Token tok{p.doc.fromPos(t.pos, p.enc), static_cast<std::uint32_t>(text.size()), -1, 0};
      if (type == "NUMBER") {
        tok.type = kNumber;
      } else if (type == "CMP") {
        tok.type = kOperator;
      } else if (const Occurrence* o = index.occurrenceAt(t.pos); o && o->pos == t.pos) {
        tok.modifiers = o->definition ? kDeclaration : 0;
        switch (o->kind) {
          case NameKind::Label: tok.type = index.isSubroutine(o->name) ? kFunction : kLabel; break;
          case NameKind::Point: tok.type = kVariable, tok.modifiers |= kReadonly; break;
          case NameKind::Variable: tok.type = kVariable; break;
          case NameKind::Instruction: tok.type = kNumber; break;
        }
      } else if (base::sameName(text, "ON") || base::sameName(text, "OFF")) {
        tok.type = kEnumMember;
      } else if (const IndexedInstruction* in = index.instructionOnLine(t.pos.line); in && in->pos == t.pos && in->known) {
        tok.type = kKeyword;
      } else if (index.pointsHeader() == t.pos) {
        tok.type = kKeyword;
      }
      if (tok.type >= 0) tokens.push_back(tok);
    }
  }
  // Comments, merged in line order.
  std::vector<Token> all;
  all.reserve(tokens.size());
  std::size_t next = 0;
  for (std::uint32_t l = 0; l < p.doc.lineCount(); ++l) {
    while (next < tokens.size() && tokens[next].at.line == l) all.push_back(tokens[next++]);
    const std::string_view line = p.doc.line(l);
    const std::size_t semi = line.find(';');
    if (semi != std::string_view::npos)
      all.push_back({{l, unitsOf(line.substr(0, semi), p.enc)}, unitsOf(line.substr(semi), p.enc), kComment, 0});
  }
  Json data = Json::array();
  Position last;
  for (const Token& t : all) {
    const std::uint32_t dl = t.at.line - last.line;
    data.push_back(dl);
    data.push_back(dl == 0 ? t.at.character - last.character : t.at.character);
    data.push_back(t.length);
    data.push_back(t.type);
    data.push_back(t.modifiers);
    last = t.at;
  }
  return {{"data", std::move(data)}};
}

}  // namespace rs::lsp
