#include "tools/testrun/scenario_file.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/ascii.h"
#include "tools/testrun/expectation_words.h"

namespace rs::testrun {

namespace {

using words::blank;
using words::columnOf;
using words::is;
using words::Word;
using words::wordsOf;

// "4", "0.5", "2.25" -> hundredths; nullopt for anything else (a sign, a
// third decimal, more than kMaxPoints).
std::optional<Hundredths> pointsOf(std::string_view text) {
  Hundredths whole = 0, fraction = 0;
  std::size_t i = 0, digits = 0, decimals = 0;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++digits) {
    whole = whole * 10 + (text[i] - '0');
    if (whole > kMaxPoints / 100) return std::nullopt;
  }
  if (digits == 0) return std::nullopt;
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9' && decimals < 2; ++i, ++decimals)
      fraction = fraction * 10 + (text[i] - '0');
    if (decimals == 0) return std::nullopt;
    if (decimals == 1) fraction *= 10;
  }
  if (i != text.size()) return std::nullopt;
  const Hundredths points = whole * 100 + fraction;
  return points <= kMaxPoints ? std::optional(points) : std::nullopt;
}

std::string pointsProblem(std::string_view text) {
  return fmt::format("expected points: a number of at most {} with at most two decimals (4, 0.5, 2.25), got '{}'",
                     kMaxPoints / 100, text);
}

// The head of a `test:` / `expect:` line ("" when the line has no colon).
std::string_view headOf(std::string_view line, std::size_t i) {
  const std::size_t colon = line.find(':', i);
  return colon == std::string_view::npos ? std::string_view() : line.substr(i, colon - i);
}

}  // namespace

ScenarioFile parseScenarioFile(const diag::SourceFile& source) {
  ScenarioFile out;
  ParsedExpectations preamble;  // the shared test: lines
  std::vector<diag::Pos> pointsAt;  // each scenario's `points` line, for its errors
  for (std::uint32_t n = 1; n <= source.lineCount(); ++n) {
    const std::string_view line = source.line(n);
    std::size_t i = 0;
    while (i < line.size() && blank(line[i])) ++i;
    if (i == line.size() || line[i] == ';') continue;
    const std::vector<Word> words = wordsOf(line.substr(0, line.find(';')), i);
    const diag::Pos pos{n, columnOf(line, i)};
    const auto error = [&](diag::Pos at, std::string message) {
      out.errors.push_back({source.name(), at, diag::Severity::Error, std::move(message)});
    };
    if (is(words[0], "scenario")) {
      if (words.size() < 2) {
        error({n, columnOf(line, line.size())}, "expected the scenario's name after 'scenario'");
        continue;
      }
      Scenario& s = out.scenarios.emplace_back();
      s.pos = pos;
      pointsAt.push_back({});
      const std::size_t from = static_cast<std::size_t>(words[1].text.data() - line.data());
      const std::size_t to = static_cast<std::size_t>(words.back().text.data() + words.back().text.size() - line.data());
      s.name = line.substr(from, to - from);
      continue;
    }
    if (is(words[0], "program") && words.size() == 3) {
      // `program LABEL FILE`: robot LABEL of the cell runs FILE, in every
      // scenario (before the first) or in this one.
      ParsedExpectations& into = out.scenarios.empty() ? preamble : out.scenarios.back().parsed;
      std::vector<RobotProgram>& programs = into.settings.programs;
      const auto same = [&](const RobotProgram& p) { return base::sameName(p.label, words[1].text); };
      if (std::any_of(programs.begin(), programs.end(), same)) {
        error({n, words[1].col}, fmt::format("robot {}'s program is named twice", words[1].text));
        continue;
      }
      programs.push_back({std::string(words[1].text), std::string(words[2].text), pos, words[1].col, words[2].col});
      continue;
    }
    if (is(words[0], "program")) {
      if (words.size() != 2 || !out.program.empty()) {
        error(pos, out.program.empty() ? "expected 'program FILE', or 'program LABEL FILE' for a robot of the cell"
                                       : "the program is named twice");
        continue;
      }
      out.program = words[1].text;
      out.programPos = pos;
      continue;
    }
    if (is(words[0], "points")) {
      if (out.scenarios.empty()) {
        error(pos, "'points N' gives a scenario its points: put it after its 'scenario NAME'");
      } else if (words.size() != 2) {
        error(words.size() < 2 ? diag::Pos{n, columnOf(line, line.size())} : diag::Pos{n, words[2].col},
              "expected 'points N' (one number)");
      } else if (const std::optional<Hundredths> p = pointsOf(words[1].text); !p) {
        error({n, words[1].col}, pointsProblem(words[1].text));
      } else if (out.scenarios.back().points) {
        error(pos, "the scenario's points are given twice");
      } else {
        out.scenarios.back().points = *p;
        pointsAt.back() = pos;
      }
      continue;
    }
    const std::string_view head = headOf(line, i);
    const bool expect = base::sameName(head, "expect") || base::sameName(head, "expect-error");
    if (expect && out.scenarios.empty()) {
      error(pos, "expected 'scenario NAME' before the first expect: ('test:' lines before it are shared by every "
                 "scenario; expectations are each scenario's own)");
      continue;
    }
    // `expect: ... points N`: the points come off before the expectation is read.
    std::string_view directive = line;
    std::optional<Hundredths> points;
    if (base::sameName(head, "expect") && words.size() >= 3 && is(words[words.size() - 2], "points")) {
      const Word& number = words.back();
      points = pointsOf(number.text);
      if (!points) {
        error({n, number.col}, pointsProblem(number.text));
        continue;
      }
      directive = line.substr(0, static_cast<std::size_t>(words[words.size() - 2].text.data() - line.data()));
    }
    ParsedExpectations& into = out.scenarios.empty() ? preamble : out.scenarios.back().parsed;
    const std::size_t before = into.expectations.size();
    if (!readDirective(directive, n, i, source.name(), into)) {
      error(pos, fmt::format("expected 'program FILE', 'scenario NAME', 'points N', 'test: ...' or 'expect: ...', got "
                             "'{}'",
                             words[0].text));
      continue;
    }
    if (points && into.expectations.size() > before) into.expectations.back().points = points;
  }
  for (const diag::Diagnostic& d : preamble.errors) out.errors.push_back(d);
  out.shared = preamble.settings;
  for (std::size_t k = 0; k < out.scenarios.size(); ++k) {
    Scenario& s = out.scenarios[k];
    for (diag::Diagnostic& d : s.parsed.errors) out.errors.push_back(std::move(d));
    s.parsed.errors.clear();
    if (s.points && partialCredit(s))
      out.errors.push_back({source.name(), pointsAt[k], diag::Severity::Error,
                            fmt::format("scenario '{}' gives its points whole ('points N') and per expectation "
                                        "('expect: ... points N') too: keep one",
                                        s.name)});
  }
  if (out.scenarios.empty() && out.errors.empty())
    out.errors.push_back({source.name(), {}, diag::Severity::Error, "the file has no 'scenario NAME'"});
  return out;
}

