// libFuzzer target: any bytes as a robot program (.rsp). The compiler must
// answer with diagnostics or an image, never crash, hang or go superlinear;
// the diagnostics must render; an image it writes must load and verify again
// (the compiler never writes what the loader refuses).
//
// fuzz_program compiles for the default robot (the paper's Rhino SCARA),
// which has no kinematic model, so straight lines (MOVES, APPRO, DEPART)
// and points written as poses stop at their refusal. fuzz_program_arms
// (ROBOTSIM_FUZZ_ARMS) compiles against the library's arms, so that every
// input reaches the poses' inverse kinematics and the straight-line
// planner: the arm a `; cell:` line names (a library robot or cell, looked
// up by name only), else the one the first byte picks among the
// library's robots (issue 32).
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "compiler/description/library_listing.h"
#include "compiler/program/compiler.h"
#include "diag/diagnostic.h"
#include "launch/cell_directive.h"
#include "launch/program.h"
#include "vm/image_file.h"

namespace {

#ifdef ROBOTSIM_FUZZ_ARMS
// Every robot and cell of the library by name, each target built once
// (names not in the library are never looked up: a fuzzed name would
// otherwise reach any .rsd file through '..').
class Arms {
 public:
  Arms() {
    for (const rs::compiler::LibraryEntry& e : rs::compiler::listLibrary(rs::compiler::librarySearchPath({})).entries) {
      if (e.kind != "robot" && e.kind != "workcell") continue;
      rs::compiler::Library library(rs::compiler::librarySearchPath({}));
      const std::optional<rs::workcell::Workcell> cell = library.workcell(e.name);
      if (!cell || !cell->drivenRobot()) std::abort();  // a library entry that does not build
      targets_.emplace(e.name, rs::launch::cellTarget(*cell));
      order_.push_back(&targets_.at(e.name));
    }
    if (order_.empty()) std::abort();  // the library was not found: the target would test nothing new
  }
  const rs::compiler::Target* named(const std::string& name) const {
    const auto it = targets_.find(name);
    return it == targets_.end() ? nullptr : &it->second;
  }
  const rs::compiler::Target& pickedBy(std::uint8_t byte) const { return *order_[byte % order_.size()]; }

 private:
  std::map<std::string, rs::compiler::Target> targets_;
  std::vector<const rs::compiler::Target*> order_;  // robots first, then cells, as listed
};

const rs::compiler::Target& targetFor(std::string_view text) {
  static const Arms arms;
  if (const std::optional<rs::launch::CellDirective> d = rs::launch::findCellDirective(text))
    if (const rs::compiler::Target* t = arms.named(d->name)) return *t;
  return arms.pickedBy(text.empty() ? 0 : static_cast<std::uint8_t>(text[0]));
}
#else
const rs::compiler::Target& targetFor(std::string_view) {
  static const rs::compiler::Target target = rs::launch::defaultTarget();
  return target;
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const rs::compiler::Target& target = targetFor(text);
  const rs::diag::SourceFile source("fuzz.rsp", text);
  const rs::compiler::CompileResult result = rs::compiler::compile(source, target, 50);
  for (const rs::diag::Diagnostic& d : result.diagnostics) (void)rs::diag::render(d, &source);
  if (result.image) {
    const std::vector<std::uint8_t> bytes = rs::vm::writeImage(*result.image);
    const rs::diag::Result<rs::vm::Image> loaded =
        rs::vm::loadImage(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    if (!loaded.ok()) std::abort();  // the compiler wrote an image its own loader refuses
  }
  return 0;
}
