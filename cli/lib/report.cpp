#include "cli/lib/report.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/lib/trace.h"

namespace rs::cli {

namespace {

using Json = nlohmann::ordered_json;

std::string_view reasonText(vm::StopReason r) {
  switch (r) {
    case vm::StopReason::End: return "finished";
    case vm::StopReason::RuntimeError: return "runtime error";
    case vm::StopReason::Deadlock: return "deadlock";
    case vm::StopReason::StepLimit: return "step limit";
    case vm::StopReason::TimeLimit: return "time limit";
  }
  return "?";
}

std::string lampList(std::uint8_t bits) {
  std::string s;
  for (int i = 0; i < 8; ++i)
    if (bits & (1u << i)) s += fmt::format("{}{}", s.empty() ? "" : ", ", i + 1);
  return s.empty() ? "none" : s;
}

// Each object at the end of the run: where its AT corner is, and whether
// the gripper holds it or it was moved.
struct ObjectEnd {
  std::string_view name;
  Eigen::Vector3d at;
  bool held, moved;
};

std::vector<ObjectEnd> objectEnds(const RunReport& r, std::span<const std::int32_t> motors) {
  std::vector<ObjectEnd> ends;
  if (!r.grasping || !r.cell) return ends;
  for (std::size_t o = 0; o < r.cell->objects.size(); ++o) {
    const workcell::PlacedObject& placed = r.cell->objects[o];
    const Eigen::Isometry3d pose = r.grasping->objectPose(o, motors);
    const bool moved = (pose.matrix() - placed.F_world_design.matrix()).cwiseAbs().maxCoeff() > 1e-9;
    ends.push_back({placed.shape.name, pose * workcell::atCorner(placed.shape), r.grasping->held() == o, moved});
  }
  return ends;
}

}  // namespace

bool RunReport::ok() const {
  return outcome && outcome->ok() && !diag::hasErrors(diagnostics);
}

diag::Diagnostic runtimeDiagnostic(const vm::Image& image, const vm::RunOutcome& outcome, const std::string& file) {
  const diag::Pos pos{image.lines[outcome.index], image.columns[outcome.index]};
  return {file, pos, diag::Severity::Error,
          fmt::format("{}: {} (instruction {})", reasonText(outcome.reason), outcome.message, outcome.index + 1)};
}

void printTextSummary(std::ostream& out, const RunReport& r) {
  if (!r.outcome || !r.image || !r.vm) return;
  const vm::Image& im = *r.image;
  const vm::Machine& m = r.vm->machine();
  const vm::RunOutcome& o = *r.outcome;
  const std::string where = o.ok() ? "" : fmt::format(" at line {}", im.lines[o.index]);
  out << fmt::format("run of {} on {}: {}{}\n", im.sourceName, im.robotName, reasonText(o.reason), where);
  out << fmt::format("  {}  {} s\n", r.realTime ? "elapsed time   " : "simulated time", vm::formatSeconds(m.now()));
  out << fmt::format("  instructions    {} executed\n", o.steps);
  std::string motors;
  const auto pos = m.positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors += fmt::format("{}{}={}", i ? "  " : "", im.motors[i].letter, pos[i]);
  out << fmt::format("  motors          {}\n", motors);
  if (r.tool) out << fmt::format("  tool centre     {}\n", pointText(r.tool->tcp(pos)));
  const std::vector<ObjectEnd> objects = objectEnds(r, pos);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const ObjectEnd& e = objects[o];
    out << fmt::format("  {:<15} {} at {}{}\n", fmt::format("object {}", o + 1), e.name,
                       pointText({e.at.x(), e.at.y(), e.at.z()}), e.held ? ", held" : e.moved ? ", moved" : "");
  }
  out << fmt::format("  outputs         {}  (ON: {})\n", lampText(m.outputs()), lampList(m.outputs()));
  out << fmt::format("  inputs          {}  (ON: {})\n", lampText(m.inputs()), lampList(m.inputs()));
  std::string vars;
  for (std::size_t i = 0; i < im.variables.size(); ++i)
    vars += fmt::format("{}{}={}", i ? "  " : "", im.variables[i], r.vm->variables()[i]);
  out << fmt::format("  variables       {}\n", vars.empty() ? "none" : vars);
}

void printJsonSummary(std::ostream& out, const RunReport& r) {
  Json j;
  j["status"] = r.ok() ? "ok" : "error";
  if (r.outcome && r.image && r.vm) {
    const vm::Image& im = *r.image;
    const vm::Machine& m = r.vm->machine();
    j["time"] = static_cast<double>(m.now()) / 1e6;
    j["steps"] = r.outcome->steps;
    Json motors = Json::object();
    const auto pos = m.positions();
    for (std::size_t i = 0; i < pos.size(); ++i) motors[std::string(1, im.motors[i].letter)] = pos[i];
    j["motors"] = motors;
    if (r.tool) j["tcp"] = roundedPoint(r.tool->tcp(pos));
    if (r.grasping && r.cell) {
      Json objects = Json::array();
      for (const ObjectEnd& e : objectEnds(r, pos))
        objects.push_back({{"name", e.name}, {"at", roundedPoint({e.at.x(), e.at.y(), e.at.z()})}, {"held", e.held},
                           {"moved", e.moved}});
      j["objects"] = objects;
    }
    Json outputs = Json::array(), inputs = Json::array();
    for (int i = 0; i < 8; ++i) {
      outputs.push_back(((m.outputs() >> i) & 1) != 0);
      inputs.push_back(((m.inputs() >> i) & 1) != 0);
    }
    j["outputs"] = outputs;
    j["inputs"] = inputs;
    Json vars = Json::object();
    for (std::size_t i = 0; i < im.variables.size(); ++i) vars[im.variables[i]] = r.vm->variables()[i];
    j["variables"] = vars;
  } else {
    j["time"] = 0;
    j["steps"] = 0;
    j["motors"] = Json::object();
    j["outputs"] = Json::array();
    j["inputs"] = Json::array();
    j["variables"] = Json::object();
  }
  Json diags = Json::array();
  for (const diag::Diagnostic& d : r.diagnostics)
    diags.push_back({{"file", d.file},
                     {"line", d.pos.line},
                     {"column", d.pos.col},
                     {"severity", diag::severityName(d.severity)},
                     {"message", d.message}});
  j["diagnostics"] = diags;
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

}  // namespace rs::cli
