#include "launch/cell_controllers.h"

#include <fmt/format.h>

#include <filesystem>

#include "base/text.h"
#include "launch/robot_choice.h"
#include "runtime/rhino/controller_session.h"

namespace rs::launch {

namespace {

// One LABEL=PATH of `option` (--device, --log-serial) checked against the
// cell: the program's index, or nullopt with the mistake in `diags`.
std::optional<std::size_t> programNamed(const std::string& option, const std::string& arg,
                                        const CellPrograms& programs, std::string& path,
                                        std::vector<diag::Diagnostic>& diags) {
  const workcell::Workcell& cell = *programs.cell;
  const auto refuse = [&](std::string message, std::string hint) {
    diags.push_back({option, {}, diag::Severity::Error, std::move(message), "cell-device", std::move(hint)});
    return std::nullopt;
  };
  const std::string labels = fmt::format("the cell's robots are {}", robotLabelsOf(cell));
  if (!isProgramAssignment(arg) || arg.back() == '=')
    return refuse(fmt::format("'{}' names no robot: a cell of several robots takes {} LABEL={}", base::safeText(arg),
                              option, option == "--device" ? "DEVICE" : "FILE"),
                  labels);
  const std::string label = arg.substr(0, arg.find('='));
  path = arg.substr(label.size() + 1);
  if (cell.robotLabeled(label) == workcell::kNoIndex)
    return refuse(fmt::format("workcell {} has no robot labelled `{}`", base::safeText(cell.name),
                              base::safeText(label)),
                  labels);
  for (std::size_t p = 0; p < programs.labels.size(); ++p)
    if (programs.labels[p] == label) return p;
  return refuse(fmt::format("robot {} runs no program: it stands still, with nothing to send its controller",
                            base::safeText(label)),
                fmt::format("give it a program with {}=FILE, or a PROGRAM in the cell", base::safeText(label)));
}

// The same device under two names (a link, a relative path) is one device.
std::string samePathKey(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

}  // namespace

std::optional<std::vector<SerialRequest>> cellDevices(const SerialRequest& request, const CellPrograms& programs,
                                                      std::vector<diag::Diagnostic>& diags) {
  std::vector<SerialRequest> out(programs.labels.size());
  const std::size_t before = diags.size();
  const rhino::Dialect dialect = request.dialect == "mark4" ? rhino::Dialect::Mark4 : rhino::Dialect::Mark3;
  std::vector<std::string> keys(out.size());  // per program: its device, as samePathKey has it
  for (const std::string& arg : request.devices) {
    std::string path;
    const std::optional<std::size_t> p = programNamed("--device", arg, programs, path, diags);
    if (!p) continue;
    const std::string& label = programs.labels[*p];
    if (!out[*p].device.empty()) {
      diags.push_back({"--device", {}, diag::Severity::Error,
                       fmt::format("robot {} is given two devices ({} and {})", base::safeText(label),
                                   base::safeText(out[*p].device), base::safeText(path)),
                       "cell-device", "one controller a robot: give each robot's label once"});
      continue;
    }
    const std::string key = samePathKey(path);
    bool shared = false;
    for (std::size_t q = 0; q < out.size(); ++q)
      if (keys[q] == key) {
        diags.push_back({"--device", {}, diag::Severity::Error,
                         fmt::format("robots {} and {} are given the same device {}", base::safeText(programs.labels[q]),
                                     base::safeText(label), base::safeText(path)),
                         "cell-device", "each robot drives its own controller, on its own serial line"});
        shared = true;
      }
    if (shared) continue;
    const std::vector<vm::MotorSpec>& motors = programs.programs[*p].image->motors;
    if (std::string e = rhino::unsupportedMotor(dialect, motors); !e.empty()) {
      diags.push_back({"--device", {}, diag::Severity::Error,
                       fmt::format("robot {} ({}) cannot run on a Rhino controller: {}", base::safeText(label),
                                   base::safeText(programs.programs[*p].image->robotName), e),
                       "cell-device", "only a robot whose motors are a Rhino controller's (A..H) takes --device"});
      continue;
    }
    out[*p] = request;
    out[*p].device = path;
    out[*p].logFile.clear();
    out[*p].devices.clear();
    out[*p].logFiles.clear();
    keys[*p] = key;
  }
  for (const std::string& arg : request.logFiles) {
    std::string path;
    const std::optional<std::size_t> p = programNamed("--log-serial", arg, programs, path, diags);
    if (!p) continue;
    if (out[*p].device.empty()) {
      diags.push_back({"--log-serial", {}, diag::Severity::Error,
                       fmt::format("robot {} has no --device: there is no serial line to log",
                                   base::safeText(programs.labels[*p])),
                       "cell-device", fmt::format("give it one with --device {}=DEVICE", base::safeText(programs.labels[*p]))});
      continue;
    }
    out[*p].logFile = path;
  }
  if (diags.size() != before) return std::nullopt;
  return out;
}

std::optional<std::vector<std::unique_ptr<rhino::RhinoMachine>>> openCellControllers(
    const std::vector<SerialRequest>& requests, const CellPrograms& programs, vm::Micros maxTime,
    std::vector<diag::Diagnostic>& diags) {
  std::vector<std::unique_ptr<rhino::RhinoMachine>> out(requests.size());
  for (std::size_t p = 0; p < requests.size(); ++p) {
    if (!requests[p].active()) continue;
    out[p] = openRhino(requests[p], programs.programs[p].image->motors, maxTime, diags);
    if (!out[p]) return std::nullopt;
  }
  return out;
}

}  // namespace rs::launch
