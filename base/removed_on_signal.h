// A temporary file that Ctrl-C, SIGTERM or a closed terminal (SIGHUP) must
// not leave behind: while a RemovedOnSignal lives, those signals, when they
// would end the process anyway (their disposition is the default one),
// first remove the file, then end the process as they would have (the
// default disposition, the signal raised again: the exit status is the
// signal's). A signal some code of ours handles itself (the serial layer's
// Ctrl-C, the debugger's, the terminal pendant's) is left to it: the
// process goes on, and so does the write, which then removes or renames
// its temporary as usual. SIGKILL cannot be caught: its temporaries stay.
//
// The handler reaches only a fixed table of paths (async-signal-safe:
// unlink, signal, raise); a path too long for it, or more temporaries at
// once than it holds, are written as before, unprotected.
#pragma once

#include <string>

namespace rs::base {

class RemovedOnSignal {
 public:
  explicit RemovedOnSignal(const std::string& path);
  ~RemovedOnSignal() { release(); }
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

  /// From now on a signal leaves the file alone (it was renamed into
  /// place, removed, or is about to be exchanged with another).
  void release();

 private:
  int slot_ = -1;
};

}  // namespace rs::base
