#include "runtime/run/trace.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/seconds.h"
#include "base/text.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/placing.h"
#include "vm/disasm.h"

namespace rs::runtime {

namespace {

// The variable an instruction wrote, if any (slot b).
bool writesVariable(const vm::Instr& in) { return vm::has(in.op, vm::kWritesVariable); }

double seconds(vm::Micros t) { return static_cast<double>(t) / 1e6; }

}  // namespace

std::string pointText(const std::array<double, 3>& p) {
  const auto num = [](double v) {
    std::string s = fmt::format("{:.2f}", v);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? std::string("0") : s;
  };
  return fmt::format("({}, {}, {})", num(p[0]), num(p[1]), num(p[2]));
}

std::array<double, 3> roundedPoint(const std::array<double, 3>& p) {
  std::array<double, 3> r{};
  for (std::size_t i = 0; i < 3; ++i) r[i] = std::round(p[i] * 1e4) / 1e4 + 0.0;
  return r;
}

// One character a line: its digit when on, '.' when off.
std::string lampText(vm::IoMask bits) {
  static_assert(vm::kIoCount <= 9, "a lamp is one digit");
  std::string s(vm::kIoCount, '.');
  for (int line = 1; line <= vm::kIoCount; ++line)
    if (vm::lineIsOn(bits, line)) s[static_cast<std::size_t>(line - 1)] = static_cast<char>('0' + line);
  return s;
}

std::string graspText(const runtime::GraspEvent& event, const workcell::Workcell& cell, std::uint32_t number) {
  const std::string what = fmt::format("{} {} (object {})", event.held ? "takes" : "lets go of",
                                       base::safeText(cell.objects[event.object].shape.name),
                                       number ? number : event.object + 1);
  // A hand-over names the other robot; a let-go by an opening move settles
  // (RESET puts it back: no settling).
  if (event.other && *event.other < cell.robots.size()) {
    const std::string other = base::safeText(cell.robots[*event.other].labelOf());
    return event.held ? fmt::format("{} from robot '{}'", what, other) : fmt::format("{}: robot '{}' has it", what, other);
  }
  if (event.held || !event.settled()) return what;
  return what + ": it " + runtime::settleText(event, cell);  // event numbered by the caller
}

std::string closesOnNothingText(const runtime::EmptyClose& e, const workcell::Workcell& cell) {
  if (e.fixture) return runtime::fixtureCloseText(e, cell);
  const std::string nearest = runtime::emptyCloseText(e, cell);
  return nearest.empty() ? std::string("closes on nothing") : "closes on nothing (" + nearest + ")";
}

TraceWriter::TraceWriter(std::ostream& out, TraceFormat format, const runtime::Run& run)
    : out_(out), format_(format), run_(run) {}

bool TraceWriter::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  if (format_ == TraceFormat::Text) textHeader(vm);
  inputEvents();
  if (format_ == TraceFormat::Text) text(vm, index);
  else json(vm, index);
  collisionEvents();
  return false;
}

void TraceWriter::finish() {
  // What the cell did after the last step (at END's instant, or in a step cut short).
  if (run_.rig().recordsAfterLastStep()) inputEvents();
  collisionEvents();
}

namespace {

// A run-off's settling as a let-go's, for the words placing.h gives it.
GraspEvent runOffSettling(const DeviceEvent& e) {
  GraspEvent g{e.at, e.object, false, Eigen::Isometry3d::Identity(), e.on, e.support, e.drop};
  g.number = e.number, g.supportNumber = e.supportNumber;
  return g;
}

}  // namespace

