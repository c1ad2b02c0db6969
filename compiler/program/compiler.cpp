#include "compiler/program/compiler.h"

#include <fmt/format.h>

#include "compiler/program/ast_builder.h"
#include "compiler/program/translator.h"
#include "compiler/program/lexer.h"
#include "compiler/program/line_reader.h"
#include "RobotProgramParser.h"

namespace rs::compiler {

std::optional<diag::Diagnostic> checkEncoding(const diag::SourceFile& source, std::string_view what) {
  if (source.text().size() > kMaxSourceBytes)
    return diag::Diagnostic{source.name(), {}, diag::Severity::Error,
                      fmt::format("file is {} bytes; the limit is {} MiB", source.text().size(), kMaxSourceBytes >> 20),
                      "file-too-large"};
  const diag::Utf8Problem bad = diag::findInvalidUtf8(source.text());
  if (bad.found)
    return diag::Diagnostic{source.name(), bad.pos, diag::Severity::Error,
                            fmt::format("invalid UTF-8 (byte 0x{:02X}): {} are UTF-8 text", bad.byte, what), "invalid-utf8"};
  const diag::LoneCarriageReturn cr = source.findLoneCarriageReturn();
  if (!cr.found) return std::nullopt;
  return diag::Diagnostic{source.name(), cr.pos, diag::Severity::Error,
                          "a carriage return without a line feed (old Mac line ends?): lines end in LF or CR LF",
                          "lone-carriage-return", "save the file with Unix (LF) or Windows (CR LF) line ends"};
}

namespace {

// Hands everything to the checker, then to the observer: a point written
// as a pose reaches the observer with the values the checker resolved.
class Tee final : public AstSink {
 public:
  Tee(Translator& first, AstSink& second) : first_(first), second_(second) {}
  void instruction(const Instruction& in) override { first_.instruction(in), second_.instruction(in); }
  void pointsHeader(diag::Pos pos) override { first_.pointsHeader(pos), second_.pointsHeader(pos); }
  void point(const PointDef& p) override {
    first_.point(p);
    if (!p.isPose) return second_.point(p);
    resolved_ = p;
    resolved_.values.clear();
    for (const std::int32_t v : first_.lastPointValues()) resolved_.values.push_back({v, p.pose.at.pos});
    second_.point(resolved_);
  }

 private:
  Translator& first_;
  AstSink& second_;
  PointDef resolved_;
};

CompileResult compileTo(const diag::SourceFile& source, const Target& target, std::size_t keepDiagnostics,
                        AstSink* observer) {
  CompileResult result;
  if (auto bad = checkEncoding(source)) {
    result.diagnostics.push_back(std::move(*bad));
    return result;
  }
  diag::Diagnostics diagnostics(source.name(), keepDiagnostics);
  LineReader lines(source, diagnostics);
  Translator checker(target, source, diagnostics);
  if (observer) {
    Tee tee(checker, *observer);
    buildAst(source, lines, target.motors, diagnostics, tee);
  } else {
    buildAst(source, lines, target.motors, diagnostics, checker);
  }
  result.image = checker.finish();
  result.diagnostics = diagnostics.sorted();
  result.omitted = diagnostics.omitted();
  return result;
}

}  // namespace

CompileResult compile(const diag::SourceFile& source, const Target& target, std::size_t keepDiagnostics) {
  return compileTo(source, target, keepDiagnostics, nullptr);
}

CompileResult compile(const diag::SourceFile& source, const Target& target, std::size_t keepDiagnostics,
                      AstSink& observer) {
  return compileTo(source, target, keepDiagnostics, &observer);
}

std::string dumpTokens(const diag::SourceFile& source, diag::Diagnostics& diagnostics) {
  if (auto bad = checkEncoding(source)) {
    diagnostics.error(bad->pos, std::move(bad->message), bad->code);
    return {};
  }
  Lexer lexer(source, diagnostics);
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
  return out;
}

}  // namespace rs::compiler
