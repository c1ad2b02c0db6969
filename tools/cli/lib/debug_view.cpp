#include "tools/cli/lib/debug_view.h"

#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>

#include "tools/teach/page.h"

namespace rs::cli {

DebugView::DebugView(const workcell::Workcell& cell, const std::string& program)
    : source_(teach::runViewPageHtml(cell, program), program), server_(source_, live::randomToken()) {}

DebugView::~DebugView() { server_.stop(); }

std::shared_ptr<DebugView> DebugView::start(debug::DebugSession& session, const std::string& program, std::string& error) {
  const workcell::Workcell* cell = session.run().rig().cell();
  if (!cell) {
    error = "--view draws the workcell: give one with --cell CELL (or a '; cell:' line in the program)";
    return nullptr;
  }
  std::shared_ptr<DebugView> view(new DebugView(*cell, program));
  view->publish(session, session.lastStop());
  // The server's threads never take SIGINT: Ctrl-C is the prompt's and the
  // run's (debug_terminal.h), on this thread.
  sigset_t interrupt, previous;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  pthread_sigmask(SIG_BLOCK, &interrupt, &previous);
  const bool listening = view->server_.start("127.0.0.1", 0, error);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (!listening) return nullptr;
  session.onStop([weak = std::weak_ptr<DebugView>(view)](const debug::DebugSession& s, const debug::Stop& stop) {
    if (const std::shared_ptr<DebugView> v = weak.lock()) v->publish(s, stop);
  });
  return view;
}

void DebugView::publish(const debug::DebugSession& session, const debug::Stop& stop) {
  source_.publish(session.run(), stop.message.empty() ? std::string(vm::debuggerName(stop.reason)) : stop.message);
}

}  // namespace rs::cli
