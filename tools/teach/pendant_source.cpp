#include "tools/teach/pendant_source.h"

#include "tools/teach/commands.h"

namespace rs::teach {

PendantSource::PendantSource(Pendant& pendant, std::string page) : pendant_(pendant), page_(std::move(page)) {
  publish();
}

void PendantSource::publish() {
  const PendantState s = pendant_.state();
  std::string json =
      pendantJson(s, pendant_.placements()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard lock(published_);
  state_ = std::move(json);
  revision_ = s.revision;
}

std::uint64_t PendantSource::revision() {
  std::lock_guard lock(published_);
  return revision_;
}

std::string PendantSource::state() {
  std::lock_guard lock(published_);
  return state_;
}

live::LiveReply PendantSource::command(const nlohmann::json& request) {
  std::lock_guard lock(commands_);
  const Outcome o = applyCommand(pendant_, request);
  publish();
  return {o.badRequest ? 400 : 200,
          {{"ok", o.ok}, {"message", o.message}, {"revision", pendant_.revision()}}};
}

}  // namespace rs::teach
