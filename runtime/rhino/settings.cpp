#include "runtime/rhino/settings.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

namespace rs::rhino {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool parseInt(std::string_view text, int lo, int hi, int& out) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size() || v < lo || v > hi) return false;
  out = v;
  return true;
}

// Seconds ("0.5", "2") to microseconds, 1 us .. 1 day.
bool parseSeconds(std::string_view text, Micros& out) {
  const std::string s(text);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v) || v <= 0 || v > 86400) return false;
  out = static_cast<Micros>(std::llround(v * 1e6));
  return out > 0;
}

std::string seconds(Micros t) { return fmt::format("{}", static_cast<double>(t) / 1e6); }

bool parseBool(std::string_view text, bool& out) {
  const std::string v = lower(text);
  if (v == "yes" || v == "true" || v == "on" || v == "1") return out = true, true;
  if (v == "no" || v == "false" || v == "off" || v == "0") return out = false, true;
  return false;
}

// "I0" .. "K5", or "none".
bool parseBitSource(std::string_view text, BitSource& out) {
  const std::string v = lower(text);
  if (v == "none") return out = {}, true;
  if (v.size() != 2 || (v[0] != 'i' && v[0] != 'j' && v[0] != 'k') || v[1] < '0' || v[1] > '5') return false;
  out = {static_cast<char>(std::toupper(static_cast<unsigned char>(v[0]))), v[1] - '0'};
  return true;
}

std::string bitSourceText(const BitSource& b) { return b.wired() ? fmt::format("{}{}", b.command, b.bit) : "none"; }

const char* parityText(Parity p) { return p == Parity::None ? "none" : p == Parity::Even ? "even" : "odd"; }
const char* flowText(FlowControl f) {
  return f == FlowControl::None ? "none" : f == FlowControl::RtsCts ? "rtscts" : "xonxoff";
}
const char* lineEndText(LineEnd e) {
  switch (e) {
    case LineEnd::Cr: return "cr";
    case LineEnd::CrLf: return "crlf";
    case LineEnd::LfCr: return "lfcr";
    case LineEnd::Lf: return "lf";
  }
  return "cr";
}

// A command template may use {n} and {port}; nothing else in braces.
bool validTemplate(std::string_view t) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '}') return false;
    if (t[i] != '{') continue;
    const std::size_t close = t.find('}', i);
    if (close == std::string_view::npos) return false;
    const std::string_view name = t.substr(i + 1, close - i - 1);
    if (name != "n" && name != "port") return false;
    i = close;
  }
  for (const char c : t)
    if (c == '\r' || c == '\n') return false;
  return true;
}

// "switch.E", "input.3", "output.3.on": the index, or -1.
// A line's number in a setting's name is one digit ("input.8").
static_assert(kControllerLines <= 9);
constexpr char kLastLineDigit = static_cast<char>('0' + kControllerLines);

int indexedKey(std::string_view key, std::string_view prefix, std::string_view suffix, char first, char last) {
  if (key.size() != prefix.size() + 1 + suffix.size() || key.substr(0, prefix.size()) != prefix ||
      key.substr(prefix.size() + 1) != suffix)
    return -1;
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(key[prefix.size()])));
  return c >= first && c <= last ? c - first : -1;
}

std::string bad(std::string_view key, std::string_view value, std::string_view expected) {
  return fmt::format("{}={}: expected {}", key, value, expected);
}

}  // namespace

std::string_view dialectName(Dialect d) { return d == Dialect::Mark3 ? "mark3" : "mark4"; }

std::string_view dialectTitle(Dialect d) { return d == Dialect::Mark3 ? "Mark III" : "Mark IV"; }

std::string_view lineEndBytes(LineEnd e) {
  switch (e) {
    case LineEnd::Cr: return "\r";
    case LineEnd::CrLf: return "\r\n";
    case LineEnd::LfCr: return "\n\r";
    case LineEnd::Lf: return "\n";
  }
  return "\r";
}

// The Mark III assumptions (docs/serial.md, "Assumptions"): switches of
// C..H on I bits 0..5 [S]; A and B on J bits 0, 1; inputs 1..4 on J bits
// 2..5 and 5..8 on K bits 0..3; outputs 1 and 2 are the aux ports (L/M,
// N/O [S]), outputs 3..8 are set together with P and the port value.
RhinoSettings defaultSettings(Dialect d) {
  RhinoSettings s;
  s.dialect = d;
  s.switches[0] = {'J', 0};
  s.switches[1] = {'J', 1};
  for (int m = 2; m < 8; ++m) s.switches[m] = {'I', m - 2};
  for (int i = 0; i < 4; ++i) s.inputs[i] = {'J', i + 2};
  for (int i = 4; i < kControllerLines; ++i) s.inputs[i] = {'K', i - 4};
  s.outputOn[0] = "L";
  s.outputOff[0] = "M";
  s.outputOn[1] = "N";
  s.outputOff[1] = "O";
  for (int i = 2; i < kControllerLines; ++i) s.outputOn[i] = s.outputOff[i] = "P{port}";
  s.inputsActiveLow = d == Dialect::Mark3;
  return s;
}

