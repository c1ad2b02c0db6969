#include "tools/cli/lib/report.h"

#include <fmt/format.h>

#include <cmath>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <span>

#include "base/seconds.h"
#include "base/text.h"
#include "tools/cli/lib/profile_report.h"
#include "runtime/run/trace.h"
#include "vm/io_lines.h"
#include "vm/stop_reason.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/placing.h"

namespace rs::cli {

namespace {

using Json = nlohmann::ordered_json;

std::string lampList(vm::IoMask bits) {
  std::string s;
  for (int line = 1; line <= vm::kIoCount; ++line)
    if (vm::lineIsOn(bits, line)) s += fmt::format("{}{}", s.empty() ? "" : ", ", line);
  return s.empty() ? "none" : s;
}

}  // namespace

bool RunReport::ok() const {
  return run && run->outcome() && run->outcome()->ok() && !diag::hasErrors(diagnostics) && omitted.errors == 0;
}

namespace {

// After a controller failure, stop was sent: a motor that was moving (or had
// a move sent) stopped somewhere between the last position the controller
// confirmed and the target the program commanded.
void printFault(std::ostream& out, const rhino::FaultState& f) {
  std::string uncertain;
  for (const rhino::FaultState::Motor& m : f.motors)
    if (m.uncertain())
      uncertain += fmt::format("{}{} between {} (last confirmed) and {} (last commanded)", uncertain.empty() ? "" : "; ",
                               m.letter, m.confirmed, m.commanded);
  out << "  fault           stop sent to every motor; 'motors' shows the positions the controller last confirmed\n";
  out << fmt::format("  uncertain       {}\n", uncertain.empty() ? std::string("none (no motor had a move under way)")
                                                                 : uncertain);
  const bool several = (f.outputsOn & (f.outputsOn - 1)) != 0;
  out << fmt::format("  left ON         {}\n",
                     f.outputsOn == 0 ? std::string("no output")
                                      : fmt::format("output{} {} (as last set: stopping the motors does not turn "
                                                    "outputs off)",
                                                    several ? "s" : "", lampList(f.outputsOn)));
}

// Each collision found (at most kShownCollisions), or "none" when the run
// checked and found none.
constexpr std::size_t kShownCollisions = 20;

std::uint32_t lineOf(const runtime::Run& run, const runtime::CollisionEvent& e) {
  return e.instruction < run.spec().image->lines.size() ? run.spec().image->lines[e.instruction] : 0;
}

void printCollisions(std::ostream& out, const runtime::Run& run) {
  const runtime::CollisionWatch* watch = run.rig().collisionWatch();
  if (!watch) return;
  const auto events = run.rig().collisions();
  if (events.empty()) out << "  collisions      none\n";
  for (std::size_t i = 0; i < events.size() && i < kShownCollisions; ++i)
    out << fmt::format("  {:<15} line {}, {} s: {}\n", i == 0 ? "collisions" : "", lineOf(run, events[i]),
                       base::formatSeconds(events[i].at), base::safeText(watch->describe(events[i])));
  if (events.size() > kShownCollisions)
    out << fmt::format("  {:<15} and {} more\n", "", events.size() - kShownCollisions);
}

// Parts the sinks took per hour of simulated time.
double throughput(const runtime::Run& run) {
  const runtime::CellDevices& d = *run.rig().devices();
  std::uint64_t taken = 0;
  for (std::size_t s = 0; s < run.rig().cell()->devices.sinks.size(); ++s) taken += d.taken(s);
  const double hours = static_cast<double>(run.rig().clock()) / 3.6e9;
  return hours > 0 ? static_cast<double>(taken) / hours : 0.0;
}

void printDevices(std::ostream& out, const runtime::Run& run) {
  const runtime::CellDevices* d = run.rig().devices();
  if (!d) return;
  const workcell::Devices& cell = run.rig().cell()->devices;
  const auto times = [](std::uint64_t n, const char* what) {
    return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
  };
  for (std::size_t s = 0; s < cell.sensors.size(); ++s)
    out << fmt::format("  {:<15} {}, turned ON {}\n", "sensor " + base::safeText(cell.sensors[s].name),
                       d->sensorOn(s) ? "ON" : "OFF", times(d->sensorCount(s), "time"));
  for (std::size_t c = 0; c < cell.conveyors.size(); ++c)
    out << fmt::format("  {:<15} {}, carried {}\n", "conveyor " + base::safeText(cell.conveyors[c].name),
                       d->running(c) ? "running" : "stopped", times(d->carried(c), "part"));
  for (std::size_t f = 0; f < cell.feeders.size(); ++f)
    out << fmt::format("  {:<15} fed {}\n", "feeder " + base::safeText(cell.feeders[f].name), times(d->fed(f), "part"));
  for (std::size_t s = 0; s < cell.sinks.size(); ++s)
    out << fmt::format("  {:<15} took {}\n", "sink " + base::safeText(cell.sinks[s].name), times(d->taken(s), "part"));
  if (!cell.sinks.empty()) out << fmt::format("  {:<15} {:.1f} parts per hour\n", "throughput", throughput(run));
}

Json devicesJson(const runtime::Run& run) {
  const runtime::CellDevices& d = *run.rig().devices();
  const workcell::Devices& cell = run.rig().cell()->devices;
  Json sensors = Json::array(), conveyors = Json::array(), feeders = Json::array(), sinks = Json::array();
  for (std::size_t s = 0; s < cell.sensors.size(); ++s)
    sensors.push_back({{"name", cell.sensors[s].name}, {"on", d.sensorOn(s)}, {"turned_on", d.sensorCount(s)}});
  for (std::size_t c = 0; c < cell.conveyors.size(); ++c)
    conveyors.push_back({{"name", cell.conveyors[c].name}, {"running", d.running(c)}, {"carried", d.carried(c)}});
  for (std::size_t f = 0; f < cell.feeders.size(); ++f) feeders.push_back({{"name", cell.feeders[f].name}, {"fed", d.fed(f)}});
  for (std::size_t s = 0; s < cell.sinks.size(); ++s) sinks.push_back({{"name", cell.sinks[s].name}, {"taken", d.taken(s)}});
  return {{"sensors", sensors},
          {"conveyors", conveyors},
          {"feeders", feeders},
          {"sinks", sinks},
          {"parts_per_hour", std::round(throughput(run) * 1e4) / 1e4}};
}

}  // namespace

void printCellLines(std::ostream& out, const runtime::Run& run) {
  const vm::Image& im = *run.spec().image;
  const std::vector<runtime::ObjectView> objects = run.rig().objects();
  const runtime::World* world = run.rig().world();
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const runtime::ObjectView& e = objects[o];
    if (!e.present) continue;
    std::string rest;  // where its last let-go settled it
    if (const auto& settled = world->restOf(o); settled && settled->settled())
      rest = "; " + runtime::settleText(run.rig().numbered(*settled), world->cell()).substr(std::string_view("settles ").size());
    const std::string named = e.as == e.name ? base::safeText(e.name)
                                             : fmt::format("{} AS {}", base::safeText(e.name), base::safeText(e.as));
    out << fmt::format("  {:<15} {} at {}, centre {}{}{}\n", fmt::format("object {}", e.number), named,
                       runtime::pointText({e.at.x(), e.at.y(), e.at.z()}),
                       runtime::pointText({e.centre.x(), e.centre.y(), e.centre.z()}),
                       e.held ? ", held" : e.moved ? ", moved" : "", rest);
  }
  if (world && world->fixtureCloseCount() > 0 && !run.rig().fixtureCloses().empty()) {
    const std::uint64_t n = world->fixtureCloseCount();
    const auto& first = run.rig().fixtureCloses().front();
    out << fmt::format("  {:<15} closed round a fixture {}, took nothing there (the warning at line {}: {})\n",
                       "gripper", n == 1 ? std::string("once") : fmt::format("{} times", n),
                       first.first < im.lines.size() ? im.lines[first.first] : 0,
                       runtime::fixtureCloseText(first.second, world->cell()));
  }
  if (world && world->longDropCount() > 0 && !run.rig().longDrops().empty()) {
    const std::uint64_t n = world->longDropCount();
    const auto& first = run.rig().longDrops().front();
    out << fmt::format("  {:<15} {} at line {}{}\n", "placing", runtime::longDropText(first.second, world->cell()),
                       first.first < im.lines.size() ? im.lines[first.first] : 0,
                       n == 1 ? std::string() : fmt::format(" ({} drops over {} in all)", n, runtime::kLongDrop));
  }
  if (const auto w = runtime::gripperWarning(run, im.sourceName))  // the warning printed before
    out << fmt::format("  gripper         closed {}, took nothing (the warning at line {})\n",
                       run.rig().world()->closeCount() == 1 ? std::string("once")
                                                         : fmt::format("{} times", run.rig().world()->closeCount()),
                       w->pos.line);
  printDevices(out, run);
}

