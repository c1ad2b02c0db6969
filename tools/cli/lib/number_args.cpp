#include "tools/cli/lib/number_args.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>

#include "base/text.h"
#include "compiler/stimuli/stimuli_text.h"

namespace rs::cli {

namespace {

// The text as messages quote it: control bytes escaped, at most 32 bytes.
std::string quotedArg(std::string_view text) {
  constexpr std::size_t kShown = 32;
  std::string s = base::safeText(text.substr(0, kShown));
  if (text.size() > kShown) s += "...";
  return "'" + s + "'";
}

// A bound as people write it: whole bounds without a decimal point.
std::string boundText(double v) {
  return std::abs(v) < 1e19 && v == std::floor(v) ? fmt::format("{:.0f}", v) : fmt::format("{}", v);
}

std::string rangeText(const NumberRule& rule) {
  if (rule.aboveMin) return fmt::format("above {} and at most {}", boundText(rule.min), boundText(rule.max));
  return fmt::format("from {} to {}", boundText(rule.min), boundText(rule.max));
}

std::string outOfRange(std::string_view text, const NumberRule& rule) {
  return fmt::format("{} is out of range: {} is {}{}", quotedArg(text), rule.what, rule.whole ? "a whole number " : "",
                     rangeText(rule));
}

// A whole number written as digits alone, exactly (doubles lose digits
// past 2^53, and the step limit goes to 2^62).
bool readWhole(std::string_view digits, std::int64_t& v) {
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  return ec == std::errc() && ptr == digits.data() + digits.size();
}

NumberRead refused(std::string problem) { return {0, {}, std::move(problem)}; }

}  // namespace

NumberRead readNumber(std::string_view text, const NumberRule& rule) {
  std::string_view t = text;
  if (!t.empty() && t[0] == '+' && t.size() > 1 && t[1] != '-') t.remove_prefix(1);
  if (rule.whole) {
    std::int64_t whole = 0;
    if (!t.empty() && readWhole(t, whole)) {
      const auto v = static_cast<long double>(whole);
      if (v < static_cast<long double>(rule.min) || v > static_cast<long double>(rule.max) ||
          (rule.aboveMin && v == static_cast<long double>(rule.min)))
        return refused(outOfRange(text, rule));
      return {static_cast<double>(whole), std::to_string(whole), {}};
    }
  }
  double v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ptr != t.data() + t.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    return refused(fmt::format("{} is not a number", quotedArg(text)));
  if (std::isnan(v)) return refused(fmt::format("{} is not a number", quotedArg(text)));
  if (ec == std::errc::result_out_of_range || std::isinf(v) || v < rule.min || v > rule.max ||
      (rule.aboveMin && v <= rule.min))
    return refused(outOfRange(text, rule));
  if (rule.whole) {
    if (v != std::floor(v))
      return refused(fmt::format("{} is not a whole number ({} is one)", quotedArg(text), rule.what));
    return {v, fmt::format("{:.0f}", v), {}};
  }
  return {v + 0.0, fmt::format("{}", v + 0.0), {}};  // never "-0"
}

std::string numberError(std::string_view option, std::string_view problem, const NumberRule& rule) {
  return fmt::format("{}: error: {}\n  hint: {}\n", option, problem, rule.hint);
}

CLI::Validator numberArg(const NumberRule& rule) {
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        NumberRead r = readNumber(text, rule);
        if (!r.problem.empty()) return fmt::format("error: {}\n  hint: {}", r.problem, rule.hint);
        text = std::move(r.canonical);
        return {};
      },
      "");
}

CLI::Validator numberListArg(const NumberRule& rule) {
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        std::size_t start = 0;
        for (int item = 1;; ++item) {
          const std::size_t comma = text.find(',', start);
          const std::string_view piece =
              std::string_view(text).substr(start, comma == std::string::npos ? std::string::npos : comma - start);
          if (const NumberRead r = readNumber(piece, rule); !r.problem.empty())
            return fmt::format("error: value {} {}\n  hint: {}", item, r.problem, rule.hint);
          if (comma == std::string::npos) return {};
          start = comma + 1;
        }
      },
      "");
}

bool parseSecondsArg(const std::string& text, std::string_view option, std::int64_t& micros, std::ostream& err) {
  const diag::Result<vm::Micros> parsed = stimuli::text::parseSeconds(text);
  if (!parsed) {
    err << fmt::format("{}: error: {}\n  hint: {}\n", option, parsed.failure().message, kSecondsHint);
    return false;
  }
  micros = *parsed;
  return true;
}

CLI::Validator secondsArg() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const diag::Result<vm::Micros> parsed = stimuli::text::parseSeconds(text);
        return parsed ? std::string() : fmt::format("error: {}\n  hint: {}", parsed.failure().message, kSecondsHint);
      },
      "");
}

bool parseNumberList(const std::string& text, std::string_view option, const NumberRule& rule, std::vector<double>& out,
                     std::ostream& err) {
  out.clear();
  std::size_t start = 0;
  for (int item = 1;; ++item) {
    const std::size_t comma = text.find(',', start);
    const std::string_view piece =
        std::string_view(text).substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const NumberRead r = readNumber(piece, rule);
    if (!r.problem.empty()) {
      err << numberError(option, fmt::format("value {} {}", item, r.problem), rule);
      return false;
    }
    out.push_back(r.value);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

}  // namespace rs::cli
