// A URDF link's visuals as robotsim draws and checks them (docs/models.md,
// "Reading URDF", "Geometry"): boxes, cylinders and spheres as wireframes;
// meshes (STL, COLLADA, OBJ, read with Debian's Assimp) by their feature
// edges, each visual's convex hull standing for it in collision checks.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include <urdf_model/link.h>

#include "model/workcell/model.h"

namespace rs::urdf {

/// A mesh edge is drawn where its two faces meet at more than this angle
/// (degrees between their normals), and where it borders one face only.
inline constexpr double kFeatureAngleDegrees = 30.0;
/// Segments of a cylinder's or a sphere's circle.
inline constexpr int kCircleSegments = 24;
/// Length of the axes drawn for a link whose mesh is missing (mm).
inline constexpr double kFrameAxisLength = 50.0;

struct MeshProblem {
  std::string message, hint;
  bool warning = true;  ///< a missing file; an unreadable one is an error
};

struct LinkGeometry {
  std::vector<workcell::Segment> segments;
  std::vector<workcell::ConvexPiece> pieces;
};

/// Adds `visual`'s lines and collision piece (in design coordinates:
/// millimetres, y up), for a link whose home frame in the root link is
/// F_root_link (metres). Mesh files are looked up from `urdfDir`
/// (urdf_mesh.cpp says how for package://).
void addVisual(const ::urdf::Visual& visual, const Eigen::Isometry3d& F_root_link,
               const std::filesystem::path& urdfDir, LinkGeometry& out, std::vector<MeshProblem>& problems);

/// The EGA colour nearest (in RGB) a URDF colour (components 0..1).
workcell::Color nearestEga(double r, double g, double b);

}  // namespace rs::urdf
