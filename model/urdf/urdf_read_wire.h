// A URDF read as bytes between processes: the helper program robotsim-urdf
// (which links urdfdom and Assimp) writes it, the static robotsim reads it
// (urdf_read_remote.h). JSON, with every double written so that it reads
// back as the same double: the robot the command gets is the one the
// helper built, to the last bit.
#pragma once

#include <string>
#include <string_view>

#include "model/urdf/urdf_read.h"

namespace rs::urdf {

std::string encodeUrdfRead(const UrdfRead& read);

/// The read `bytes` hold; a read whose robot or diagnostics cannot be
/// decoded is an error of `file`.
UrdfRead decodeUrdfRead(std::string_view bytes, const std::string& file);

}  // namespace rs::urdf
