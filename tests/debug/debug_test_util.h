// Shared by the debugger's tests: programs compiled from text or from the
// examples, on the default robot or a library cell, as a RunSpec.
#pragma once

#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "../render/render_test_util.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "runtime/run/run.h"

namespace debugtest {

inline const std::string kExamples = rendertest::kSourceDir + "/examples/";

/// `text` compiled for the default robot (no workcell).
inline rs::runtime::RunSpec specOf(const std::string& text, rs::stimuli::Stimuli stimuli = {}) {
  const rs::diag::SourceFile source("program.rsp", text);
  rs::compiler::CompileResult p = rs::compiler::compile(source, rs::launch::defaultTarget());
  for (const auto& d : p.diagnostics) INFO(d.message);
  REQUIRE(p.image);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(*p.image);
  spec.stimuli = std::move(stimuli);
  return spec;
}

/// An example program on a library cell.
inline rs::runtime::RunSpec specOnCell(const std::string& example, const std::string& cellName) {
  const rs::workcell::Workcell cell = rendertest::cell(cellName);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(rendertest::compile(kExamples + example, cell));
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  return spec;
}

}  // namespace debugtest
