// A workcell's devices and wires in words (issue 35): one sentence per
// device, the same in the language server's hover on a device line and in
// `robotsim describe` (tools/cli/lib), so that the two never say a device
// two ways. Names are quoted with backticks (Markdown in the hover, plain
// quotes on a terminal). The devices may be read but not yet resolved (the
// hover reads the editor's text): nothing here needs an index filled in.
#pragma once

#include <string>

#include "model/workcell/devices.h"

namespace rs::lsp {

/// A signal as people read it: "always on", "always off", "output 1",
/// "input 2 of robot `left`", "sensor `eye`".
std::string signalWords(const workcell::Signal& s);
/// A sensor's shape in its SENSOR line's words: "BEAM 300 520 440 300 520
/// 760" or "ZONE l r t b f bk" (the edges as BOX writes them).
std::string sensorShape(const workcell::Sensor& s);

/// "sensor `eye`: a beam from (300, 520, 440) to (300, 520, 760); on while
/// it sees parts across it".
std::string sensorSentence(const workcell::Sensor& s);
/// "conveyor `infeed`: runs its belt at 100 length units per second while
/// output 1 is on".
std::string conveyorSentence(const workcell::Conveyor& v);
/// "feeder `parts`: puts a `block` at (-740, 500, 620) at the start and
/// then every 6 s" (or "on each rising edge of ...", ", at most N").
std::string feederSentence(const workcell::Feeder& f);
/// "sink `done`: a part whose centre enters the zone from (...) to (...)
/// leaves the cell, counted".
std::string sinkSentence(const workcell::Sink& k);
/// "wire: input 1 follows sensor `eye`, 0.5 s later, inverted".
std::string wireSentence(const workcell::Wire& w);

}  // namespace rs::lsp
