#include "tools/cli/lib/profile_report.h"

#include <fmt/format.h>

#include "base/seconds.h"
#include "base/text.h"
#include "vm/interpreter.h"

namespace rs::cli {
namespace {

using Json = nlohmann::ordered_json;
using runtime::TimeSplit;

// A share of the total in tenths of a percent, rounded half up: integer
// arithmetic, the same digits on every machine.
std::string percent(vm::Micros part, vm::Micros total) {
  if (total <= 0) return "0.0 %";
  const vm::Micros permille = (part * 1000 + total / 2) / total;
  return fmt::format("{}.{} %", permille / 10, permille % 10);
}

std::string seconds(vm::Micros t) { return base::formatSeconds(t) + " s"; }

std::string splitColumns(const TimeSplit& s) {
  return fmt::format("{:>11} {:>11} {:>11} {:>11}", seconds(s.total()), seconds(s.moving), seconds(s.waiting),
                     seconds(s.gripper));
}

Json splitJson(const TimeSplit& s) {
  return {{"total_us", s.total()}, {"moving_us", s.moving}, {"waiting_us", s.waiting}, {"gripper_us", s.gripper},
          {"other_us", s.other}};
}

Json namedJson(const std::vector<runtime::NamedTime>& list, const char* countName) {
  Json out = Json::array();
  for (const runtime::NamedTime& n : list) {
    Json one = {{"name", n.name}, {"line", n.line}, {countName, n.count}};
    one.update(splitJson(n.time));
    out.push_back(std::move(one));
  }
  return out;
}

void printNamed(std::ostream& out, const char* title, const char* countName,
                const std::vector<runtime::NamedTime>& list) {
  if (list.empty()) return;
  out << fmt::format("  {:<24} {:>11} {:>11} {:>11} {:>11} {:>7}\n", title, "total", "moving", "waiting", "gripper",
                     countName);
  for (const runtime::NamedTime& n : list)
    out << fmt::format("    {:<22} {} {:>7}\n", fmt::format("{} (line {})", base::safeText(n.name), n.line),
                       splitColumns(n.time), n.count);
}

}  // namespace

void printTextProfile(std::ostream& out, const runtime::Profile& p) {
  const vm::Micros total = p.total.total();
  out << fmt::format("profile: {} simulated, {} move{}\n", seconds(total), p.moves, p.moves == 1 ? "" : "s");
  for (auto [name, t] : {std::pair{"moving", p.total.moving}, std::pair{"waiting", p.total.waiting},
                         std::pair{"gripper", p.total.gripper}, std::pair{"other", p.total.other}})
    out << fmt::format("  {:<10} {:>11} {:>8}\n", name, seconds(t), percent(t, total));
  out << fmt::format("  {:<24} {:>11} {:>11} {:>11} {:>11} {:>7}\n", "source line", "total", "moving", "waiting",
                     "gripper", "steps");
  for (const runtime::LineTime& l : p.lines)
    out << fmt::format("    {:<22} {} {:>7}\n", fmt::format("line {}", l.line), splitColumns(l.time), l.steps);
  printNamed(out, "label", "steps", p.labels);
  printNamed(out, "subroutine (with calls)", "calls", p.subroutines);
  if (!p.inputWaits.empty()) {
    out << fmt::format("  {:<48} {:>11} {:>7}\n", "waiting for inputs (by what ended the wait)", "waiting", "waits");
    for (const runtime::InputWait& w : p.inputWaits)
      out << fmt::format("    {:<46} {:>11} {:>7}\n", fmt::format("input {}: {}", w.input, base::safeText(w.driver)),
                         seconds(w.time), w.waits);
  }
  if (p.slowest.empty()) return;
  out << "  slowest moves\n";
  for (std::size_t i = 0; i < p.slowest.size(); ++i) {
    const runtime::SlowMove& m = p.slowest[i];
    out << fmt::format("    {}. line {}: {} from {} (motor {} {} -> {})\n", i + 1, m.line, seconds(m.duration),
                       seconds(m.start), m.motor, m.from, m.to);
  }
}

Json profileJson(const runtime::Profile& p) {
  Json j = splitJson(p.total);
  j["moves"] = p.moves;
  Json lines = Json::array();
  for (const runtime::LineTime& l : p.lines) {
    Json one = {{"line", l.line}, {"steps", l.steps}};
    one.update(splitJson(l.time));
    lines.push_back(std::move(one));
  }
  j["lines"] = std::move(lines);
  j["labels"] = namedJson(p.labels, "steps");
  j["subroutines"] = namedJson(p.subroutines, "calls");
  Json slowest = Json::array();
  for (const runtime::SlowMove& m : p.slowest)
    slowest.push_back({{"line", m.line},
                       {"instruction", m.instruction + 1},
                       {"step", m.step + 1},
                       {"start_us", m.start},
                       {"duration_us", m.duration},
                       {"motor", std::string(1, m.motor)},
                       {"from", m.from},
                       {"to", m.to}});
  j["slowest_moves"] = std::move(slowest);
  Json waits = Json::array();
  for (const runtime::InputWait& w : p.inputWaits)
    waits.push_back({{"input", w.input}, {"driver", w.driver}, {"waits", w.waits}, {"waiting_us", w.time}});
  j["input_waits"] = std::move(waits);
  return j;
}

}  // namespace rs::cli
