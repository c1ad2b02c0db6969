// collision_bench's sweep and runs parts (bench/collision_main.cpp).
#include "bench/collision_runs.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "bench/collision_programs.h"
#include "bench/timing.h"
#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "runtime/run/run.h"

namespace rs::bench {

namespace {

workcell::Workcell libraryCell(const std::string& name) {
  compiler::Library library(compiler::librarySearchPath({}));
  std::optional<workcell::Workcell> cell = library.workcell(name);
  if (!cell) throw std::runtime_error("the library has no workcell " + name);
  return *cell;
}

std::shared_ptr<const vm::Image> compileFor(const std::string& name, const std::string& text, const workcell::Workcell& cell) {
  const diag::SourceFile source(name, text);
  compiler::CompileResult compiled = compiler::compile(source, launch::cellTarget(cell));
  if (!compiled.image) {
    std::string why = compiled.diagnostics.empty() ? "" : ": " + compiled.diagnostics.front().message;
    throw std::runtime_error(name + " did not compile" + why);
  }
  return std::make_shared<const vm::Image>(*compiled.image);
}

// One run to the end; its CPU time, and what the run and its watch say.
struct Timed {
  Sample sample;
  double simulated = 0;  // seconds
  std::uint64_t steps = 0, moves = 0, remembered = 0, checks = 0;
};

Timed timedRun(const runtime::RunSpec& base, runtime::CollisionMode mode) {
  runtime::RunSpec spec = base;
  spec.collisions = mode;
  runtime::Run run(std::move(spec));
  const Stopwatch clock;
  const vm::RunOutcome outcome = run.runToEnd();
  Timed t;
  t.sample = clock.stop();
  if (!outcome.ok()) throw std::runtime_error("a benchmark run stopped: " + outcome.message);
  t.simulated = static_cast<double>(run.rig().clock()) / 1e6;
  t.steps = run.interpreter().steps();
  if (const runtime::CollisionWatch* w = run.rig().collisionWatch())
    t.moves = w->moves(), t.remembered = w->remembered(), t.checks = w->checks();
  return t;
}

// A SCARA program that sweeps its arm over the whole range, up and down,
// with the gripper opening and closing: every move checked.
constexpr const char* kWholeRange =
    "        SET N 0\n"
    "loop:   MOVETO 1000 -550 0 0 0\n"
    "        MOVETO -1000 550 0 700 120\n"
    "        MOVETO 0 0 0 -700 0\n"
    "        ADD N 1\n"
    "        JMPVAR N < {} loop\n"
    "        END\n";

}  // namespace

void benchSweep(const CollisionBenchOptions& options) {
  const long passes = options.smoke ? 2 : 50;
  const workcell::Workcell cell = libraryCell("scara-pick");
  runtime::RunSpec spec;
  spec.cell = std::make_shared<const workcell::Workcell>(cell);
  spec.image = compileFor("sweep.rsp", fmt::format(kWholeRange, passes), cell);
  double off = 1e300, on = 1e300;
  Timed checked;
  for (int r = 0; r < options.reps; ++r) {
    off = std::min(off, timedRun(spec, runtime::CollisionMode::Off).sample.cpu);
    checked = timedRun(spec, runtime::CollisionMode::Error);
    on = std::min(on, checked.sample.cpu);
  }
  // The sweep alone: the same moves, each swept with nothing remembered.
  double fresh = 1e300;
  std::uint64_t freshChecks = 0;
  for (int r = 0; r < options.reps; ++r) {
    runtime::SimMachine machine(spec.image->motors, {});
    runtime::World world(cell);
    runtime::CollisionWatch watch(cell);
    const std::vector<std::vector<std::int32_t>> targets{{1000, -550, 0, 0, 0}, {-1000, 550, 0, 700, 120}, {0, 0, 0, -700, 0}};
    const Stopwatch clock;
    for (long pass = 0; pass < passes; ++pass)
      for (const auto& target : targets) {
        const std::vector<std::int32_t> before(machine.positions().begin(), machine.positions().end());
        const vm::Micros start = machine.now();
        if (!machine.moveTo(target)) throw std::runtime_error("a move of the sweep benchmark failed");
        watch.forget();
        if (watch.sweep(machine, world, before, machine.positions(), start, machine.now()))
          throw std::runtime_error("the sweep benchmark's moves collide");
        world.moved(before, machine.positions(), start, machine.now());
      }
    fresh = std::min(fresh, clock.stop().cpu);
    freshChecks = watch.checks();
  }
  const double moves = static_cast<double>(passes * 3);
  fmt::print("swept check, rhino-scara on scara-pick, {} moves over the whole range ({:.1f} s simulated), CPU best of {}\n",
             passes * 3, checked.simulated, options.reps);
  fmt::print("  --collisions=off    {:8.2f} ms\n", off * 1e3);
  fmt::print("  --collisions=error  {:8.2f} ms: {} moves, {} answered from memory, {} poses checked\n", on * 1e3,
             checked.moves, checked.remembered, checked.checks);
  fmt::print("  every move swept afresh {:8.2f} ms: {} poses checked ({:.1f} a move), {:.1f} us a move\n", fresh * 1e3,
             freshChecks, static_cast<double>(freshChecks) / moves, fresh * 1e6 / moves);
}

void benchWorkcellRuns(const CollisionBenchOptions& options) {
  fmt::print("\nruns on workcells, --collisions=error against off: CPU time, best of {} (interleaved)\n", options.reps);
  fmt::print("  {:<11} {:<15} {:>10} {:>11} {:>10} {:>10} {:>7} {:>13} {:>9} {:>8}\n", "cell", "program", "steps",
             "simulated", "off ms", "error ms", "ratio", "sim s/CPU s", "moves", "swept");
  for (const CollisionProgram& program : collisionPrograms()) {
    const workcell::Workcell cell = libraryCell(program.cell);
    runtime::RunSpec spec;
    spec.cell = std::make_shared<const workcell::Workcell>(cell);
    spec.image = compileFor(program.cell + ".rsp", fmt::format(fmt::runtime(program.text), options.smoke ? 50 : program.loops), cell);
    spec.limits.maxSteps = UINT64_MAX;
    spec.limits.maxTime = INT64_MAX / 2;
    double off = 1e300, on = 1e300;
    Timed checked;
    try {
      for (int r = 0; r < options.reps; ++r) {
        off = std::min(off, timedRun(spec, runtime::CollisionMode::Off).sample.cpu);
        checked = timedRun(spec, runtime::CollisionMode::Error);
        on = std::min(on, checked.sample.cpu);
      }
    } catch (const std::runtime_error& e) {  // a program that collides: said, and the others still measured
      fmt::print("  {:<11} {:<15} {}\n", program.cell, program.kind, e.what());
      continue;
    }
    fmt::print("  {:<11} {:<15} {:>10} {:>9.0f} s {:>10.2f} {:>10.2f} {:>7.2f} {:>13.0f} {:>9} {:>8}\n", program.cell,
               program.kind, checked.steps, checked.simulated, off * 1e3, on * 1e3, on / off, checked.simulated / on,
               checked.moves, checked.moves - checked.remembered);
  }
  fmt::print("  targets: ratio <= 2 for every program; >= 100,000 simulated s per CPU s for scara-pick's pick and place\n");
}

}  // namespace rs::bench
