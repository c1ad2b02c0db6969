#include "compiler/program/ast_builder.h"

#include <algorithm>
#include <fmt/format.h>

#include "base/near_names.h"
#include "compiler/program/ast_builder_detail.h"

namespace rs::compiler {

namespace detail {

void Builder::finish() {
  if (!pendingLabel_.empty())
    diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_),
                "label-without-instruction");
}

// Splits a line's tokens into label, head word and operands.
void Builder::line(std::span<const RawToken> tokens) {
  if (tokens.empty()) return;  // blank line
  if (tokens[0].type != P::IDENT)
    return diag_.error(posOf(tokens[0]), fmt::format("unexpected '{}': a line starts with an instruction, a label "
                                                     "or a point name",
                                                     diag::excerpt(textOf(src_, tokens[0]))),
                       "syntax");
  const bool labelled = tokens.size() >= 2 && tokens[1].type == P::COLON;
  std::size_t next = labelled ? 2 : 0;
  const RawToken* headToken = nullptr;
  if (next < tokens.size() && tokens[next].type == P::IDENT) headToken = &tokens[next++];
  std::vector<Word>& words = words_;
  words.clear();
  for (; next < tokens.size(); ++next) {
    if (tokens[next].type == P::COLON)
      return diag_.error(posOf(tokens[next]),
                         "unexpected ':': a label is a name followed by ':' at the start of a line", "syntax");
    words.push_back({tokens[next].type, textOf(src_, tokens[next]), posOf(tokens[next])});
  }
  if (labelled) {
    const std::string_view label = textOf(src_, tokens[0]);
    const diag::Pos pos = posOf(tokens[0]);
    if (inPoints_) {
      diag_.error(pos, "points cannot have labels: labels name instructions", "label-on-point");
    } else if (!pendingLabel_.empty()) {
      diag_.error(pos, fmt::format("label '{}' follows label '{}': an instruction can have only one label",
                                   diag::excerpt(label), pendingLabel_),
                  "two-labels", {diag_.relatedAt(pendingLabelPos_, fmt::format("label '{}' is here", pendingLabel_))});
    } else if (checkName("a label", label, pos)) {
      pendingLabel_ = label;
      pendingLabelPos_ = pos;
    }
  }
  if (!headToken) {
    if (labelled && !words.empty()) {
      diag_.error(words[0].pos,
                  fmt::format("expected an instruction after the label, found '{}'", diag::excerpt(words[0].text)),
                  "syntax");
      pendingLabel_ = {};
    }
    return;
  }
  const std::string_view head = textOf(src_, *headToken);
  if (sameName(head, "POINTS") && words.empty()) {
    if (inPoints_)
      return diag_.error(posOf(*headToken),
                         fmt::format("POINTS appears twice (the section began on line {})", pointsHeader_.line),
                         "duplicate-points-section", {diag_.relatedAt(pointsHeader_, "the POINTS section begins here")});
    if (!pendingLabel_.empty()) {
      diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_),
                  "label-without-instruction");
      pendingLabel_ = {};
    }
    inPoints_ = true;
    pointsHeader_ = posOf(*headToken);
    sink_.pointsHeader(pointsHeader_);
    return;
  }
  if (inPoints_) return point(*headToken, words);
  if (looksLikePoint(head, words)) {
    // A point row after the program's END without a POINTS line: say so
    // once, then read this row and the rest as the points they are.
    const diag::Pos pos = posOf(*headToken);
    diag_.error(pos,
                fmt::format("'{}' is not an instruction: it looks like a taught point, but no POINTS line comes "
                            "before it",
                            diag::excerpt(head)),
                diag::Hint{fmt::format("points follow a line POINTS after the instructions: add POINTS on a line "
                                       "of its own after the END on line {}, before line {}",
                                       endLine_, pos.line)},
                "missing-points-line");
    if (!pendingLabel_.empty()) {
      diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_));
      pendingLabel_ = {};
    }
    inPoints_ = true;
    pointsHeader_ = pos;
    sink_.pointsHeader(pointsHeader_);
    return point(*headToken, words);
  }
  instruction(*headToken, words);
}

