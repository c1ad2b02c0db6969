#include "tools/teach/run_source.h"

#include "tools/teach/pendant_state.h"

namespace rs::teach {

RunSource::RunSource(std::string page, std::string program) : page_(std::move(page)), program_(std::move(program)) {}

std::uint64_t RunSource::revision() {
  std::lock_guard lock(published_);
  return revision_;
}

std::string RunSource::state() {
  std::lock_guard lock(published_);
  return state_;
}

live::LiveReply RunSource::command(const nlohmann::json&) {
  return {403,
          {{"ok", false},
           {"message", "read-only: this page follows robotsim debug; jog and teach with robotsim teach"},
           {"revision", revision()}}};
}

void RunSource::publish(const runtime::Run& run, const std::string& message) {
  const runtime::RunView v = run.view();
  PendantState s;
  s.program = program_;
  s.cell = run.rig().cell() ? run.rig().cell()->name : "";
  s.motors = run.spec().image->motors;
  s.encoders = v.motors;
  s.tcp = v.tcp;
  s.gripper = gripperState(s.motors, s.encoders);
  s.inputs = v.inputs;
  s.outputs = v.outputs;
  for (const runtime::ObjectView& o : v.objects) s.objects.push_back({std::string(o.name), o.pose, o.held, o.moved, o.present});
  if (run.rig().cell()) addDeviceStates(*run.rig().cell(), run.rig().devices(), s);
  s.clock = v.clock;
  s.message = message;
  std::vector<Eigen::Isometry3d> placed;
  if (run.rig().cell())
    for (const workcell::PlacedObject& o : run.rig().cell()->objects) placed.push_back(o.F_world_design);
  s.revision = revision() + 1;  // publish() is called from one thread only
  nlohmann::ordered_json json = pendantJson(s, placed);
  json["readOnly"] = true;
  json["line"] = v.line;
  json["instruction"] = v.instruction + 1;  // numbered from 1, as disasm and the debugger's messages
  json["steps"] = v.steps;
  json["finished"] = v.finished;
  std::string text = json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard lock(published_);
  state_ = std::move(text);
  revision_ = s.revision;
}

}  // namespace rs::teach
