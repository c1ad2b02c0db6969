// `robotsim describe`'s devices and wires (issue 35): each sensor,
// conveyor, feeder and sink of a WORKCELL and each WIRE to an input, in
// the sentences the language server's hover says (tools/lsp/device_text.h)
// and as JSON with every clause of its line.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "model/workcell/model.h"

namespace rs::cli {

/// "devices" and one line per sensor, conveyor, feeder, sink and wire;
/// nothing for a cell without devices.
void describeDevicesText(const workcell::Workcell& cell, std::ostream& out);
/// {"sensors": [...], "conveyors": [...], "feeders": [...], "sinks": [...]}:
/// each a list of objects with `name` and the clauses of its line.
nlohmann::ordered_json describeDevicesJson(const workcell::Workcell& cell);
/// The WIRE lines: [{"input", "robot", "source", "after", "inverted"}].
nlohmann::ordered_json describeWiresJson(const workcell::Workcell& cell);

}  // namespace rs::cli