TestSettings settingsOf(const ScenarioFile& file, const Scenario& s) {
  TestSettings settings = s.parsed.settings;
  const TestSettings& shared = file.shared;
  if (settings.cell.empty()) settings.cell = shared.cell;
  if (settings.robot.empty()) settings.robot = shared.robot;
  // A robot's program in the scenario replaces the shared one of that robot.
  std::vector<RobotProgram> programs;
  for (const RobotProgram& p : shared.programs)
    if (std::none_of(settings.programs.begin(), settings.programs.end(),
                     [&](const RobotProgram& own) { return base::sameName(own.label, p.label); }))
      programs.push_back(p);
  programs.insert(programs.end(), settings.programs.begin(), settings.programs.end());
  settings.programs = std::move(programs);
  if (settings.stimuliFile.empty()) settings.stimuliFile = shared.stimuliFile;
  if (settings.maxTime.empty()) settings.maxTime = shared.maxTime;
  if (!settings.maxSteps) settings.maxSteps = shared.maxSteps;
  settings.inputs.insert(settings.inputs.begin(), shared.inputs.begin(), shared.inputs.end());
  return settings;
}

bool partialCredit(const Scenario& s) {
  for (const Expectation& e : s.parsed.expectations)
    if (e.points) return true;
  return false;
}

Hundredths maxPointsOf(const Scenario& s) {
  if (s.points) return *s.points;
  if (!partialCredit(s)) return 100;
  Hundredths sum = 0;
  for (const Expectation& e : s.parsed.expectations) sum += e.points.value_or(0);
  return sum;
}

std::string pointsText(Hundredths points) {
  const char* sign = points < 0 ? "-" : "";
  const Hundredths p = points < 0 ? -points : points;
  if (p % 100 == 0) return fmt::format("{}{}", sign, p / 100);
  if (p % 10 == 0) return fmt::format("{}{}.{}", sign, p / 100, (p % 100) / 10);
  return fmt::format("{}{}.{:02}", sign, p / 100, p % 100);
}

}  // namespace rs::testrun