void printTextSummary(std::ostream& out, const RunReport& r) {
  if (!r.run || !r.run->outcome()) return;
  const vm::Image& im = *r.run->spec().image;
  const vm::Machine& m = r.run->rig().machine();
  const vm::RunOutcome o = *r.run->outcome();
  const std::string where = o.ok() ? "" : fmt::format(" at line {}", im.lines[o.index]);
  out << fmt::format("run of {} on {}: {}{}\n", base::safeText(im.sourceName), base::safeText(im.robotName),
                     vm::stopReasonName(o.reason), where);
  out << fmt::format("  {}  {} s\n", r.realTime ? "elapsed time   " : "simulated time", base::formatSeconds(m.now()));
  out << fmt::format("  instructions    {} executed\n", o.steps);
  std::string motors;
  const auto pos = m.positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors += fmt::format("{}{}={}", i ? "  " : "", im.motors[i].letter, pos[i]);
  out << fmt::format("  motors          {}\n", motors);
  if (r.fault) printFault(out, *r.fault);
  if (const auto tcp = r.run->rig().tcp()) out << fmt::format("  tool centre     {}\n", runtime::pointText(*tcp));
  if (r.cellLines) printCellLines(out, *r.run);
  printCollisions(out, *r.run);
  out << fmt::format("  outputs         {}  (ON: {})\n", runtime::lampText(m.outputs()), lampList(m.outputs()));
  out << fmt::format("  inputs          {}  (ON: {})\n", runtime::lampText(m.inputs()), lampList(m.inputs()));
  std::string vars;
  for (std::size_t i = 0; i < im.variables.size(); ++i)
    vars += fmt::format("{}{}={}", i ? "  " : "", base::safeText(im.variables[i]), r.run->interpreter().variables()[i]);
  out << fmt::format("  variables       {}\n", vars.empty() ? "none" : vars);
}