namespace {

// Applies one `key=value`; returns "" or what is wrong.
std::string applySetting(RhinoSettings& s, std::string_view rawKey, std::string_view rawValue) {
  const std::string key = lower(trim(rawKey));
  const std::string_view value = trim(rawValue);
  const std::string v = lower(value);
  int n = 0;
  if (key == "baud") {
    if (!parseInt(value, 1, 4'000'000, n) || !supportedBaud(n))
      return bad(key, value, "a standard baud rate (9600, 19200, ...)");
    s.line.baud = n;
  } else if (key == "data-bits") {
    if (!parseInt(value, 5, 8, n)) return bad(key, value, "5, 6, 7 or 8");
    s.line.dataBits = n;
  } else if (key == "parity") {
    if (v == "none" || v == "n")
      s.line.parity = Parity::None;
    else if (v == "even" || v == "e")
      s.line.parity = Parity::Even;
    else if (v == "odd" || v == "o")
      s.line.parity = Parity::Odd;
    else
      return bad(key, value, "none, even or odd");
  } else if (key == "stop-bits") {
    if (!parseInt(value, 1, 2, n)) return bad(key, value, "1 or 2");
    s.line.stopBits = n;
  } else if (key == "flow") {
    if (v == "none")
      s.line.flow = FlowControl::None;
    else if (v == "rtscts")
      s.line.flow = FlowControl::RtsCts;
    else if (v == "xonxoff")
      s.line.flow = FlowControl::XonXoff;
    else
      return bad(key, value, "none, rtscts or xonxoff");
  } else if (key == "line-end") {
    if (v == "cr")
      s.lineEnd = LineEnd::Cr;
    else if (v == "crlf")
      s.lineEnd = LineEnd::CrLf;
    else if (v == "lfcr")
      s.lineEnd = LineEnd::LfCr;
    else if (v == "lf")
      s.lineEnd = LineEnd::Lf;
    else
      return bad(key, value, "cr, crlf, lfcr or lf");
  } else if (key == "timeout") {
    if (!parseSeconds(value, s.timeout)) return bad(key, value, "seconds > 0");
  } else if (key == "poll") {
    if (!parseSeconds(value, s.pollInterval)) return bad(key, value, "seconds > 0");
  } else if (key == "stall-timeout") {
    if (!parseSeconds(value, s.stallTimeout)) return bad(key, value, "seconds > 0");
  } else if (key == "home-timeout") {
    if (!parseSeconds(value, s.homeTimeout)) return bad(key, value, "seconds > 0");
  } else if (key == "chunk") {
    if (!parseInt(value, 1, 127, n)) return bad(key, value, "1..127 steps");
    s.chunk = n;
  } else if (key == "refill") {
    // 0 would never send the next chunk: |steps to go| < 0 never holds.
    if (!parseInt(value, 1, 127, n)) return bad(key, value, "1..127 steps (0 would stall every long move)");
    s.refill = n;
  } else if (key == "remaining") {
    if (v == "magnitude")
      s.signedRemaining = false;
    else if (v == "signed")
      s.signedRemaining = true;
    else
      return bad(key, value, "magnitude or signed");
  } else if (const int m = indexedKey(key, "switch.", "", 'A', 'H'); m >= 0) {
    if (!parseBitSource(value, s.switches[static_cast<std::size_t>(m)])) return bad(key, value, "I0..K5 or none");
  } else if (const int i = indexedKey(key, "input.", "", '1', kLastLineDigit); i >= 0) {
    if (!parseBitSource(value, s.inputs[static_cast<std::size_t>(i)])) return bad(key, value, "I0..K5 or none");
  } else if (key == "input-active") {
    if (v == "low")
      s.inputsActiveLow = true;
    else if (v == "high")
      s.inputsActiveLow = false;
    else
      return bad(key, value, "low or high");
  } else if (const int on = indexedKey(key, "output.", ".on", '1', kLastLineDigit); on >= 0) {
    if (!validTemplate(value)) return bad(key, value, "a command, optionally with {n} and {port}");
    s.outputOn[static_cast<std::size_t>(on)] = std::string(value);
  } else if (const int off = indexedKey(key, "output.", ".off", '1', kLastLineDigit); off >= 0) {
    if (!validTemplate(value)) return bad(key, value, "a command, optionally with {n} and {port}");
    s.outputOff[static_cast<std::size_t>(off)] = std::string(value);
  } else if (key == "home-order") {
    std::string order;
    for (const char c : value) {
      const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (up < 'A' || up > 'H' || order.find(up) != std::string::npos)
        return bad(key, value, "distinct motor letters A..H");
      order += up;
    }
    s.homeOrder = order;
  } else if (key == "home-search") {
    if (!parseInt(value, 0, 1'000'000, n)) return bad(key, value, "0..1000000 steps (0: the motor's range)");
    s.homeSearch = n;
  } else if (key == "home-direction") {
    if (value == "-" || v == "negative")
      s.homeDirection = -1;
    else if (value == "+" || v == "positive")
      s.homeDirection = 1;
    else
      return bad(key, value, "- or +");
  } else if (key == "start") {
    if (v == "mi")
      s.coordinated = false;
    else if (v == "mc")
      s.coordinated = true;
    else
      return bad(key, value, "MI or MC");
  } else if (key == "tolerance") {
    if (!parseInt(value, 0, 32767, n)) return bad(key, value, "0..32767 encoder units");
    s.tolerance = n;
  } else if (key == "check-errors") {
    if (!parseBool(value, s.checkErrors)) return bad(key, value, "yes or no");
  } else {
    return fmt::format("unknown serial setting '{}' (robotsim run --help lists them; see docs/serial.md)", rawKey);
  }
  return {};
}

}  // namespace

