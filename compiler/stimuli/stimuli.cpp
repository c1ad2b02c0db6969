// The stimuli file parser. Line oriented: each line is split into words at
// blanks (after cutting a `;` comment), then one of two statements is read:
//
//   line   := [ at | when ] [ ';' comment ]
//   at     := 'at' SECONDS 'input' LINE STATE
//   when   := 'when' 'output' LINE STATE 'then' 'input' LINE STATE [ 'after' SECONDS ]
//   LINE   := [ LABEL '.' ] N       (a robot's label, in a cell of several robots)
//   STATE  := 'on' | 'off'          (keywords in any case)
//
// A bad line yields one error at the first word that does not fit, and the
// parser goes on with the next line, so one run reports every bad line.
#include "compiler/stimuli/stimuli.h"

#include "diag/read_input.h"

#include <fmt/format.h>

#include <climits>
#include <fstream>

#include "compiler/stimuli/stimuli_text.h"
#include "vm/io_lines.h"

namespace rs::stimuli {
namespace {

constexpr std::size_t kMaxFileBytes = 64u << 20;  // far beyond any real stimuli file

std::uint32_t clampToU32(std::size_t n) { return n > UINT32_MAX ? UINT32_MAX : static_cast<std::uint32_t>(n); }

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct Token {
  std::string_view text;
  std::size_t offset = 0;  // 0-based byte offset in the line
};

struct Failure {
  std::size_t offset = 0;
  std::string message;
};

// Reads the words of one line, one statement piece at a time. The first
// failure is kept; after it, every read fails, so statement code can chain
// reads with && and stop at the first problem.
class LineParser {
 public:
  explicit LineParser(std::string_view line) : line_(line.substr(0, line.find(';'))) {}

  std::optional<Token> peek() const {
    std::size_t at = pos_;
    while (at < line_.size() && isBlank(line_[at])) ++at;
    std::size_t end = at;
    while (end < line_.size() && !isBlank(line_[end])) ++end;
    if (at == end) return std::nullopt;
    return Token{line_.substr(at, end - at), at};
  }

  // Word `keyword`; the error says "expected 'keyword' <context>".
  bool keyword(std::string_view kw, std::string_view context) {
    const auto token = take(fmt::format("expected '{}' {}", kw, context));
    if (!token) return false;
    if (text::equalsKeyword(token->text, kw)) return true;
    return fail(*token,
                fmt::format("expected '{}' {}, got {}", kw, context, text::quoted(token->text)));
  }

  // 'on' or 'off'.
  bool state(bool& on, std::string_view context) {
    const auto token = take(fmt::format("expected 'on' or 'off' {}", context));
    if (!token) return false;
    on = text::equalsKeyword(token->text, "on");
    if (on || text::equalsKeyword(token->text, "off")) return true;
    return fail(*token, fmt::format("expected 'on' or 'off' {}, got {}", context,
                                    text::quoted(token->text)));
  }

  // An input or output number 1..vm::kIoCount right after the keyword `what`,
  // with its robot's label before a '.' where one is written (`right.3`).
  bool lineNumber(int& n, std::string& robot, std::uint32_t& robotColumn, std::string_view what) {
    const auto token = take(fmt::format("expected an {} number 1..{} after '{}'", what, vm::kIoCount, what));
    if (!token) return false;
    std::string_view number = token->text;
    std::size_t numberOffset = token->offset;
    const auto dot = number.rfind('.');
    const bool labelled = dot != std::string_view::npos && dot > 0 && !(number[0] >= '0' && number[0] <= '9');
    if (labelled) {  // a number such as `3.5` stays a bad number, not a label
      const std::string_view label = number.substr(0, dot);
      if (!text::isLabel(label))
        return fail(*token, fmt::format("expected a robot's label before '.' in {} (a name: letters, digits, '_', "
                                        "'-' and '.', a letter or '_' first), got {}",
                                        what, text::quoted(label)));
      robot = std::string(label);
      robotColumn = clampToU32(token->offset + 1);
      number.remove_prefix(dot + 1);
      numberOffset += dot + 1;
    }
    const diag::Result<int> parsed = text::parseLineNumber(number, what);
    if (!parsed) return fail(Token{number, numberOffset}, parsed.failure().message);
    n = *parsed;
    return true;
  }

  bool seconds(vm::Micros& t, std::string_view missing) {
    const auto token = take(std::string(missing));
    if (!token) return false;
    const diag::Result<vm::Micros> parsed = text::parseSeconds(token->text);
    if (!parsed) return fail(*token, parsed.failure().message);
    t = *parsed;
    return true;
  }

  // Nothing but blanks (or a comment) left on the line.
  bool atEnd() {
    const auto token = peek();
    if (!token) return true;
    return fail(*token, fmt::format("unexpected {} after the end of the statement",
                                    text::quoted(token->text)));
  }

