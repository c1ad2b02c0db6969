// Collision geometry of a workcell and the check of one pose (Pinocchio's
// split: an immutable CollisionModel built once from the cell, a
// CollisionData workspace built once from the model; findContact writes
// only into the workspace and never allocates).
//
// What is modelled (docs/models.md, "Collisions"):
//  - every link, gripper part and object is the union of its convex pieces
//    (ConvexPiece: each BOX, the hull of the LINEs, or COLLIDE statements);
//    each piece is made smaller by kContactTolerance (a box face by face, a
//    hull by moving each point that far towards its centre), so shapes that
//    touch or overlap by less than that do not collide;
//  - the floor (Workcell::floor) is solid below its plane;
//  - pairs checked: each moving part of the robot (links that move, the
//    gripper's base and fingers) against the floor, every object and every
//    robot part whose frame is at least two joints away (adjacent links
//    touch at their joint by design); the carried object belongs to the
//    gripper's frame and is checked the same way, against the floor, the
//    other objects and the links at least two joints away. Not checked:
//    the gripper's parts against the object they carry or are about to take
//    (`exempt`: fingers go round what they grip), the gripper's parts
//    against each other, resting objects against each other, link 0
//    (which never moves) against the objects and the floor — all of which
//    only checkAtHome looks at.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/chain_model.h"
#include "model/workcell/model.h"

namespace rs::workcell {

/// How much each piece is made smaller, in the cell's length units.
inline constexpr double kContactTolerance = 0.01;
/// The sweep's bound δ: between two checks of a move, no point of the robot
/// (or of what it carries) moves farther than this, in length units, unless
/// one encoder count alone moves a point farther (CollisionModel::countStep).
inline constexpr double kSweepStep = 1.0;

enum class BodyKind : std::uint8_t { Link, GripperBase, Finger2, Finger3, Object, Floor };

/// A part that takes part in a collision.
struct BodyRef {
  BodyKind kind = BodyKind::Link;
  int index = 0;  ///< link number; object index for Object; 0 otherwise
  bool operator==(const BodyRef&) const = default;
};

/// Two parts found overlapping: `a` belongs to the robot (or is the object
/// it carries), `b` is what it hits.
struct Contact {
  BodyRef a, b;
  bool operator==(const Contact&) const = default;
};

/// A piece as the check uses it: inset, in its body's own coordinates.
struct CollisionPiece {
  std::vector<Eigen::Vector3d> points;
};

struct CollisionBody {
  BodyRef ref;
  std::string name;  ///< the link's or object's name
  int frame = 0;     ///< the robot frame it moves with (objects: -1)
  std::vector<CollisionPiece> pieces;
};

class CollisionModel {
 public:
  /// Robot `robot` of `cell` (which must outlive the model) is the one that
  /// moves. A robot without a chain has only static parts.
  explicit CollisionModel(const Workcell& cell, std::size_t robot = 0);

  const Workcell& cell() const { return *cell_; }
  /// Robot parts (links in order, then the gripper's base and fingers).
  std::span<const CollisionBody> robotBodies() const { return robotBodies_; }
  /// One per object of the cell, in order.
  std::span<const CollisionBody> objectBodies() const { return objectBodies_; }
  /// The name of a part, as messages give it ("link 2 (upper_arm)",
  /// "object 3 (block)", "the floor").
  std::string describe(const BodyRef& ref) const;
  /// The link or object's own name ("" for the floor).
  std::string_view nameOf(const BodyRef& ref) const;

  /// Length units a point of the robot (gripper included, nothing carried)
  /// can move per encoder count of each motor: the sum over the joints the
  /// motor drives of |dq/de| × (distance bound from the joint's axis).
  std::span<const double> motorWeights() const { return motorWeights_; }
  /// The same when carrying an object whose points lie within `reach` of
  /// the tool centre point.
  void motorWeightsCarrying(double reach, std::span<double> out) const;
  /// The largest distance a point moves for one count of one motor (the
  /// resolution below which the sweep cannot go).
  double countStep() const;
  bool movable() const { return chain_.has_value(); }

 private:
  friend class CollisionData;
  const Workcell* cell_;
  std::size_t robot_;
  std::optional<kinematics::ChainModel> chain_;  // placed in the world
  std::vector<Eigen::Isometry3d> M_;  // per frame: F_world_i(home)⁻¹ · F_world_design
  std::vector<CollisionBody> robotBodies_, objectBodies_;
  std::vector<double> motorWeights_;
  // Per joint i (index i-1): |dq_i/de_m| per motor, whether revolute (in
  // radians per degree), the bound on |o_{i-1} − o_n| over all poses.
  std::vector<std::vector<double>> dqde_;
  std::vector<double> jointScale_, toReach_, staticRho_;
  std::size_t gripperMotor_ = 0;
  bool hasGripper_ = false;
  double fingerWeight_ = 0;
};

/// What else the check needs to know besides the robot's motors.
struct CollisionQuery {
  std::span<const Eigen::Isometry3d> objectPoses;  ///< F_world_design of each object at rest
  std::optional<std::size_t> held;                 ///< carried with the gripper's frame
  Eigen::Isometry3d heldOffset = Eigen::Isometry3d::Identity();  ///< F_E_object of the carried one
  /// The objects the gripper's parts may overlap: those the tool centre
  /// point is in at the start and at the end of the move.
  std::optional<std::size_t> exempt, exemptToo;
};

/// The workspace: poses of every part for one check.
class CollisionData {
 public:
  explicit CollisionData(const CollisionModel& model);

  /// The first overlap at the robot's motor positions `encoders` (arm
  /// joints, then the gripper), in a fixed order: robot parts in order
  /// against the floor, the objects, the other links; then the carried
  /// object. No allocation.
  std::optional<Contact> findContact(std::span<const std::int32_t> encoders, const CollisionQuery& query);
  /// Every overlap at that pose, in the same order (for pictures and
  /// checkAtHome; allocates). `withStatic`: link 0 against the floor and
  /// the objects too.
  std::vector<Contact> allContacts(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                   bool withStatic = false);
  /// The end-effector frame of the last pose checked.
  const Eigen::Isometry3d& toolFrame() const { return F_world_i_.back(); }
  /// Pose of a robot part at the last pose checked (F_world of its points).
  const Eigen::Isometry3d& robotPose(std::size_t body) const { return robotPoses_[body]; }

 private:
  template <typename OnContact>
  void scan(std::span<const std::int32_t> encoders, const CollisionQuery& query, OnContact&& on);
  void pose(std::span<const std::int32_t> encoders);

  const CollisionModel& model_;
  std::optional<kinematics::ChainData> chainData_;
  std::vector<double> q_;
  std::vector<std::int32_t> encoders_;
  std::vector<Eigen::Isometry3d> F_world_i_;
  std::vector<Eigen::Isometry3d> robotPoses_;
  // World boxes round each piece: the robot's at the last pose, each
  // object's at the pose they were made for, the carried object's.
  std::vector<std::vector<Eigen::AlignedBox3d>> robotBoxes_, objectBoxes_;
  std::vector<Eigen::Isometry3d> objectBoxPose_;
  std::vector<char> objectBoxOk_;
  std::vector<Eigen::AlignedBox3d> heldBoxes_;
};

/// Every overlap of the cell's first robot at its home pose, objects where
/// the cell placed them, nothing exempt, link 0 included (what the
/// description reader reports when it builds a workcell).
std::vector<Contact> checkAtHome(const Workcell& cell);

}  // namespace rs::workcell
