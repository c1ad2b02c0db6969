// Inverse kinematics: joint values that put the tool frame (frame n) at a
// wanted pose. Closed form by kinematic family, found from the D-H table
// (ik_family.h), and a deterministic numeric method for every other chain
// (ik_numeric.h). Like forward kinematics: an immutable solver built once
// from a model, then calls that do not allocate.
//
// Poses are in the chain's frame 0 (the base). A target always carries a
// whole rotation, but says which of its axes the user wrote: the rest was
// filled in by the caller (from the previous point) and is what the arm
// may keep, in its family's way (docs/models.md, "Inverse kinematics").
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "model/kinematics/chain_model.h"
#include "model/kinematics/ik_family.h"

namespace rs::kinematics {

/// Chains with more joints than this are refused by inverse kinematics.
inline constexpr int kMaxIkJoints = 12;
/// Most solutions a closed form gives (shoulder × elbow × wrist).
inline constexpr int kMaxIkSolutions = 8;
/// Poses closer than this to a singular one are refused, in degrees of the
/// joint angle that measures it (a straight elbow, a straight wrist).
inline constexpr double kSingularDegrees = 1.0;
/// Points nearer joint 1's axis than this fraction of the arm's size
/// (FamilyShape::reach), where joint 1's angle is barely defined, are refused.
inline constexpr double kSingularAxisFraction = 1e-3;

/// The tool pose wanted, in frame 0 coordinates.
struct ToolTarget {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Columns n (normal, x), s (= a × n), a (approach, z): a rotation.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  bool approachGiven = false;  ///< the user wrote the approach a
  bool normalGiven = false;    ///< the user wrote the normal n
};

/// Configuration flags of a closed-form solution (bits).
enum IkConfig : std::uint8_t {
  kShoulderBack = 1,  ///< joint 1 turned half a turn from facing the target (reaching over)
  kElbowDown = 2,     ///< the other sign of the elbow angle (see docs/models.md)
  kWristFlip = 4,     ///< the other sign of the middle wrist angle
};

struct IkSolution {
  std::array<double, kMaxIkJoints> q{};  ///< degrees or length units, joints 1..n at 0..n-1
  std::uint8_t config = 0;               ///< IkConfig bits
};

enum class IkErrorKind : std::uint8_t {
  NoChain,             // too many joints, or nothing to solve
  Unreachable,         // the position is out of the arm's reach
  Singular,            // too close to a singular pose
  OrientationFixed,    // the arm cannot turn its tool that way
  NotConverged,        // the numeric method got no closer than `distance`
  NoSuchConfiguration, // solveConfig: the family has no such configuration
};

struct IkError {
  IkErrorKind kind = IkErrorKind::Unreachable;
  std::string message;  ///< a sentence without a position
  std::string hint;     ///< how to get past it, or empty
  double distance = 0;  ///< length units (or degrees) by which it failed
};

/// Every solution of one call, or why there is none.
struct IkSolutions {
  std::array<IkSolution, kMaxIkSolutions> solutions{};
  int count = 0;
  IkError error;  ///< meaningful when count == 0
  bool ok() const { return count > 0; }
  std::span<const IkSolution> view() const { return {solutions.data(), static_cast<std::size_t>(count)}; }
};

namespace ik {
struct Branches;  // ik_solvers.h
}

/// The solver of one chain: its family and the constants its closed form
/// needs, worked out once.
class InverseKinematics {
 public:
  explicit InverseKinematics(const ChainModel& model);

  const ChainModel& model() const { return model_; }
  IkFamily family() const { return family_.kind; }
  const FamilyShape& shape() const { return family_; }

  /// Every closed-form solution (or the numeric one) for `target`.
  /// `reference` holds the joint values of the previous point: the numeric
  /// method starts there, and a family keeps from it what the target did
  /// not write (see docs/models.md). Each solution is checked by forward
  /// kinematics; solutions that miss the target are dropped.
  IkSolutions solve(const ToolTarget& target, std::span<const double> reference) const;

  /// Only the solution of configuration `config` (IkConfig bits, one of
  /// configurations()): count 1 with exactly the joint values solve() gives
  /// for that configuration, bit for bit, or count 0 with why that
  /// configuration does not reach the target. It walks one branch of the
  /// same closed form (ik_solvers.h, Branches), so it costs about one
  /// solution. The numeric method has the one configuration 0.
  IkSolutions solveConfig(const ToolTarget& target, std::span<const double> reference, std::uint8_t config) const;

  /// The configurations the family has, in the order solve() lists its
  /// solutions: {0} (cartesian, numeric), 2 (scara: elbow), 4
  /// (articulated-5: shoulder × elbow) or 8 (the six-axis families:
  /// shoulder × elbow × wrist). A solution's index here is stable: what
  /// `robotsim ik --solution N` counts from 1.
  std::span<const std::uint8_t> configurations() const;

 private:
  IkSolutions solveBranches(const ToolTarget& target, std::span<const double> reference,
                            const ik::Branches& want) const;

  ChainModel model_;
  FamilyShape family_;
};

}  // namespace rs::kinematics
