// `robotsim run --cell CELL --profile`: each robot's profile (where its
// time went: moving, waiting on which input and driven by what, the
// gripper), from its own log (runtime/run/profile.h), and its share of
// the cell's cycle: each kind of its time, and the time after its program
// ended, as parts of the cell's whole simulated time.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <vector>

#include "runtime/run/cell_run.h"
#include "runtime/run/profile.h"

namespace rs::cli {

/// Every robot's profile (none for a robot that kept no log).
std::vector<std::optional<runtime::Profile>> cellProfiles(const runtime::CellRun& cell);

/// A section per robot: its profile as `run --profile` prints one, then
/// its share of the cell's cycle.
void printCellProfiles(std::ostream& out, const runtime::CellRun& cell,
                       const std::vector<std::optional<runtime::Profile>>& profiles);

/// Robot `p`'s "profile" member of the JSON summary: the profile's members
/// and "cell_share" (its kinds and "ended_us" against "cell_us").
nlohmann::ordered_json cellProfileJson(const runtime::CellRun& cell, std::size_t p, const runtime::Profile& profile);

}  // namespace rs::cli
