#include "compiler/stimuli/stimuli_text.h"

#include <fmt/format.h>

#include "compiler/stimuli/stimuli.h"
#include "base/ascii.h"
#include "vm/io_lines.h"

namespace rs::stimuli::text {
namespace {

constexpr std::size_t kMaxQuotedBytes = 40;
constexpr int kMaxDecimals = 6;  // the clock counts microseconds

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool allDigits(std::string_view s) {
  for (char c : s)
    if (!isDigit(c)) return false;
  return !s.empty();
}

std::string_view stripLeadingZeros(std::string_view digits) {
  while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
  return digits;
}

// Digits already checked and short enough not to overflow.
std::int64_t digitsValue(std::string_view digits) {
  std::int64_t value = 0;
  for (char c : digits) value = value * 10 + (c - '0');
  return value;
}

// True when `token` is DIGITS or DIGITS.DIGITS (any number of decimals).
bool looksLikeSeconds(std::string_view token) {
  const auto dot = token.find('.');
  if (dot == std::string_view::npos) return allDigits(token);
  return allDigits(token.substr(0, dot)) && allDigits(token.substr(dot + 1));
}

}  // namespace

bool equalsKeyword(std::string_view token, std::string_view keyword) { return base::sameName(token, keyword); }

std::string quoted(std::string_view token) {
  const bool cut = token.size() > kMaxQuotedBytes;
  std::string out = "'";
  for (const char ch : token.substr(0, kMaxQuotedBytes)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f && c != '\\')
      out += ch;
    else
      out += fmt::format("\\x{:02x}", c);
  }
  if (cut) out += "...";
  return out + "'";
}

diag::Result<vm::Micros> parseSeconds(std::string_view token) {
  if (token.starts_with('-') && looksLikeSeconds(token.substr(1)))
    return diag::refusal(fmt::format("time must not be negative, got {}", quoted(token)));
  if (!looksLikeSeconds(token))
    return diag::refusal(fmt::format("bad time {}: expected seconds such as 2 or 1.5", quoted(token)));
  const auto dot = token.find('.');
  const auto whole = stripLeadingZeros(token.substr(0, dot));
  const auto decimals = dot == std::string_view::npos ? std::string_view{} : token.substr(dot + 1);
  if (decimals.size() > kMaxDecimals)
    return diag::refusal(fmt::format("time {} has more than {} decimals", quoted(token), kMaxDecimals));
  // 7 digits hold the largest allowed whole part (1000000) without overflow.
  vm::Micros micros = whole.size() <= 7 ? digitsValue(whole) * 1'000'000 : kMaxStimulusTime + 1;
  std::int64_t scale = 100'000;
  for (char c : decimals) {
    micros += (c - '0') * scale;
    scale /= 10;
  }
  if (micros > kMaxStimulusTime)
    return diag::refusal(fmt::format("time {} is past the limit of 1000000 seconds", quoted(token)));
  return micros;
}

diag::Result<int> parseLineNumber(std::string_view token, std::string_view what) {
  if (!allDigits(token))
    return diag::refusal(fmt::format("expected an {} number 1..{}, got {}", what, vm::kIoCount, quoted(token)));
  const auto digits = stripLeadingZeros(token);
  const int value = digits.size() == 1 ? digits[0] - '0' : 0;  // longer is out of range
  if (value < 1 || value > vm::kIoCount)
    return diag::refusal(fmt::format("{} number must be 1..{}, got {}", what, vm::kIoCount,
                                     digits.size() <= kMaxQuotedBytes ? std::string(digits) : quoted(digits)));
  return value;
}

bool isLabel(std::string_view token) {
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (token.empty() || token.size() > 64 || !(letter(token[0]) || token[0] == '_')) return false;
  for (const char c : token)
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '_' && c != '-' && c != '.') return false;
  return true;
}

}  // namespace rs::stimuli::text
