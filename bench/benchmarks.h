// The benchmarks of `make bench`. Each prints readable lines to stdout
// (a progress line before every long measurement) and fills its part of the
// machine-readable summary. None of them is a test: a missed target is
// reported, not failed; a measurement that cannot be trusted (a program
// that did not compile, a loop that did not count) throws.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rs::bench {

struct Options {
  int reps = 5;
  /// The smallest sizes: every benchmark runs through and prints its
  /// figures, which then measure nothing (the test suite's bench-smoke
  /// tests run each mode so, to see that none has rotted).
  bool smoke = false;
  std::string robotsim = "robotsim";  // the CLI binary
  std::string lua = "lua5.4";
  std::string luajit = "luajit";      // run with -joff: its interpreter, not its JIT compiler
  std::string luac = "luac5.4";
  std::string workDir = "bench-work";  // generated inputs go here
  std::string jsonPath;                // empty: no summary file
};

/// `full`, or `smoke` with --smoke.
template <typename T>
T sized(const Options& options, T full, T smoke) {
  return options.smoke ? smoke : full;
}

/// VM dispatch: a 10,000,000-iteration SET/ADD/JMPVAR loop run in-process,
/// against the same loop in a `lua5.4` process and in a `luajit -joff`
/// process (each with its start-up subtracted). Target: no slower than
/// LuaJIT's interpreter.
nlohmann::json benchDispatch(const Options& options);

/// Compile throughput at 10k, 100k and 1M instructions, in-process and as a
/// `robotsim compile` process, and `luac5.4 -p` on a Lua file of the same
/// line count as the 100k program (target: 1.3 times luac's CPU time).
/// Also image bytes per instruction and the peak RSS of compiling 1M
/// instructions.
nlohmann::json benchCompile(const Options& options);

/// Compile memory: the peak RSS of `robotsim compile` on programs of 1M
/// and 2M lines of one short kind (END, MOVE, labels, jumps, unknown
/// words), the growth between them per source byte (target: 5) and the
/// whole peak over the source. Runs first: the driver must stay smaller
/// than what it measures.
nlohmann::json benchMemory(const Options& options);

/// `robotsim test` hardened: the peak RSS of a test whose run is 1e8
/// instructions (target: 100 MB) beside the same loop logged; one
/// `; expect: motors` line of 10k, 100k and 1M terms (target: 1 s at 1M);
/// the CPU time of a submission that never ends under `--spec` (target:
/// 1 s) beside the limits grading had before. Runs second, while the
/// driver is small.
nlohmann::json benchTestRun(const Options& options);

/// Startup: `robotsim check` on a 1,000-line program, whole process.
nlohmann::json benchStartup(const Options& options);

/// Issue 25's start-up targets, paired in one run: `robotsim check` on a
/// 3-line program and `robotsim help` against `luac5.4 -v` (target: 2 times
/// its time), and the peak RSS of a one-line `robotsim compile` read by GNU
/// time (target: half of the 13 MiB before). Part of `--only startup`.
nlohmann::json benchStartupPeers(const Options& options);

/// Run snapshots: a run on the library's scara-pick cell (moves, a
/// subroutine, outputs, a log), to the end without snapshots and with one
/// every 300 instructions; the cost of one snapshot and one restore.
nlohmann::json benchSnapshot(const Options& options);

/// `robotsim test -j 2` on 1,000 generated programs with 3 expectations
/// each, whole process. Target: 2 s.
nlohmann::json benchTestSuite(const Options& options);

/// Programs full of errors: 10k, 100k and 1M lines, every line with one or
/// two errors, and one 10 MB line (100,000 stray characters; 5M words):
/// compile() and rendering the diagnostics in-process as `robotsim check`
/// does (the first 50 kept, the rest counted), and `robotsim check` as a
/// process; growth ratios (linear = 10), peak RSS, bytes printed.
nlohmann::json benchErrors(const Options& options);

/// The language server on a 10,000-line program: diagnostics published
/// after a one-character change (target 30 ms), hover and completion
/// (5 ms), in-process; peak RSS of a `robotsim lsp` process with the file
/// open (50 MiB).
nlohmann::json benchLsp(const Options& options);

/// The language server's run-time diagnostics (issue 23): a 10,000-line
/// program on scara-pick changed by one character; the time to its compile
/// diagnostics and to its run's (target 200 ms), collisions on and off.
nlohmann::json benchLspRuns(const Options& options);

/// The language server formatting a 50 MB document (issue 26): peak RSS
/// and time of a `robotsim lsp` process that opens it and formats it,
/// against one that only opens it.
nlohmann::json benchLspFormat(const Options& options);

/// The debugger's reverse steps on a run of about 1,000,000 instructions,
/// for several snapshot intervals: time forwards with snapshots, their
/// memory, one reverse step (median, worst). Targets: 10 ms, 64 MiB.
nlohmann::json benchDebug(const Options& options);

/// Straight lines (issue 32): `robotsim compile` on 1,000 and 4,000 MOVES
/// lines of the IRB 120 (target: 0.5 s of CPU at 1,000) and on 1,000 lines
/// all different; the language server's hover right after an edit on 4,000
/// of them (30 ms); a reverse step on a MOVES loop; `pause` and
/// `disconnect` answered by `robotsim dap` on a MOVES loop and on a gantry
/// of 65,536-knot lines; grading a MOVES submission that never ends on the
/// IRB 120's cell and on a cell of the student's (1 s).
nlohmann::json benchMoves(const Options& options);

/// The cell's devices (issue 35): an hour of simulated production of
/// adept_hour.rsp on adept-cell, paired with the same program on the cell
/// without its devices, its input played by a stimuli file of the device
/// run's input changes (the same moves at the same times). Target: at most
/// 2 times the stimuli run's CPU time; simulated seconds per CPU second.
nlohmann::json benchCell(const Options& options);
/// The description reader on 100,000 device and wire lines (issue 35):
/// a valid cell and one with 49,992 errors, in-process and through
/// `robotsim describe`. Target: under 1 s of CPU each.
nlohmann::json benchDevices(const Options& options);
/// Two robots on one clock that never interact against each alone (issue 36).
nlohmann::json benchRobots(const Options& options);
/// Reverse step in the two-robot example (tools/debug/cell_session.h): median and worst.
nlohmann::json benchCellDebug(const Options& options);

}  // namespace rs::bench