nlohmann::ordered_json diagnosticJson(const diag::Diagnostic& d) {
  Json one = {{"file", d.file},
              {"line", d.pos.line},
              {"column", d.pos.col},
              {"severity", diag::severityName(d.severity)},
              {"message", d.message}};
  if (!d.code.empty()) one["code"] = d.code;
  if (!d.hint.empty()) one["hint"] = d.hint;
  return one;
}

nlohmann::ordered_json motorsJson(const runtime::Run& run) {
  const vm::Image& im = *run.spec().image;
  Json motors = Json::object();
  const auto pos = run.rig().machine().positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors[std::string(1, im.motors[i].letter)] = pos[i];
  return motors;
}

void addLinesAndVariablesJson(nlohmann::ordered_json& j, const runtime::Run& run) {
  const vm::Machine& m = run.rig().machine();
  const vm::Image& im = *run.spec().image;
  Json outputs = Json::array(), inputs = Json::array();
  for (int line = 1; line <= vm::kIoCount; ++line) {
    outputs.push_back(vm::lineIsOn(m.outputs(), line));
    inputs.push_back(vm::lineIsOn(m.inputs(), line));
  }
  j["outputs"] = outputs;
  j["inputs"] = inputs;
  Json vars = Json::object();
  for (std::size_t i = 0; i < im.variables.size(); ++i) vars[im.variables[i]] = run.interpreter().variables()[i];
  j["variables"] = vars;
}

