// A run, stopped, as a read-only live source (live_source.h): what the
// debugger's live view serves. The page is the teach page in its read-only
// mode (page.h); the state is the pendant's JSON (pendant_state.h) filled
// from the run's view at the moment it was published, plus where the run
// stands. Every command is refused with 403: the view follows a run, it
// does not move the robot. publish() is called on the thread that owns the
// run (after each stop); the server's threads read a copy under a lock.
#pragma once

#include <mutex>
#include <string>

#include "runtime/run/run.h"
#include "tools/live/live_source.h"

namespace rs::teach {

class RunSource final : public live::LiveSource {
 public:
  /// `program` names the program in the state; nothing is served until
  /// the first publish() but an empty state.
  RunSource(std::string page, std::string program);

  std::string page() override { return page_; }
  std::uint64_t revision() override;
  std::string state() override;
  live::LiveReply command(const nlohmann::json& request) override;

  /// `run` at its current moment becomes the state (a new revision);
  /// `message` says how it got there (a breakpoint, a step, ...).
  void publish(const runtime::Run& run, const std::string& message);

 private:
  const std::string page_;
  const std::string program_;
  std::mutex published_;  // guards the two below
  std::uint64_t revision_ = 0;
  std::string state_ = "{}";
};

}  // namespace rs::teach