// One line per input change during the step (or since the last step), at
// its time and with its cause, before the step's own line.
std::string deviceEventText(const DeviceEvent& e, const workcell::Workcell& cell) {
  const workcell::Devices& d = cell.devices;
  const auto object = [&] {
    return fmt::format("{} (object {})", base::safeText(cell.objects[e.object].shape.name), e.number);
  };
  switch (e.kind) {
    case DeviceEvent::Kind::SensorOn: return fmt::format("sensor {} ON", base::safeText(d.sensors[e.device].name));
    case DeviceEvent::Kind::SensorOff: return fmt::format("sensor {} OFF", base::safeText(d.sensors[e.device].name));
    case DeviceEvent::Kind::Fed:
      return fmt::format("feeder {}: {} at {}", base::safeText(d.feeders[e.device].name), object(),
                         pointText(std::array<double, 3>{e.place.x(), e.place.y(), e.place.z()}));
    case DeviceEvent::Kind::Waits:
      return fmt::format("feeder {}: waits, its place is taken by {}", base::safeText(d.feeders[e.device].name),
                         object());
    case DeviceEvent::Kind::Taken: return fmt::format("sink {}: takes {}", base::safeText(d.sinks[e.device].name), object());
    case DeviceEvent::Kind::RunsOff: {
      // Worded as a let-go's settling is.
      const std::string how = e.on == workcell::Settled::On::Nothing
                                  ? std::string("nothing under it, it stays there")
                                  : "it " + runtime::settleText(runOffSettling(e), cell);
      return fmt::format("conveyor {}: {} runs off its end: {}", base::safeText(d.conveyors[e.device].name), object(),
                         how);
    }
  }
  return "";
}