// After an END, a word that is no instruction (nor one letter away from
// one: "MOVX 1 2 3 4 5" is a slip of MOVE) followed only by numbers: a
// point row whose POINTS line is missing ("HOME 0 0 0 0 0").
bool Builder::looksLikePoint(std::string_view head, const std::vector<Word>& words) const {
  if (endLine_ == 0 || words.empty() || vm::opByName(head)) return false;
  for (const vm::OpInfo& op : vm::kOps)
    if (base::nameDistance(head, op.name) <= 1) return false;
  return std::all_of(words.begin(), words.end(), [](const Word& w) { return w.type == P::NUMBER; });
}

void Builder::instruction(const RawToken& head, const std::vector<Word>& words) {
  Instruction& in = in_;
  std::vector<Value> values = std::move(in.values);
  values.clear();
  in = Instruction{};
  in.values = std::move(values);
  in.pos = posOf(head);
  in.number = ++instructions_;
  in.label = pendingLabel_;
  in.labelPos = pendingLabelPos_;
  pendingLabel_ = {};
  const std::string_view mnemonic = textOf(src_, head);
  if (const auto op = vm::opByName(mnemonic)) {
    in.op = *op;
    if (vm::has(*op, vm::kEnds)) endLine_ = in.pos.line;
    operands(in, vm::info(*op).name, words);
  } else {
    in.known = false;
    const std::string_view near = closestMnemonic(mnemonic);
    diag_.error(in.pos,
                near.empty() ? fmt::format("unknown instruction '{}'", diag::excerpt(mnemonic))
                             : fmt::format("unknown instruction '{}' (did you mean {}?)", diag::excerpt(mnemonic), near),
                "unknown-instruction");
  }
  sink_.instruction(in);
}

}  // namespace detail

std::string_view closestMnemonic(std::string_view word) {
  std::vector<std::string_view> names;
  for (const vm::OpInfo& op : vm::kOps) names.push_back(op.name);
  return base::nearestName(word, names);
}

namespace {

// Collects what the builder hands on into a Program.
class Collect final : public AstSink {
 public:
  explicit Collect(const diag::SourceFile& source) {
    // One instruction per line at most: reserving for that touches no
    // memory the program does not use, and saves the copies of growth.
    program.instructions.reserve(source.lineCount());
  }
  void instruction(const Instruction& in) override { program.instructions.push_back(in); }
  void pointsHeader(diag::Pos pos) override { program.pointsHeader = pos; }
  void point(const PointDef& p) override { program.points.push_back(p); }
  Program program;
};

}  // namespace

using detail::Builder;
using detail::P;

void buildAst(const diag::SourceFile& source, LineReader& lines, std::span<const vm::MotorSpec> motors,
              diag::Diagnostics& diagnostics, AstSink& sink) {
  Builder b(source, motors, diagnostics, sink);
  for (std::span<const RawToken> words; lines.next(words);) b.line(words);
  b.finish();
}

// A line of the whole file's tree as the lexer's tokens: every child of a
// LineContext is a token node (a SourceToken from the TokenArray); after
// error recovery some are error nodes for tokens the parser skipped
// (already reported), which are left out.
Program buildAst(ParseTree& tree, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics) {
  Collect collect(tree.source());
  Builder b(tree.source(), motors, diagnostics, collect);
  std::vector<RawToken> words;
  for (P::LineContext* l : static_cast<P::ProgramContext*>(tree.root())->line()) {
    words.clear();
    for (antlr4::tree::ParseTree* child : l->children) {
      if (tree.recovered() && dynamic_cast<antlr4::tree::ErrorNode*>(child)) continue;
      const antlr4::Token* t = static_cast<antlr4::tree::TerminalNode*>(child)->getSymbol();
      words.push_back({t->getType(), t->getStartIndex(), t->getStopIndex() + 1,
                       {static_cast<std::uint32_t>(t->getLine()),
                        static_cast<std::uint32_t>(t->getCharPositionInLine() + 1)}});
    }
    b.line(words);
  }
  b.finish();
  return std::move(collect.program);
}

Program buildAst(const diag::SourceFile& source, LineReader& lines, std::span<const vm::MotorSpec> motors,
                 diag::Diagnostics& diagnostics) {
  Collect collect(source);
  buildAst(source, lines, motors, diagnostics, collect);
  return std::move(collect.program);
}

}  // namespace rs::compiler
