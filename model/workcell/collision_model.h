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
//    other objects and the links at least two joints away, raised by
//    kSettleTolerance against the floor and the objects (a part put down a
//    little into its support rests on it). Not checked: the gripper's parts
//    against the object they carry, the fingers against the part they close
//    round or open round (`exempt`), the gripper's parts
//    against each other, resting objects against each other, link 0
//    (which never moves) against the objects and the floor — all of which
//    only checkAtHome looks at.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/chain_model.h"
#include "model/workcell/model.h"
#include "model/workcell/penetration.h"
#include "model/workcell/settle.h"

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
  CollisionModel(const Workcell& cell, std::size_t robot);
  /// The robot the cell's run drives moves (Workcell::drivenRobot).
  explicit CollisionModel(const Workcell& cell) : CollisionModel(cell, cell.drivenRobotIndex()) {}

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
  /// The same for robot part `body` alone (an index into robotBodies()):
  /// a link near the base moves less per count than the gripper, and a
  /// part moves not at all for a motor that drives no joint below it. A
  /// finger's gripper-motor weight is its own turn about its axis.
  std::span<const double> bodyWeights(std::size_t body) const;
  /// The same for the carried object alone, its points within `reach` of
  /// the tool centre point (it moves with the end-effector frame, not
  /// with the gripper motor).
  void carriedWeights(double reach, std::span<double> out) const;
  /// The same, joint by joint, for bounds that look at directions (the
  /// swept check): the arm's joints (joint j + 1 at index j) and, per count
  /// of each arm motor, how far each turns (radians, for a revolute joint)
  /// or slides (length units): |dq_j/de_m|.
  std::size_t jointCount() const { return revolute_.size(); }
  bool revolute(std::size_t j) const { return revolute_[j] != 0; }
  std::span<const double> jointRates(std::size_t j) const;
  /// Robot part `body`: per joint, a bound on the distance from the
  /// joint's axis to the part's points over every pose (0 for a joint above
  /// the part's frame: it does not move the part).
  std::span<const double> bodyRadii(std::size_t body) const;
  /// The same for the carried object, its points within `reach` of the
  /// tool centre point.
  void carriedRadii(double reach, std::span<double> out) const;
  /// Part `body`'s weight for the gripper motor (a finger's turn about its
  /// axis; 0 for any other part), and that motor's index (one past the
  /// arm's motors) when the robot has a gripper.
  double fingerWeight(std::size_t body) const { return fingerWeights_.empty() ? 0.0 : fingerWeights_[body]; }
  std::optional<std::size_t> gripperMotor() const {
    return hasGripper_ ? std::optional<std::size_t>(gripperMotor_) : std::nullopt;
  }
  /// The largest distance a point moves for one count of one motor (the
  /// resolution below which the sweep cannot go).
  double countStep() const;
  bool movable() const { return chain_.has_value(); }
  /// Where the robot's frame 0 (its base) stands in the world, and a bound
  /// on the distance from there to every point of its parts over every
  /// pose (the sum of the D-H translations' bounds up to each part's
  /// frame, plus the part's reach from that frame): two robots whose bases
  /// are farther apart than the sum of their reaches never meet.
  Eigen::Vector3d baseOrigin() const { return baseOrigin_; }
  double reach() const { return reach_; }
  /// The same for an object carried with its points within `carried` of
  /// the tool centre point.
  double reachCarrying(double carried) const {
    return std::max(reach_, (toReach_.empty() ? 0.0 : toReach_.front()) + carried);
  }

 private:
  friend class CollisionData;
  const Workcell* cell_;
  std::size_t robot_;
  std::optional<kinematics::ChainModel> chain_;  // placed in the world
  std::vector<Eigen::Isometry3d> M_;  // per frame: F_world_i(home)⁻¹ · F_world_design
  std::vector<CollisionBody> robotBodies_, objectBodies_;
  std::vector<double> motorWeights_;
  std::vector<double> bodyWeights_;  // robot bodies × motorWeights_.size()
  std::vector<char> revolute_;        // per joint
  std::vector<double> jointRates_;    // joints × arm motors
  std::vector<double> bodyRadii_;     // robot bodies × joints
  std::vector<double> fingerWeights_; // per robot body
  // Per joint i (index i-1): |dq_i/de_m| per motor, whether revolute (in
  // radians per degree), the bound on |o_{i-1} − o_n| over all poses.
  std::vector<std::vector<double>> dqde_;
  std::vector<double> jointScale_, toReach_, staticRho_;
  std::size_t gripperMotor_ = 0;
  bool hasGripper_ = false;
  double fingerWeight_ = 0;
  Eigen::Vector3d baseOrigin_ = Eigen::Vector3d::Zero();
  double reach_ = 0;
};

