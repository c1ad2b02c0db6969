// Helpers shared by the renderer tests: library workcells, programs
// compiled for them, and the stdlib robots by name.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <memory>

#include "base/file_io.h"
#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "model/workcell/model.h"
#include "runtime/run/run.h"
#include "tests/cli/cli_support.h"

namespace rendertest {

inline const std::string kSourceDir = ROBOTSIM_SOURCE_DIR;

/// A workcell (or a robot standing where it was drawn) from the library.
inline rs::workcell::Workcell cell(const std::string& name) {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> c = library.workcell(name);
  for (const auto& d : library.diagnostics()) INFO(d.message);
  REQUIRE(c);
  return *c;
}

/// The names of stdlib/robots/*.rsd, sorted.
inline std::vector<std::string> libraryRobots() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kSourceDir + "/stdlib/robots"))
    if (entry.path().extension() == ".rsd") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// A program source compiled for the first robot of `c`.
inline rs::vm::Image compile(const std::string& path, const rs::workcell::Workcell& c) {
  const rs::base::FileRead text = rs::base::readFile(path, rs::launch::kMaxInputBytes);
  INFO(text.error);
  REQUIRE(text.bytes);
  const rs::diag::SourceFile source(path, *text.bytes);
  rs::compiler::CompileResult p = rs::compiler::compile(source, rs::launch::cellTarget(c));
  for (const auto& d : p.diagnostics) INFO(d.message);
  REQUIRE(p.image);
  return *p.image;
}

/// A run of `image` on the simulated machine, on `c` (a copy; may be null).
/// Tests of grasping and drawing that hold a gripper at a block's middle
/// (its fingers graze the pallet: docs/models.md, "Collisions") pass
/// CollisionMode::Off.
inline std::unique_ptr<rs::runtime::Run> runOf(const rs::vm::Image& image, const rs::workcell::Workcell* c,
                                               rs::stimuli::Stimuli stimuli = {}, bool log = false,
                                               rs::runtime::CollisionMode collisions = rs::runtime::CollisionMode::Error) {
  rs::runtime::RunSpec spec;
  spec.collisions = collisions;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  if (c) spec.cell = std::make_shared<const rs::workcell::Workcell>(*c);
  spec.stimuli = std::move(stimuli);
  spec.log = log;
  return std::make_unique<rs::runtime::Run>(std::move(spec));
}

/// A program given as text, written to a scratch file and compiled.
inline rs::vm::Image compileText(const std::string& text, const rs::workcell::Workcell& c) {
  const rs::testing::TempDir dir;
  return compile(dir.write("program.rsp", text), c);
}

}  // namespace rendertest
