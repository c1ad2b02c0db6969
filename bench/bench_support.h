// What the benchmarks of benchmarks.h share: the lines they print (a
// progress line, a row of timings, a verdict against a target), their
// samples as JSON, and the inputs they write and compile.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "compiler/program/compiler.h"
#include "diag/source_file.h"
#include "vm/image.h"

namespace rs::bench {

/// "  ... what", flushed: said before every long measurement.
void progress(std::string_view what);
/// "  123.45 ms" for a time in seconds.
std::string millis(double seconds);
/// Wall best and median, then CPU best (user + system) in brackets.
void row(std::string_view what, const Samples& s, std::string_view extra = {});
/// "0.85 (target <= 1: met)" or "4.20 (target <= 3: missed by 40%)".
std::string verdict(double ratio, double target);
nlohmann::json toJson(const Samples& s);

/// Writes `text` to NAME in the work folder; returns its path (throws when
/// it cannot be written).
std::string writeInput(const Options& options, const std::string& name, const std::string& text);
/// The image of `source`; throws with the first diagnostic when it does
/// not compile.
vm::Image compileOrThrow(const diag::SourceFile& source, const compiler::Target& target);
/// The slot of variable `name` in the image; throws when it has none.
std::size_t slotOf(const vm::Image& image, std::string_view name);
/// True when `argv` runs and exits 0 (a tool that is installed).
bool canRun(const std::vector<std::string>& argv);

/// `robotsim lsp` given a whole session on its stdin, its answers to
/// `replyPath`: wall and CPU time, and the peak RSS by GNU time, whose own
/// wait4 sees the server alone (a spawned child's rusage reports this
/// driver's peak when the server's is smaller). Throws unless it exits 0.
ProcessRun runLspSession(const Options& options, const std::string& sessionPath, const std::string& replyPath);

}  // namespace rs::bench
