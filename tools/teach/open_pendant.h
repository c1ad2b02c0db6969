// From what a user names to a pendant: the program file, the cell (--cell,
// or the program's "; cell:" directive), the device. Every front end of
// the pendant (the web page's `robotsim teach`, the terminal pendant)
// opens it here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/program.h"
#include "launch/rhino.h"
#include "tools/teach/pendant.h"

namespace rs::teach {

struct TeachRequest {
  launch::ProgramRequest program;  ///< file, --cell, --lib
  launch::SerialRequest serial;    ///< --device and its settings
};

struct OpenedPendant {
  std::unique_ptr<Pendant> pendant;
  launch::LoadedProgram loaded;  ///< the descriptions read, for the diagnostics' source lines
  std::vector<diag::Diagnostic> diagnostics;
  bool ok() const { return pendant != nullptr; }
};

/// The cell must have a robot; the program must be a source file (an
/// image has no points to edit). Problems come back as diagnostics.
OpenedPendant openPendant(const TeachRequest& request);

}  // namespace rs::teach
