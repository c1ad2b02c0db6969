// A pendant (tools/teach/pendant.h) on the library's gantry cell over a program
// written to a fresh folder: the fixture the pendant's tests and the
// terminal pendant's share. The cell's numbers, worked out by hand, are in
// tests/teach/test_pendant.cpp.
#pragma once

#include <catch2/catch.hpp>

#include <memory>
#include <optional>
#include <string>

#include "../render/render_test_util.h"
#include "base/file_io.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/pendant.h"

namespace rs::testing {

struct GantryPendant {
  /// `program` written to `name` in the folder, then opened on the cell.
  GantryPendant(const std::string& name, const std::string& program)
      : path(dir.write(name, program)),
        cell(std::make_shared<const workcell::Workcell>(rendertest::cell("gantry-cell"))) {
    diag::Result<teach::ProgramFile> file = teach::ProgramFile::load(path);
    INFO((file ? std::string() : file.failure().message));
    REQUIRE(file);
    pendant = std::make_unique<teach::Pendant>(cell, launch::cellTarget(*cell).motors, std::move(*file));
  }

  /// The program file as it is on disk now.
  std::string text() const { return *base::readFile(path, 1 << 20).bytes; }

  TempDir dir;
  std::string path;
  std::shared_ptr<const workcell::Workcell> cell;
  std::unique_ptr<teach::Pendant> pendant;
};

}  // namespace rs::testing
