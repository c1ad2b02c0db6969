#include "tools/testrun/expectation_words.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "base/ascii.h"
#include "base/text.h"
#include "compiler/stimuli/stimuli_text.h"

namespace rs::testrun::words {

std::uint32_t columnOf(std::string_view line, std::size_t offset) {
  std::uint32_t col = 1;
  for (std::size_t i = 0; i < offset && i < line.size(); i += std::max<std::size_t>(base::utf8SequenceLength(line, i), 1))
    ++col;
  return col;
}

// Columns are counted on as the words are found, never again from the
// start of the line: a line of a million words costs a million steps, not
// a million squared (one `motors` line with 1M terms took minutes).
std::vector<Word> wordsOf(std::string_view line, std::size_t from) {
  std::vector<Word> words;
  std::size_t counted = 0;  // the column of byte `counted` is `col`
  std::uint32_t col = 1;
  const auto columnAt = [&](std::size_t offset) {
    for (; counted < offset && counted < line.size();
         counted += std::max<std::size_t>(base::utf8SequenceLength(line, counted), 1))
      ++col;
    return col;
  };
  std::size_t i = from;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) words.push_back({line.substr(start, i - start), columnAt(start)});
  }
  return words;
}

bool is(const Word& w, std::string_view keyword) { return base::sameName(w.text, keyword); }

bool LineReader::accept(std::string_view keyword) {
  if (done() || !is(words_[next_], keyword)) return false;
  ++next_;
  return true;
}

bool LineReader::acceptPhrase(std::span<const std::string_view> phrase) {
  if (next_ + phrase.size() > words_.size()) return false;
  for (std::size_t i = 0; i < phrase.size(); ++i)
    if (!is(words_[next_ + i], phrase[i])) return false;
  next_ += phrase.size();
  return true;
}

std::optional<Word> LineReader::take(std::string_view what) {
  if (done()) return fail(fmt::format("expected {}", what)), std::nullopt;
  return words_[next_++];
}

bool LineReader::keyword(std::string_view keyword) {
  if (accept(keyword)) return true;
  fail(done() ? fmt::format("expected '{}'", keyword)
              : fmt::format("expected '{}', got '{}'", keyword, words_[next_].text));
  return false;
}

bool LineReader::integer(std::string_view what, std::int64_t& v, std::int64_t lo, std::int64_t hi) {
  const std::optional<Word> w = take(what);
  if (!w) return false;
  const auto [ptr, ec] = std::from_chars(w->text.data(), w->text.data() + w->text.size(), v);
  if (ec != std::errc() || ptr != w->text.data() + w->text.size() || v < lo || v > hi) {
    --next_;
    return fail(fmt::format("expected {} ({}..{}), got '{}'", what, lo, hi, w->text));
  }
  return true;
}

bool LineReader::real(std::string_view what, double& v) {
  const std::optional<Word> w = take(what);
  if (!w) return false;
  const auto [ptr, ec] = std::from_chars(w->text.data(), w->text.data() + w->text.size(), v);
  if (ec != std::errc() || ptr != w->text.data() + w->text.size() || !std::isfinite(v) || std::abs(v) > 1e12) {
    --next_;
    return fail(fmt::format("expected {} (a number), got '{}'", what, w->text));
  }
  return true;
}

bool LineReader::seconds(std::string_view what, vm::Micros& micros) {
  const std::optional<Word> w = take(what);
  if (!w) return false;
  const diag::Result<vm::Micros> parsed = stimuli::text::parseSeconds(w->text);
  if (!parsed) return failAt(w->col, parsed.failure().message);
  micros = *parsed;
  return true;
}

bool LineReader::onOff(bool& on) {
  if (accept("on")) return on = true, true;
  if (accept("off")) return on = false, true;
  return fail(done() ? "expected ON or OFF" : fmt::format("expected ON or OFF, got '{}'", words_[next_].text));
}

std::optional<Word> LineReader::robotPrefix() {
  if (done()) return std::nullopt;
  Word& w = words_[next_];
  const std::size_t dot = w.text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == w.text.size()) return std::nullopt;
  const Word label{w.text.substr(0, dot), w.col};
  w.col += columnOf(w.text, dot + 1) - 1;
  w.text.remove_prefix(dot + 1);
  return label;
}

bool LineReader::end() {
  if (done()) return true;
  return fail(fmt::format("unexpected '{}' after the end of the expectation", words_[next_].text));
}

bool LineReader::failAt(std::uint32_t col, std::string message) {
  if (!error_) error_ = diag::Diagnostic{{}, {line_, col}, diag::Severity::Error, std::move(message)};
  return false;
}

}  // namespace rs::testrun::words
