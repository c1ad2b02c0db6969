// The cell's devices against a stimuli file (issue 35, `--only cell`): an
// hour of simulated production of adept_hour.rsp on adept-cell, its belts,
// feeder, beam and sink acting on the cell's clock; paired in one run with
// the same program on the same cell without its devices, its input played
// by a stimuli file made from the device run's input changes, so the robot
// makes the same moves at the same times. Target: the devices cost at most
// 2x the CPU time of the stimuli run.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/seconds.h"
#include "bench/adept_hour.h"
#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/run/run.h"

namespace rs::bench {
namespace {

using json = nlohmann::json;

std::unique_ptr<runtime::Run> cellRun(const std::shared_ptr<const vm::Image>& image,
                                      const std::shared_ptr<const workcell::Workcell>& cell, stimuli::Stimuli stimuli,
                                      bool log, runtime::CollisionMode collisions = runtime::CollisionMode::Error) {
  runtime::RunSpec spec;
  spec.collisions = collisions;
  spec.image = image;
  spec.cell = cell;
  spec.stimuli = std::move(stimuli);
  spec.log = log;
  spec.limits.maxTime = vm::Micros{1} << 50;
  return std::make_unique<runtime::Run>(std::move(spec));
}

// "at 12.231187 input 1 on": every input change the run logged, in order.
std::string stimuliOf(const runtime::RunLog& log) {
  std::string text = "; the input changes of the device run (bench/cell_bench.cpp)\n";
  for (const runtime::InputRecord& change : log.inputChanges)
    text += fmt::format("at {} input {} {}\n", base::formatSecondsExactly(change.at), change.cause.input,
                        change.cause.on ? "on" : "off");
  return text;
}

}  // namespace

json benchCell(const Options& options) {
  const int blocks = sized(options, 600, 10);
  fmt::print("\n[cell] The cell's devices against a stimuli file: adept_hour.rsp on adept-cell, {} blocks\n", blocks);
  compiler::Library library(compiler::librarySearchPath({}));
  const std::optional<workcell::Workcell> found = library.workcell("adept-cell");
  if (!found) throw std::runtime_error("the library has no adept-cell workcell");
  const auto withDevices = std::make_shared<const workcell::Workcell>(*found);
  workcell::Workcell bare = *found;
  bare.devices = {};
  bare.fedParts.clear();
  const auto withoutDevices = std::make_shared<const workcell::Workcell>(std::move(bare));
  const diag::SourceFile source("adept_hour.rsp", adeptHourProgram(blocks));
  const auto image = std::make_shared<const vm::Image>(compileOrThrow(source, launch::cellTarget(*withDevices)));

  // Once, logged and untimed: the input changes the devices make.
  auto logged = cellRun(image, withDevices, {}, true);
  const vm::RunOutcome first = logged->runToEnd();
  if (!first.ok()) throw std::runtime_error("the device run failed: " + first.message);
  const vm::Micros simulated = logged->rig().clock();
  const std::uint64_t steps = first.steps;
  const std::size_t changes = logged->log()->inputChanges.size();
  const std::string stimuliText = stimuliOf(*logged->log());
  const std::string stimuliPath = writeInput(options, "adept_hour.stim", stimuliText);
  // Read back as `--stimuli FILE` reads it.
  launch::RunRequest request;
  request.stimuliFile = stimuliPath;
  stimuli::Stimuli played;
  std::vector<diag::Diagnostic> problems;
  if (!launch::loadStimuli(request, played, problems))
    throw std::runtime_error("the generated stimuli do not read: " +
                             (problems.empty() ? std::string("?") : problems.front().message));
  logged.reset();

  const auto timed = [&](const std::shared_ptr<const workcell::Workcell>& cell, const stimuli::Stimuli& played,
                         const char* what, runtime::CollisionMode collisions) {
    return [&, cell, what, collisions]() {
      auto run = cellRun(image, cell, played, false, collisions);
      const Stopwatch clock;
      const vm::RunOutcome outcome = run->runToEnd();
      const Sample sample = clock.stop();
      // The same moves at the same times, or the pair measures nothing.
      if (!outcome.ok() || outcome.steps != steps || run->rig().clock() != simulated)
        throw std::runtime_error(fmt::format("the {} run is not the device run: {} steps to {} s ({})", what,
                                             outcome.steps, base::formatSeconds(run->rig().clock()), outcome.message));
      return sample;
    };
  };
  const stimuli::Stimuli none;
  using runtime::CollisionMode;
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: with the devices, with the stimuli ({} input changes); "
                       "collisions on (the default), then off",
                       options.reps, changes));
  const std::vector<Samples> s = interleave({timed(withDevices, none, "device", CollisionMode::Error),
                                             timed(withoutDevices, played, "stimuli", CollisionMode::Error),
                                             timed(withDevices, none, "device", CollisionMode::Off),
                                             timed(withoutDevices, played, "stimuli", CollisionMode::Off)},
                                            options.reps);
  const double seconds = static_cast<double>(simulated) / 1e6;
  row("with the devices", s[0], fmt::format("{} steps, {} s simulated", steps, base::formatSeconds(simulated)));
  row("with a stimuli file", s[1], fmt::format("{} input changes", changes));
  row("with the devices, collisions off", s[2]);
  row("with a stimuli file, collisions off", s[3]);
  const double ratio = s[0].cpuBest() / s[1].cpuBest();
  const double ratioOff = s[2].cpuBest() / s[3].cpuBest();
  const double perCpu = seconds / s[0].cpuBest();
  fmt::print("  ratio devices / stimuli (CPU) {}\n", verdict(ratio, 2));
  fmt::print("  collisions off: ratio devices / stimuli (CPU) {}\n", verdict(ratioOff, 2));
  fmt::print("  simulated seconds per CPU second: {:.0f} with the devices, {:.0f} with the stimuli; collisions off {:.0f} "
             "and {:.0f}\n",
             perCpu, seconds / s[1].cpuBest(), seconds / s[2].cpuBest(), seconds / s[3].cpuBest());
  return {{"blocks", blocks},
          {"steps", steps},
          {"simulated_s", seconds},
          {"input_changes", changes},
          {"devices", toJson(s[0])},
          {"stimuli", toJson(s[1])},
          {"devices_collisions_off", toJson(s[2])},
          {"stimuli_collisions_off", toJson(s[3])},
          {"cpu_ratio", ratio},
          {"cpu_ratio_collisions_off", ratioOff},
          {"simulated_s_per_cpu_s", perCpu},
          {"simulated_s_per_cpu_s_collisions_off", seconds / s[2].cpuBest()}};
}

}  // namespace rs::bench