  // Consumes a word already seen with peek().
  void skip() { take({}); }

  bool fail(const Token& token, std::string message) {
    return failAt(token.offset, std::move(message));
  }

  const std::optional<Failure>& failure() const { return failure_; }

 private:
  // The next word, or a failure just after the previous word when the line ends.
  std::optional<Token> take(std::string missingMessage) {
    if (failure_) return std::nullopt;
    auto token = peek();
    if (!token) {
      failAt(lastEnd_, std::move(missingMessage));
      return std::nullopt;
    }
    pos_ = lastEnd_ = token->offset + token->text.size();
    return token;
  }

  bool failAt(std::size_t offset, std::string message) {
    if (!failure_) failure_ = Failure{offset, std::move(message)};
    return false;
  }

  std::string_view line_;
  std::size_t pos_ = 0;
  std::size_t lastEnd_ = 0;  // one past the last word read
  std::optional<Failure> failure_;
};

// at := 'at' SECONDS 'input' N STATE   ('at' already read)
void parseAt(LineParser& p, Stimuli& out) {
  InputChange change;
  if (p.seconds(change.at, "expected a time in seconds after 'at'") &&
      p.keyword("input", "after the time") && p.lineNumber(change.input, change.robot, change.robotColumn, "input") &&
      p.state(change.on, "after the input number") && p.atEnd())
    out.changes.push_back(change);
}

// [ 'after' SECONDS ] at the end of a rule.
bool parseOptionalDelay(LineParser& p, vm::Micros& delay) {
  const auto next = p.peek();
  if (!next) return true;
  if (!text::equalsKeyword(next->text, "after"))
    return p.fail(*next, fmt::format("expected 'after' or the end of the line, got {}",
                                     text::quoted(next->text)));
  p.skip();
  return p.seconds(delay, "expected a delay in seconds after 'after'") && p.atEnd();
}

// when := 'when' 'output' N STATE 'then' 'input' N STATE [ 'after' SECONDS ]
void parseWhen(LineParser& p, Stimuli& out) {
  ReactiveRule rule;
  if (p.keyword("output", "after 'when'") &&
      p.lineNumber(rule.output, rule.outputRobot, rule.outputRobotColumn, "output") &&
      p.state(rule.outputOn, "after the output number") &&
      p.keyword("then", "after the output state") && p.keyword("input", "after 'then'") &&
      p.lineNumber(rule.input, rule.inputRobot, rule.inputRobotColumn, "input") &&
      p.state(rule.inputOn, "after the input number") &&
      parseOptionalDelay(p, rule.delay))
    out.rules.push_back(rule);
}

// One line: a statement, a comment, or nothing. Returns the failure, if any.
std::optional<Failure> parseLine(std::string_view line, Stimuli& out) {
  LineParser p(line);
  const auto first = p.peek();
  if (!first) return std::nullopt;
  if (text::equalsKeyword(first->text, "at")) {
    p.skip();
    parseAt(p, out);
  } else if (text::equalsKeyword(first->text, "when")) {
    p.skip();
    parseWhen(p, out);
  } else {
    p.fail(*first, fmt::format("expected 'at' or 'when' at the start of a line, got {}",
                               text::quoted(first->text)));
  }
  return p.failure();
}

}  // namespace

diag::Result<Stimuli> parseStimuli(std::string_view text, std::string_view fileName) {
  Stimuli stimuli;
  std::vector<diag::Diagnostic> errors;
  text = diag::withoutByteOrderMark(text);
  std::size_t lineNo = 0;
  while (true) {
    ++lineNo;
    const auto newline = text.find('\n');
    const auto line = text.substr(0, newline);
    const std::size_t rulesBefore = stimuli.rules.size(), changesBefore = stimuli.changes.size();
    if (auto failure = parseLine(line, stimuli))
      errors.push_back({std::string(fileName), {clampToU32(lineNo), clampToU32(failure->offset + 1)},
                        diag::Severity::Error, std::move(failure->message)});
    if (stimuli.rules.size() > rulesBefore) stimuli.rules.back().line = clampToU32(lineNo);
    for (std::size_t c = changesBefore; c < stimuli.changes.size(); ++c) stimuli.changes[c].line = clampToU32(lineNo);
    if (newline == std::string_view::npos) break;
    text.remove_prefix(newline + 1);
  }
  if (!errors.empty()) return diag::Result<Stimuli>(std::move(errors));
  return stimuli;
}

diag::Result<Stimuli> loadStimuliFile(const std::filesystem::path& path) {
  const auto name = path.string();
  diag::Result<std::string> read = diag::readInput(name, kMaxFileBytes, "cannot read the stimuli file");
  if (!read) return diag::Result<Stimuli>(std::move(read).failures());
  return parseStimuli(*read, name);
}

}  // namespace rs::stimuli