/// A bound on the distance from a gripper's tool centre point to every
/// point of any part of `cell` it holds (not a fixture): it takes a part
/// only with the tool centre point inside the part's world box, which lies
/// within √3·ρ of the centre of a ball of radius ρ round the part's lines
/// and pieces, so every point of the part is within (1 + √3)·ρ of it.
double carriedReach(const Workcell& cell);

/// The world box round each piece of `body` at pose `T` (into `out`, one
/// per piece): the exact test is asked about two pieces only when their
/// boxes meet.
void pieceBoxes(const CollisionBody& body, const Eigen::Isometry3d& T, Eigen::AlignedBox3d* out);
/// The gripper's base or a finger.
bool isGripperPart(const CollisionBody& body);
/// A finger of the gripper.
bool isFinger(const CollisionBody& body);
/// The carried object's pose for its checks against the floor and the
/// objects: `T` raised by kSettleTolerance (world y is up).
inline Eigen::Isometry3d raisedForRest(const Eigen::Isometry3d& T) {
  return Eigen::Translation3d(0, kSettleTolerance, 0) * T;
}

/// What else the check needs to know besides the robot's motors.
struct CollisionQuery {
  std::span<const Eigen::Isometry3d> objectPoses;  ///< F_world_design of each object at rest
  std::optional<std::size_t> held;                 ///< carried with the gripper's frame
  Eigen::Isometry3d heldOffset = Eigen::Isometry3d::Identity();  ///< F_E_object of the carried one
  /// The part the fingers (not the gripper's base) may overlap: the one
  /// they close round during a closing move, or open round during an
  /// opening one (runtime/cell/world.h decides).
  std::optional<std::size_t> exempt;
  /// The cell's objects that are in it (Grasping::inCell, in index order)
  /// when not every one is: the first `cellObjects` objects are checked
  /// only when listed, the rest (another robot's parts) always. A feeder's
  /// empty slot is out of the cell: nothing collides with it.
  const std::vector<std::size_t>* inCell = nullptr;
  std::size_t cellObjects = 0;
  /// Calls f(o) for each object checked, in index order, of `count`, until
  /// f returns true; whether it did.
  template <typename F>
  bool anyObject(std::size_t count, F&& f) const {
    std::size_t from = 0;
    if (inCell) {
      for (const std::size_t o : *inCell) {
        if (o >= count || o >= cellObjects) break;
        if (f(o)) return true;
      }
      from = cellObjects;
    }
    for (std::size_t o = from; o < count; ++o)
      if (f(o)) return true;
    return false;
  }
};

/// A gap between a moving part and what it is checked against, which
/// stands still or moves with arm frame `from` (the floor and the objects:
/// 0; another part of the robot: its frame): no point of the part is
/// nearer than `distance` to it along `normal`, a unit vector (either way).
/// To touch it, some point of the part must move at least that far along
/// that direction relative to frame `from`, which only the joints above
/// `from` can do.
struct Gap {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double distance = 0;
  std::size_t from = 0;
};

/// What the swept check learns of one moving part at a pose: its nearest
/// gaps, each with its direction, and a bound on its distance to all else
/// it is checked against, in any direction and relative to the world (the
/// gaps that did not fit).
struct PartClearance {
  static constexpr std::size_t kGaps = 16;
  std::array<Gap, kGaps> gaps;
  std::size_t count = 0;
  double elsewhere = 0;  ///< set by reset() to +infinity

  void reset();
  /// Keeps the kGaps smallest gaps; a larger one goes to `elsewhere`.
  void add(const Gap& gap);
  /// The distance to the nearest of all, in any direction.
  double least() const;
};

class CollisionData;

/// What findContactOrClearance asks of the motion still to come, to leave
/// out the gaps a part cannot close before the move ends. Parts are
/// numbered as PartClearance's: robot parts, then the carried object.
class SweepMotion {
 public:
  /// The arm is posed for the check (`data`'s frame() and partBox() are
  /// this pose's): before anything else is asked.
  virtual void posed(const CollisionData& data) = 0;
  /// How far a point of `part` can still move, in any direction.
  virtual double anyWay(std::size_t part) = 0;
  /// How far along `normal` (a unit vector, either way), relative to arm
  /// frame `from`.
  virtual double along(std::size_t part, const Eigen::Vector3d& normal, std::size_t from) = 0;

