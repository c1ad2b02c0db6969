// A teach pendant as a live source (live_source.h): the page, the state as
// JSON, the commands. Commands run one at a time under a lock; the state is
// published after each, so a page reading it while a real robot moves gets
// the last state at once instead of waiting for the move.
#pragma once

#include <mutex>
#include <string>

#include "tools/live/live_source.h"
#include "tools/teach/pendant.h"

namespace rs::teach {

class PendantSource final : public live::LiveSource {
 public:
  /// `pendant` must outlive the source.
  PendantSource(Pendant& pendant, std::string page);

  std::string page() override { return page_; }
  std::uint64_t revision() override;
  std::string state() override;
  live::LiveReply command(const nlohmann::json& request) override;

  /// Publishes the pendant's state after a change made outside command().
  void publish();

 private:
  Pendant& pendant_;
  const std::string page_;
  std::mutex commands_;  // one operation at a time
  std::mutex published_;  // guards the two below
  std::uint64_t revision_ = 0;
  std::string state_;
};

}  // namespace rs::teach
