#include "tools/cli/lib/cell_profile.h"

#include <fmt/format.h>

#include "base/seconds.h"
#include "base/text.h"
#include "tools/cli/lib/profile_report.h"

namespace rs::cli {

namespace {

using Json = nlohmann::ordered_json;

// A share in tenths of a percent, rounded half up, in integers: the same
// digits on every machine (as profile_report.cpp's).
std::string percent(vm::Micros part, vm::Micros total) {
  if (total <= 0) return "0.0 %";
  const vm::Micros permille = (part * 1000 + total / 2) / total;
  return fmt::format("{}.{} %", permille / 10, permille % 10);
}

// The time from the robot's end to the cell's: it stood still, done.
vm::Micros endedFor(const runtime::CellRun& cell, std::size_t p) {
  return cell.clock() > cell.endTime(p) ? cell.clock() - cell.endTime(p) : 0;
}

}  // namespace

std::vector<std::optional<runtime::Profile>> cellProfiles(const runtime::CellRun& cell) {
  std::vector<std::optional<runtime::Profile>> out(cell.size());
  for (std::size_t p = 0; p < cell.size(); ++p)
    if (const runtime::RunLog* log = cell.robot(p).log()) out[p] = runtime::profileOf(*cell.robot(p).spec().image, *log);
  return out;
}

void printCellProfiles(std::ostream& out, const runtime::CellRun& cell,
                       const std::vector<std::optional<runtime::Profile>>& profiles) {
  for (std::size_t p = 0; p < cell.size(); ++p) {
    if (!profiles[p]) continue;
    const runtime::Profile& pr = *profiles[p];
    out << fmt::format("\nprofile of robot {} ({}):\n", base::safeText(cell.label(p)),
                       base::safeText(cell.robot(p).spec().image->sourceName));
    printTextProfile(out, pr);
    const vm::Micros all = cell.clock();
    out << fmt::format("share of the cell's cycle ({} s): moving {}, waiting {}, gripper {}, ended {}\n",
                       base::formatSeconds(all), percent(pr.total.moving, all), percent(pr.total.waiting, all),
                       percent(pr.total.gripper, all), percent(endedFor(cell, p), all));
  }
}

Json cellProfileJson(const runtime::CellRun& cell, std::size_t p, const runtime::Profile& profile) {
  Json j = profileJson(profile);
  j["cell_share"] = {{"cell_us", cell.clock()},
                     {"moving_us", profile.total.moving},
                     {"waiting_us", profile.total.waiting},
                     {"gripper_us", profile.total.gripper},
                     {"ended_us", endedFor(cell, p)}};
  return j;
}

}  // namespace rs::cli
