#include "compiler/compiler.h"

#include <fmt/format.h>

#include "compiler/ast_builder.h"
#include "compiler/checks.h"
#include "compiler/lexer.h"
#include "compiler/parse_tree.h"
#include "RobotProgramParser.h"

namespace rs::compiler {

std::optional<Diagnostic> checkEncoding(const SourceFile& source, std::string_view what) {
  if (source.text().size() > kMaxSourceBytes)
    return Diagnostic{source.name(), {}, Severity::Error,
                      fmt::format("file is {} bytes; the limit is {} MiB", source.text().size(), kMaxSourceBytes >> 20)};
  const Utf8Problem bad = findInvalidUtf8(source.text());
  if (!bad.found) return std::nullopt;
  return Diagnostic{source.name(), bad.pos, Severity::Error,
                    fmt::format("invalid UTF-8 (byte 0x{:02X}): {} are UTF-8 text", bad.byte, what)};
}

CompileResult compile(const SourceFile& source, const Target& target) {
  CompileResult result;
  if (auto bad = checkEncoding(source)) {
    result.diagnostics.push_back(std::move(*bad));
    return result;
  }
  Diagnostics diagnostics(source.name());
  LineParser parser(source, diagnostics);
  const Program program = buildAst(source, parser, target.motors, diagnostics);
  const Resolution resolution = check(program, target.motors, diagnostics);
  if (!diagnostics.hasErrors()) result.image = generate(program, resolution, target, source.name());
  result.diagnostics = diagnostics.sorted();
  return result;
}

std::string dumpTokens(const SourceFile& source, std::vector<Diagnostic>& diagnostics) {
  if (auto bad = checkEncoding(source)) {
    diagnostics.push_back(std::move(*bad));
    return {};
  }
  Diagnostics d(source.name());
  Lexer lexer(source, d);
  std::string out;
  for (;;) {
    const RawToken t = lexer.scan();
    const std::string pos = fmt::format("{}:{}", t.pos.line, t.pos.col);
    const bool shown = t.type != antlr4::Token::EOF && t.type != rs_grammar::RobotProgramParser::NEWLINE;
    out += shown ? fmt::format("{:<8} {:<8} {}\n", pos, tokenTypeName(t.type),
                               std::string_view(source.text()).substr(t.begin, t.end - t.begin))
                 : fmt::format("{:<8} {}\n", pos, tokenTypeName(t.type));
    if (t.type == antlr4::Token::EOF) break;
  }
  diagnostics = d.sorted();
  return out;
}

}  // namespace rs::compiler
