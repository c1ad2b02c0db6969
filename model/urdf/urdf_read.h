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
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "model/workcell/model.h"

namespace rs::urdf {

/// The largest URDF file read, as for descriptions: a larger one is
/// refused before it is parsed.
inline constexpr std::size_t kMaxUrdfBytes = std::size_t{64} << 20;
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