 protected:
  ~SweepMotion() = default;
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
  /// What the swept check asks at one pose (conservative advancement):
  /// the first overlap, exactly as findContact finds it; when there is
  /// none, for each robot part (index into robotBodies()) and, last, the
  /// carried object, its gaps to the floor, the objects and the parts of
  /// the robot below it that it could close before the move ends
  /// (`motion` says how far it can still go: a gap it cannot close is left
  /// out): while every part keeps within its gaps, no pair that is checked
  /// can meet. A gap is a whole body's while their boxes are apart, else a
  /// piece's, refined by GJK. `clearance` has robotBodies().size() + 1
  /// entries. No allocation.
  std::optional<Contact> findContactOrClearance(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                                SweepMotion& motion, std::span<PartClearance> clearance);
  /// What a move's reach is measured from, with the motors at `encoders`:
  /// per moving part (robotBodies() order, then the carried object as
  /// raised for rest), its world box, empty for a part that is not checked
  /// against objects. An object whose box is out of reach (outOfReach) of
  /// every part's box by twice that part's travel over a stretch of the
  /// move from here plus how far a check looks (MotionBounds::kLookAhead,
  /// or what the part can still go) gets no gap and no contact in any
  /// check of the stretch: it may stand anywhere (clearance.cpp).
  void reachBoxes(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                  std::vector<Eigen::AlignedBox3d>& out);
  /// Object o's world box at `pose` (its pieces' boxes, kept for the checks).
  const Eigen::AlignedBox3d& objectHull(std::size_t o, const Eigen::Isometry3d& pose) {
    objectBoxes(o, pose);
    return objectHull_[o];
  }
  /// Whether the gap between a part's box and an object's is longer than
  /// `reach`, with a margin for rounding (true when either is empty).
  static bool outOfReach(const Eigen::AlignedBox3d& part, double reach, const Eigen::AlignedBox3d& object);
  /// Poses the arm at `encoders` and checks nothing: frame() and
  /// robotPose() answer for this pose (what a sensor that sees the robot
  /// asks, runtime/cell/robot_sight.h). No allocation.
  void poseOnly(std::span<const std::int32_t> encoders) { pose(encoders); }
  /// Frame i (0..n) of the arm in the world at the last pose checked:
  /// joint i + 1 turns about (or slides along) its z axis.
  const Eigen::Isometry3d& frame(std::size_t i) const { return F_world_i_[i]; }
  /// The world box round robot part `part` (robotBodies() order; one past
  /// them: the carried object) at the last findContactOrClearance without
  /// a contact.
  const Eigen::AlignedBox3d& partBox(std::size_t part) const {
    return part < robotHull_.size() ? robotHull_[part] : heldHull_;
  }
  /// Every overlap at that pose, in the same order (for pictures and
  /// checkAtHome; allocates). `withStatic`: link 0 against the floor and
  /// the objects too.
  std::vector<Contact> allContacts(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                   bool withStatic = false);
  /// How deep the two parts of `contact` are in each other at the last
  /// pose checked (the contact findContact or findContactOrClearance found
  /// there), as drawn: their deepest pair of overlapping pieces
  /// (penetration.h), the check's inset (kContactTolerance) added back.
  /// For messages (contact_depth.cpp).
  Overlap overlap(const Contact& contact, const CollisionQuery& query) const;
  /// The same pair at motor positions `encoders` (which becomes the last
  /// pose checked): their overlap there, or nothing when they do not overlap.
  std::optional<Overlap> overlapAt(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                   const Contact& contact);
  /// The end-effector frame of the last pose checked.
  const Eigen::Isometry3d& toolFrame() const { return F_world_i_.back(); }
  /// Pose of a robot part at the last pose checked (F_world of its points).
  const Eigen::Isometry3d& robotPose(std::size_t body) const { return robotPoses_[body]; }

 private:
  /// The body `ref` names and where it is at the last pose checked (the floor: none).
  std::pair<const CollisionBody*, Eigen::Isometry3d> placed(const BodyRef& ref, const CollisionQuery& query) const;
  /// Whether any pair of their pieces overlaps, and the deepest pair's overlap.
  std::optional<Overlap> pairOverlap(const Contact& contact, const CollisionQuery& query) const;
  template <typename OnContact>
  void scan(std::span<const std::int32_t> encoders, const CollisionQuery& query, OnContact&& on);
  void pose(std::span<const std::int32_t> encoders);
  // The robot's piece boxes and hulls at the pose, the carried object's
  // true and raised for rest (clearance.cpp).
  void boxParts(const CollisionQuery& query, bool holds);
  // outOfReach_ for this check (clearance.cpp).
  void markOutOfReach(const CollisionQuery& query, SweepMotion& motion, bool holds);
  // Object o's piece boxes at `pose`, kept until its pose changes.
  const Eigen::AlignedBox3d* objectBoxes(std::size_t o, const Eigen::Isometry3d& pose);

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
  std::vector<Eigen::AlignedBox3d> heldBoxes_, heldRaisedBoxes_;  // the carried object's, true and raisedForRest
  // The union of each body's piece boxes (the broad phase of the clearance).
  std::vector<Eigen::AlignedBox3d> robotHull_, objectHull_;
  Eigen::AlignedBox3d heldHull_, heldRaisedHull_;
  std::vector<char> outOfReach_;  // per object: no moving part can close its gap this check (clearance.cpp)
};

/// Every overlap of the robot the cell drives (Workcell::drivenRobot) at its home pose, objects where
/// the cell placed them, nothing exempt, link 0 included (what the
/// description reader reports when it builds a workcell).
std::vector<Contact> checkAtHome(const Workcell& cell);

}  // namespace rs::workcell
