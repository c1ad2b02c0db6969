// What the image tests share (tests/vm/test_image_file.cpp,
// test_verifier.cpp): images compiled for the library's SCARA, a sample
// with every operand format, the smallest sound image, and the loader's
// error for an image or its bytes.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/program/compiler.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace rs::testing {

using Image = vm::Image;
using Bytes = std::vector<std::uint8_t>;

inline rs::compiler::Target rhino() { return {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth}; }

// An image's label names and line table are packed (vm/image.h): these
// change one entry as a forger would, rebuilding the rest as it was.
inline void setLabelName(Image& im, std::size_t i, std::string_view name) {
  Image was = im;
  im.labels.clear();
  im.labelNames.clear();
  for (std::size_t k = 0; k < was.labels.size(); ++k) im.addLabel(was.labels[k].index, k == i ? name : was.labelName(k));
}
inline void setLine(Image& im, std::size_t i, std::uint32_t line) {
  std::vector<std::uint32_t> lines = im.lines.toVector();
  lines[i] = line;
  im.lines.clear();
  for (std::uint32_t l : lines) im.lines.push_back(l);
}

inline Image compileOk(const std::string& text, const std::string& name = "v.rsp") {
  const rs::diag::SourceFile source(name, text);
  rs::compiler::CompileResult r = rs::compiler::compile(source, rhino());
  INFO(text);
  REQUIRE(r.ok());
  return std::move(*r.image);
}

// Ten instructions with every operand format the checks below poke at:
//   1 MOVETO (constants 0..4)  2 MOVEP P1  3 SET N  4 JMPVAR -> 6
//   5 OUTSIG  6 JMPIN -> 8  7 WINDOW (constants 5..7)  8 DELAY
//   9 GOTO -> 10  10 END
inline const std::string kSample =
    "MOVETO 1 2 3 4 5\n"
    "MOVEP P1\n"
    "SET N 1\n"
    "JMPVAR N < 3 6\n"
    "OUTSIG 1 ON\n"
    "JMPIN 2 ON 8\n"
    "WINDOW 1 2 3\n"
    "DELAY 0.5\n"
    "GOTO done\n"
    "done: END\n"
    "POINTS\n"
    "P1 1 2 3 4 5\n";

inline Image sample() { return compileOk(kSample); }

// The smallest sound image: one END on the default motors.
inline Image tiny() {
  Image im;
  im.sourceName = "tiny.rsp";
  im.robotName = "rhino-scara";
  im.motors = rs::stdlib::rhinoScaraMotors();
  im.code = {vm::Instr{vm::Op::End, 0, 0, 0, 0}};
  im.lines = {1};
  im.columns = {1};
  return im;
}

inline std::string_view view(const Bytes& b) { return {reinterpret_cast<const char*>(b.data()), b.size()}; }

/// The loader's message, "" when the image loaded.
inline std::string loadError(const rs::diag::Result<rs::vm::Image>& r) { return r.ok() ? std::string() : r.failure().message; }
inline std::string loadError(const Bytes& b) { return loadError(rs::vm::loadImage(view(b))); }
inline std::string loadError(const Image& im) { return loadError(rs::vm::writeImage(im)); }

}  // namespace rs::testing