void addCellJson(nlohmann::ordered_json& j, const runtime::Run& run) {
  if (run.rig().cell()) {
    Json objects = Json::array();
    const bool numbered = run.rig().devices() != nullptr;
    const runtime::World* world = run.rig().world();
    const std::vector<runtime::ObjectView> views = run.rig().objects();
    for (std::size_t o = 0; o < views.size(); ++o) {
      const runtime::ObjectView& e = views[o];
      if (!e.present) continue;
      Json one = {{"name", e.name}, {"at", runtime::roundedPoint({e.at.x(), e.at.y(), e.at.z()})},
                  {"centre", runtime::roundedPoint({e.centre.x(), e.centre.y(), e.centre.z()})}, {"held", e.held},
                  {"moved", e.moved}};
      if (e.as != e.name) one["as"] = e.as;     // its OBJECT line's AS name
      if (numbered) one["number"] = e.number;  // fed parts make the list's order no number
      // Where its last let-go settled it, and how far it dropped (to 1e-4).
      if (world && world->restOf(o) && world->restOf(o)->settled())
        one["settled"] = {{"on", runtime::supportText(run.rig().numbered(*world->restOf(o)), world->cell())},
                          {"drop", std::round(world->restOf(o)->drop * 1e4) / 1e4 + 0.0}};
      objects.push_back(std::move(one));
    }
    j["objects"] = objects;
    if (numbered) j["devices"] = devicesJson(run);
  }
}

void printJsonSummary(std::ostream& out, const RunReport& r) {
  Json j;
  // The text summary's word for a run that ran to its end (vm::stopReasonName), in both.
  j["status"] = r.ok() ? vm::stopReasonName(vm::StopReason::End) : "error";
  if (r.run && r.run->outcome()) {
    const vm::Machine& m = r.run->rig().machine();
    j["time"] = static_cast<double>(m.now()) / 1e6;
    j["steps"] = r.run->outcome()->steps;
    j["motors"] = motorsJson(*r.run);
    if (r.fault) {
      Json uncertain = Json::array(), on = Json::array();
      for (const rhino::FaultState::Motor& mo : r.fault->motors)
        if (mo.uncertain())
          uncertain.push_back({{"motor", std::string(1, mo.letter)}, {"confirmed", mo.confirmed}, {"commanded", mo.commanded}});
      for (int line = 1; line <= vm::kIoCount; ++line)
        if (vm::lineIsOn(r.fault->outputsOn, line)) on.push_back(line);
      j["fault"] = {{"message", r.fault->failure}, {"uncertain_motors", uncertain}, {"outputs_left_on", on}};
    }
    if (const auto tcp = r.run->rig().tcp()) j["tcp"] = runtime::roundedPoint(*tcp);
    if (r.cellLines) addCellJson(j, *r.run);
    if (const runtime::CollisionWatch* watch = r.run->rig().collisionWatch()) {
      Json collisions = Json::array();
      for (const runtime::CollisionEvent& e : r.run->rig().collisions())
        collisions.push_back({{"line", lineOf(*r.run, e)},
                              {"time", static_cast<double>(e.at) / 1e6},
                              {"part", watch->model().describe(e.contact.a)},
                              {"hits", watch->model().describe(e.contact.b)},
                              {"depth", std::round(e.depth * 1e4) / 1e4}});  // to 1e-4, as the trace
      j["collisions"] = collisions;
    }
    addLinesAndVariablesJson(j, *r.run);
    if (r.profile) j["profile"] = profileJson(*r.profile);
  } else {
    j["time"] = 0;
    j["steps"] = 0;
    j["motors"] = Json::object();
    j["outputs"] = Json::array();
    j["inputs"] = Json::array();
    j["variables"] = Json::object();
  }
  Json diags = Json::array();
  const std::size_t listed =
      r.maxDiagnostics == 0 ? r.diagnostics.size() : std::min(r.maxDiagnostics, r.diagnostics.size());
  diag::Omitted omitted = r.omitted;
  for (std::size_t i = listed; i < r.diagnostics.size(); ++i) omitted.count(r.diagnostics[i].severity);
  for (const diag::Diagnostic& d : std::span(r.diagnostics).first(listed)) diags.push_back(diagnosticJson(d));
  j["diagnostics"] = diags;
  if (omitted.any()) j["diagnostics_not_listed"] = {{"errors", omitted.errors}, {"warnings", omitted.warnings}};
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

}  // namespace rs::cli