void TraceWriter::deviceEvent(const DeviceEvent& e) {
  const workcell::Workcell& cell = *run_.rig().cell();
  if (format_ == TraceFormat::Text) {
    out_ << fmt::format("{:>10}  {}\n", base::formatSeconds(e.at), deviceEventText(e, cell));
    return;
  }
  nlohmann::ordered_json j;
  const workcell::Devices& d = cell.devices;
  const bool sensor = e.kind == DeviceEvent::Kind::SensorOn || e.kind == DeviceEvent::Kind::SensorOff;
  const bool runOff = e.kind == DeviceEvent::Kind::RunsOff;
  j["event"] = sensor ? "sensor" : e.kind == DeviceEvent::Kind::Taken ? "sink" : runOff ? "conveyor" : "feeder";
  j["time"] = seconds(e.at);
  j["name"] = sensor ? d.sensors[e.device].name
              : e.kind == DeviceEvent::Kind::Taken ? d.sinks[e.device].name
              : runOff                             ? d.conveyors[e.device].name
                                                   : d.feeders[e.device].name;
  if (sensor) j["on"] = e.kind == DeviceEvent::Kind::SensorOn;
  if (!sensor) {
    j["object"] = e.number;
    j["part"] = cell.objects[e.object].shape.name;
  }
  if (e.kind == DeviceEvent::Kind::Fed) j["at"] = roundedPoint(std::array<double, 3>{e.place.x(), e.place.y(), e.place.z()});
  if (e.kind == DeviceEvent::Kind::Waits) j["waits"] = true;
  if (runOff && e.on != workcell::Settled::On::Nothing) {
    // As a let-go's "grasp": {"settled": ...}.
    nlohmann::ordered_json settled;
    settled["on"] = runtime::supportText(runOffSettling(e), cell);
    if (e.on != workcell::Settled::On::Floor) settled["object"] = e.supportNumber;
    settled["belt"] = e.on == workcell::Settled::On::Belt;
    settled["drop"] = std::round(e.drop * 1e4) / 1e4 + 0.0;
    j["settled"] = settled;
  }
  j["text"] = deviceEventText(e, cell);
  out_ << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

void TraceWriter::inputEvents() {
  // The devices' events and the inputs' changes in time order; at one
  // instant a device's first (a sensor's edge before the input its wire drives).
  const auto devices = run_.rig().devicesOfLastStep();
  std::size_t next = 0;
  for (const Rig::InputChangeRecord& c : run_.rig().inputsOfLastStep()) {
    for (; next < devices.size() && devices[next].at <= c.at; ++next) deviceEvent(devices[next]);
    if (format_ == TraceFormat::Text) {
      out_ << fmt::format("{:>10}  {}\n", base::formatSeconds(c.at), base::safeText(inputChangeText(c.cause)));
    } else {
      nlohmann::ordered_json j;
      j["event"] = "input";
      j["time"] = seconds(c.at);
      j["input"] = c.cause.input;
      j["on"] = c.cause.on;
      j["cause"] = inputCauseWord(c.cause.kind);
      if (c.cause.line) j["cause_line"] = c.cause.line;
      if (!c.cause.source.empty()) j["source"] = c.cause.source;
      j["text"] = inputChangeText(c.cause);
      out_ << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    }
  }
  for (; next < devices.size(); ++next) deviceEvent(devices[next]);
}

// One line per collision found since the last step traced: its time, the
// move's line, the parts.
void TraceWriter::collisionEvents() {
  const auto events = run_.rig().collisions();
  const runtime::CollisionWatch* watch = run_.rig().collisionWatch();
  for (; collisionsShown_ < events.size() && watch; ++collisionsShown_) {
    const runtime::CollisionEvent& e = events[collisionsShown_];
    const auto& lines = run_.spec().image->lines;
    const std::uint32_t line = e.instruction < lines.size() ? lines[e.instruction] : 0;
    if (format_ == TraceFormat::Text) {
      out_ << fmt::format("{:>10}  collision at line {}: {}\n", base::formatSeconds(e.at), line,
                          base::safeText(watch->describe(e)));
    } else {
      const workcell::CollisionModel& m = watch->model();
      nlohmann::ordered_json j;
      j["event"] = "collision";
      j["time"] = seconds(e.at);
      j["line"] = line;
      j["instr"] = e.instruction + 1;
      j["part"] = m.describe(e.contact.a);
      j["hits"] = m.describe(e.contact.b);
      j["depth"] = std::round(e.depth * 1e4) / 1e4;  // to 1e-4: what a message says, not the last bits
      out_ << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    }
  }
}

// The column heads, once, before anything of the first step (the devices'
// and inputs' events during it come before its own line).
void TraceWriter::textHeader(const vm::Interpreter& vm) {
  if (headerDone_) return;
  const vm::Image& im = vm.image();
  // Wide enough for every motor at the longest value its range allows.
  for (const vm::MotorSpec& m : im.motors)
    motorsWidth_ += 3 + std::max(fmt::formatted_size("{}", m.min), fmt::formatted_size("{}", m.max));
  out_ << fmt::format("{:>10}  {:>5}  {:>5}  {:<28}  {:<{}}  {:<8}  {}{}\n", "time", "instr", "line", "instruction",
                      "motors", motorsWidth_, "outputs", run_.rig().world() ? fmt::format("{:<28}  ", "tool centre point") : "",
                      "changed");
  headerDone_ = true;
}

void TraceWriter::text(const vm::Interpreter& vm, std::uint32_t index) {
  const vm::Image& im = vm.image();
  std::string motors;
  const auto pos = vm.machine().positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors += fmt::format("{}{}={}", i ? " " : "", im.motors[i].letter, pos[i]);
  const vm::Instr& in = im.code[index];
  std::string changed = writesVariable(in)
                            ? fmt::format("{}={}", base::safeText(im.variables[in.b]), vm.variables()[in.b])
                            : std::string();
  if (const runtime::GraspEvent* g = run_.rig().graspOfLastStep())
    changed += (changed.empty() ? "" : "  ") + graspText(run_.rig().numbered(*g), run_.rig().world()->cell(), run_.rig().objectNumber(g->object));
  if (vm::info(in.op).format == vm::Format::Point && !im.points[in.b].origin.empty())
    changed += (changed.empty() ? "" : "  ") + fmt::format("{} from {}", base::safeText(im.points[in.b].name),
                                                           base::safeText(im.points[in.b].origin));
  if (const runtime::EmptyClose* e = run_.rig().emptyCloseOfLastStep())
    changed += std::string(changed.empty() ? "" : "  ") + closesOnNothingText(*e, run_.rig().world()->cell());
  const std::optional<std::array<double, 3>> tool = run_.rig().world() ? run_.rig().world()->tcp(pos, run_.rig().robotIndex()) : std::nullopt;
  const std::string tcp = tool ? fmt::format("{:<28}  ", pointText(*tool)) : std::string();
  std::string row = fmt::format("{:>10}  {:>5}  {:>5}  {:<28}  {:<{}}  {}  {}{}", base::formatSeconds(vm.machine().now()),
                                index + 1, im.lines[index], vm::instructionText(im, index), motors, motorsWidth_,
                                lampText(vm.machine().outputs()), tcp, changed);
  while (!row.empty() && row.back() == ' ') row.pop_back();
  out_ << row << '\n';
}

void TraceWriter::json(const vm::Interpreter& vm, std::uint32_t index) {
  const vm::Image& im = vm.image();
  const vm::Instr& in = im.code[index];
  nlohmann::ordered_json j;
  j["time"] = seconds(vm.machine().now());
  j["instr"] = index + 1;
  j["line"] = im.lines[index];
  j["op"] = vm::info(in.op).name;
  j["text"] = vm::instructionText(im, index);
  nlohmann::ordered_json motors = nlohmann::ordered_json::object();
  const auto pos = vm.machine().positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors[std::string(1, im.motors[i].letter)] = pos[i];
  j["motors"] = motors;
  nlohmann::ordered_json outputs = nlohmann::ordered_json::array();
  for (int line = 1; line <= vm::kIoCount; ++line) outputs.push_back(vm::lineIsOn(vm.machine().outputs(), line));
  j["outputs"] = outputs;
  if (const runtime::World* world = run_.rig().world())
    if (const auto tool = world->tcp(pos, run_.rig().robotIndex())) j["tcp"] = roundedPoint(*tool);
  nlohmann::ordered_json changed = nlohmann::ordered_json::object();
  if (writesVariable(in)) changed[im.variables[in.b]] = vm.variables()[in.b];
  j["changed"] = changed;
  if (vm::info(in.op).format == vm::Format::Point && !im.points[in.b].origin.empty())
    j["point_from"] = im.points[in.b].origin;
  if (const runtime::GraspEvent* g = run_.rig().graspOfLastStep()) {
    const workcell::Workcell& cell = run_.rig().world()->cell();
    j["grasp"] = {{"object", run_.rig().objectNumber(g->object)}, {"name", cell.objects[g->object].shape.name},
                  {"held", g->held}};
    if (g->other && *g->other < cell.robots.size())  // a hand-over: from whom, or to whom
      j["grasp"][g->held ? "from" : "to"] = cell.robots[*g->other].labelOf();
    if (g->settled()) {
      nlohmann::ordered_json settled;
      settled["on"] = runtime::supportText(run_.rig().numbered(*g), cell);
      if (g->on != workcell::Settled::On::Floor) settled["object"] = run_.rig().objectNumber(g->support);
      settled["belt"] = g->on == workcell::Settled::On::Belt;
      settled["drop"] = std::round(g->drop * 1e4) / 1e4 + 0.0;
      j["grasp"]["settled"] = settled;
    }
  }
  if (const runtime::EmptyClose* e = run_.rig().emptyCloseOfLastStep()) {
    nlohmann::ordered_json empty;
    empty["tcp"] = roundedPoint({e->tcp.x(), e->tcp.y(), e->tcp.z()});
    if (e->fixture) empty["fixture"] = *e->fixture + 1;
    if (e->nearest) {
      empty["nearest"] = *e->nearest + 1;
      empty["name"] = run_.rig().world()->cell().objects[*e->nearest].shape.name;
      empty["distance"] = std::round(e->distance * 1e4) / 1e4;
      const Eigen::Vector3d offset = e->centre - e->tcp;
      empty["centre_offset"] = roundedPoint({offset.x(), offset.y(), offset.z()});
    }
    empty["text"] = closesOnNothingText(*e, run_.rig().world()->cell());
    j["closes_on_nothing"] = empty;
  }
  out_ << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

}  // namespace rs::runtime