diag::Result<RhinoSettings> applySettingArg(RhinoSettings s, std::string_view arg) {
  const std::size_t eq = arg.find('=');
  std::string error = eq == std::string_view::npos ? fmt::format("serial setting '{}': expected KEY=VALUE", arg)
                                                   : applySetting(s, arg.substr(0, eq), arg.substr(eq + 1));
  if (!error.empty()) return diag::Diagnostic{"--serial-set", {}, diag::Severity::Error, std::move(error)};
  return s;
}

diag::Result<RhinoSettings> applySettingsText(RhinoSettings s, std::string_view text, std::string_view name) {
  std::vector<diag::Diagnostic> errors;
  text = diag::withoutByteOrderMark(text);
  std::uint32_t lineNo = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view whole = text.substr(0, nl);
    std::string_view line = whole;
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    if (lineNo < UINT32_MAX) ++lineNo;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    const std::size_t eq = line.find('=');
    const std::string e = eq == std::string_view::npos ? std::string("expected key = value")
                                                       : applySetting(s, line.substr(0, eq), line.substr(eq + 1));
    if (e.empty()) continue;
    // The column of the key: where the trimmed line starts in the whole one.
    const std::size_t offset = static_cast<std::size_t>(line.data() - whole.data());
    const std::uint32_t col = offset >= UINT32_MAX ? UINT32_MAX : static_cast<std::uint32_t>(offset) + 1;
    errors.push_back({std::string(name), {lineNo, col}, diag::Severity::Error, e});
  }
  if (!errors.empty()) return diag::Result<RhinoSettings>(std::move(errors));
  return s;
}

std::vector<std::pair<std::string, std::string>> listSettings(const RhinoSettings& s) {
  std::vector<std::pair<std::string, std::string>> out = {
      {"baud", std::to_string(s.line.baud)},
      {"data-bits", std::to_string(s.line.dataBits)},
      {"parity", parityText(s.line.parity)},
      {"stop-bits", std::to_string(s.line.stopBits)},
      {"flow", flowText(s.line.flow)},
      {"line-end", lineEndText(s.lineEnd)},
      {"timeout", seconds(s.timeout)},
      {"poll", seconds(s.pollInterval)},
      {"stall-timeout", seconds(s.stallTimeout)},
      {"home-timeout", seconds(s.homeTimeout)},
      {"chunk", std::to_string(s.chunk)},
      {"refill", std::to_string(s.refill)},
      {"remaining", s.signedRemaining ? "signed" : "magnitude"},
  };
  for (int m = 0; m < 8; ++m)
    out.emplace_back(fmt::format("switch.{}", static_cast<char>('A' + m)),
                     bitSourceText(s.switches[static_cast<std::size_t>(m)]));
  for (int i = 0; i < kControllerLines; ++i)
    out.emplace_back(fmt::format("input.{}", i + 1), bitSourceText(s.inputs[static_cast<std::size_t>(i)]));
  out.emplace_back("input-active", s.inputsActiveLow ? "low" : "high");
  for (std::size_t i = 0; i < s.outputOn.size(); ++i) {
    out.emplace_back(fmt::format("output.{}.on", i + 1), s.outputOn[i]);
    out.emplace_back(fmt::format("output.{}.off", i + 1), s.outputOff[i]);
  }
  out.emplace_back("home-order", s.homeOrder.empty() ? "(motor-table order)" : s.homeOrder);
  out.emplace_back("home-search", std::to_string(s.homeSearch));
  out.emplace_back("home-direction", s.homeDirection < 0 ? "-" : "+");
  out.emplace_back("start", s.coordinated ? "MC" : "MI");
  out.emplace_back("tolerance", std::to_string(s.tolerance));
  out.emplace_back("check-errors", s.checkErrors ? "yes" : "no");
  return out;
}

}  // namespace rs::rhino
