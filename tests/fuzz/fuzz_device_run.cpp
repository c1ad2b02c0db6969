// libFuzzer target: a long random run of a device cell (issue 35). The
// input is a WORKCELL's device lines (CONVEYOR, FEEDER, SENSOR, SINK,
// WIRE, and anything else a WORKCELL may say), then a line `---`, then a
// robot program. The lines go into a fixed cell (the library's gantry over
// a belt with a part on it); when the cell builds, the program is compiled
// for its gantry and, when it compiles, run for up to an hour of simulated
// time on that cell: belts, sensors that see the carried part and the
// robot, feeders, sinks and wires all act. Nothing may crash, hang or go
// superlinear, and the cell must survive the image's cell section
// (encode, decode, encode: the same bytes).
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "compiler/description/library.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "model/workcell/cell_file.h"
#include "runtime/run/run.h"
#include "tests/runtime/belt_and_part.h"

namespace {

// The gantry's description, read once from the library beside the fuzzer:
// the cell names it by its own text, so no input makes the library search.
std::string gantryText() {
  for (const std::filesystem::path& dir : rs::compiler::librarySearchPath({})) {
    std::ifstream in(dir / "robots" / "gantry.rsd", std::ios::binary);
    if (!in) continue;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::abort();  // the library was not found: the target would test nothing
}

const std::string& prelude() {
  static const std::string text = gantryText() + "\n" + celltest::kBeltAndPart +
                                  "WORKCELL fz\n"
                                  "  ROBOT gantry AT 0 1000 0\n"
                                  "  OBJECT belt AT 0 0 650 AS line\n"
                                  "  OBJECT blk AT 17 10 630\n";
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = [] {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("robotsim-fuzz-devices-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / "cell.rsd";
  }();
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find("\n---\n");
  const std::string devices = input.substr(0, split);
  const std::string program = split == std::string::npos ? std::string("        DELAY 60\n        END\n")
                                                         : input.substr(split + 5);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << prelude() << devices << "\nEND\n";
  }
  rs::compiler::Library library({});
  const std::optional<rs::workcell::Workcell> built = library.workcell(file.string());
  if (!built || !built->drivenRobot()) return 0;
  const auto cell = std::make_shared<const rs::workcell::Workcell>(*built);
  // The image's cell section holds every fact of the cell.
  const std::vector<std::uint8_t> bytes = rs::workcell::encodeCell(*cell);
  const rs::diag::Result<rs::workcell::Workcell> decoded = rs::workcell::decodeCell(bytes);
  if (!decoded || rs::workcell::encodeCell(*decoded) != bytes) std::abort();

  const rs::diag::SourceFile source("fuzz.rsp", program);
  const rs::compiler::CompileResult compiled = rs::compiler::compile(source, rs::launch::cellTarget(*cell), 20);
  if (!compiled.image) return 0;
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(*compiled.image);
  spec.cell = cell;
  spec.limits.maxSteps = 20'000;
  spec.limits.maxStepsPerInstant = 20'000;
  spec.limits.maxKnots = 20'000;
  spec.limits.maxTime = rs::vm::Micros{3600} * 1'000'000;
  rs::runtime::Run run(std::move(spec));
  (void)run.runToEnd();
  return 0;
}
