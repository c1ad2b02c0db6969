// Robots from URDF files (the Robot Description Format of ROS): a URDF arm
// read into the workcell model, so that it is used wherever a robot
// description is (docs/models.md, "URDF", "Reading URDF").
//
// The XML is parsed by Debian's urdfdom (urdf::parseURDF), the format's own
// reader, not by hand; tinyxml2 (which urdfdom reads with) gives the lines
// that urdfdom's messages lack. What robotsim adds: the chain from the root
// link to the tip (urdf_chain.h), its D-H frames (urdf_dh.h), the motors,
// the geometry (urdf_mesh.h), and positioned errors for bad input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "base/file_io.h"
#include "diag/diagnostic.h"
#include "model/workcell/model.h"

namespace rs::urdf {

/// The largest URDF file read, as for descriptions: a larger one (the
/// issue's "100 MB URDF") is refused by its size, before a byte of it is
/// read or parsed, so that it costs no time and no memory.
inline constexpr std::size_t kMaxUrdfBytes = std::size_t{64} << 20;

/// The one error for a URDF file (or an editor's text) of `bytes` bytes,
/// more than kMaxUrdfBytes: about the whole file (line 0), with a hint.
/// Inline: the helper's caller (urdf_read_remote.h) refuses an editor's
/// text so too, without linking the reader.
inline diag::Diagnostic urdfTooLarge(const std::string& file, std::uint64_t bytes) {
  return {file, {}, diag::Severity::Error,
          fmt::format("the URDF file is {} ({} bytes), more than the {} a URDF file may be: it is not read",
                      base::sizeText(bytes), bytes, base::sizeText(kMaxUrdfBytes)),
          "urdf-size",
          "a robot's URDF is text of kilobytes (its meshes are files of their own, named by <mesh filename>): "
          "check that this is the robot's URDF file, or run xacro on its source again"};
}
/// Degrees (revolute) or millimetres (prismatic) per encoder count, unless
/// --precision says otherwise.
inline constexpr double kDefaultPrecision = 0.01;
/// The range a continuous joint gets: one turn either way from home.
inline constexpr double kContinuousRangeDegrees = 360.0;
/// SPEED of a joint whose limit gives no velocity (or 0): degrees or
/// millimetres per second.
inline constexpr double kDefaultRevoluteSpeed = 90.0;
inline constexpr double kDefaultPrismaticSpeed = 250.0;

struct UrdfOptions {
  /// The link the chain ends at; empty: the one leaf of the tree.
  std::string tip;
  /// kDefaultPrecision unless given (--precision).
  double precision = kDefaultPrecision;
};

/// What reading one URDF file gave: the robot, or the errors; warnings in
/// both cases. Every diagnostic is positioned in the file (its XML line).
struct UrdfRead {
  std::optional<workcell::Robot> robot;
  std::vector<diag::Diagnostic> diagnostics;
};

/// Whether a name is a URDF file's (`.urdf`, any case).
inline bool isUrdfName(std::string_view fileOrName) {
  constexpr std::string_view kExt = ".urdf";
  if (fileOrName.size() <= kExt.size()) return false;
  for (std::size_t i = 0; i < kExt.size(); ++i) {
    char c = fileOrName[fileOrName.size() - kExt.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != kExt[i]) return false;
  }
  return true;
}

/// Reads `text`, the contents of the URDF file `file` (the name the
/// diagnostics carry; mesh files are looked up from its folder). In this
/// process: urdfdom and Assimp are linked (the helper program
/// `robotsim-urdf`, the tests and the fuzz target).
UrdfRead readUrdfText(std::string_view text, const std::string& file, const UrdfOptions& options);

/// Reads the file `path` (at most kMaxUrdfBytes; a FIFO or device is
/// refused) and then as readUrdfText.
UrdfRead readUrdfFile(const std::filesystem::path& path, const UrdfOptions& options);

}  // namespace rs::urdf
