// Errors and tolerances of the kinematics core. Bad geometry (a zero-length
// axis, a frame that breaks the D-H rules, ...) is an ordinary outcome of
// reading a description, so it comes back as a value, never as an exception:
// the description compiler turns each error into a `file:line:col: error:`
// diagnostic, using `index` to find the construct that caused it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rs::kinematics {

/// What went wrong, so callers and tests can tell errors apart without
/// parsing messages.
enum class ErrorKind : std::uint8_t {
  NotFinite,                     // a coordinate or parameter is NaN or infinite
  DegenerateAxis,                // an axis whose two points coincide
  AxesNotPerpendicular,          // a frame's x and z axes are not at right angles
  XNotPerpendicularToPreviousZ,  // D-H rule broken: x_i must be perpendicular to z_{i-1}
  XMissesPreviousZ,              // D-H rule broken: x_i must meet z_{i-1}
  CountMismatch,                 // frames, joints and drives do not add up
  BadPrecision,                  // a precision of zero, or not finite
  BadEncoder,                    // an encoder index that is negative or used twice
  BadCoupling,                   // coupling ON where there is nothing sound to couple
  TcpMismatch,                   // the approach vector does not start at the normal's start
};

/// One error. `index` is the frame number (0..n) for frame errors, the joint
/// number (1..n) for joint errors, and -1 when the error concerns the whole
/// chain or gripper. `message` is a complete sentence without a location.
struct KinematicsError {
  ErrorKind kind = ErrorKind::NotFinite;
  int index = -1;
  std::string message;
  bool operator==(const KinematicsError&) const = default;
};

/// What building a part of the model gave: the part, or every error found
/// while trying to build it (never both). Named apart from diag::Result,
/// which carries Diagnostics: the description compiler turns these errors
/// into those.
template <class T>
struct Built {
  std::optional<T> value;
  std::vector<KinematicsError> errors;
  bool ok() const { return value.has_value(); }
};

/// How far from ideal geometry may be before it counts as an error.
struct Tolerances {
  double cosine = 1e-6;    ///< largest |cos| between axes that must be perpendicular
  double distance = 1e-6;  ///< length units: largest gap between lines that must meet
  double length = 1e-9;    ///< length units: shortest axis that is not degenerate
};

}  // namespace rs::kinematics
