// How far each part of the arm can move between two moments of a move:
// the bounds of the swept check's conservative advancement
// (runtime/sim/collision_watch.h, docs/models.md "Collisions").
//
// Joint j (revolute) turns |Δq_j| radians; a point of a part it carries
// moves by at most |Δq_j| × its distance from the axis, and along a unit
// direction n by at most that × |n × u_j| (u_j the axis: the motion is
// round the axis). A prismatic joint moves it by |Δq_j| × |n · u_j|. Each
// motor moves one way during a move, so |Δq_j| <= Σ_m |dq_j/de_m| × the
// counts motor m covered, and these bounds hold for every moment between.
// While the arm moves, the axes tilt and the distances change: axis j
// tilts by at most the turns of the joints below it, each times the sine
// between its axis and axis j (which only the joints between them change:
// a SCARA's parallel axes never tilt); a part's distance from axis j grows
// by at most how far the joints above j move it. Relative to a frame of
// the arm (for a gap to another part of the robot) only the joints above
// that frame count. The fingers turn on the gripper motor, counted in any
// direction. Parts are numbered as workcell::PartClearance's: robot parts,
// then the carried object. No allocation after construction.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/collision_model.h"

namespace rs::runtime {

class MotionBounds final : public workcell::SweepMotion {
 public:
  /// `model` must outlive this.
  explicit MotionBounds(const workcell::CollisionModel& model);

  /// A new move; `carriedReach`: the carried object's points lie within
  /// this of the tool centre point (none: nothing carried).
  void startMove(std::optional<double> carriedReach);
  /// A check with the motors at `at`; the move ends with them at `end`
  /// (both must stay valid until the next check).
  void setCheck(std::span<const std::int32_t> at, std::span<const std::int32_t> end);
  /// What the gaps to the world are to (another robot's parts) may move
  /// this far by the move's end (from this check on): a moving part's gap
  /// to them closes by their travel too. Gaps to the arm's own parts do not.
  void othersMove(double toEnd) { othersToEnd_ = toEnd; }

  /// The most part `part` can move over a move from motors `from` to `to`
  /// (after startMove), from any check of it to any later one or to its
  /// end: each joint's whole turn at the part's bound on its distance from
  /// the axis. At least what anyWay() says at any check of the move.
  double mostTravel(std::size_t part, std::span<const std::int32_t> from, std::span<const std::int32_t> to) const;

  void posed(const workcell::CollisionData& data) override;
  /// At most kLookAhead: a check looks no farther (limit() keeps every
  /// part within it until the next check).
  double anyWay(std::size_t part) override { return std::min(need_[part] + others(part, 0), kLookAhead); }

  /// How far a check looks (length units): the gaps it counts are shorter,
  /// and no part goes this far before the next check. What lies farther
  /// from every part at a check cannot bear on it, so a move's verdict
  /// depends only on what lies near its way (CollisionWatch::reachKeyOf),
  /// and a long move through free space pays for the few pieces near it,
  /// not for every piece in the cell.
  static constexpr double kLookAhead = 200.0;
  double along(std::size_t part, const Eigen::Vector3d& normal, std::size_t from) override;

  /// The limits this check's gaps put on each part until the next check:
  /// a part may close a gap of at least workcell::kSweepStep up to a
  /// margin; where a gap is less, the part may move kSweepStep in any
  /// direction. False when there is none: the rest of the move is clear.
  bool limit(std::span<const workcell::PartClearance> clearance);
  /// The largest share of its allowance any limit has used with the
  /// motors at `to` (at most 1: within every limit).
  double used(std::span<const std::int32_t> to, double othersMoved = 0);

 private:
  struct Limit {
    std::size_t part = 0;
    std::size_t from = 0;
    std::size_t facing = 0;  // index into facing_, or SIZE_MAX: any direction
    double allowed = 0;
  };
  // How far the joints move from the check to motors `to`: turns_, tilt_.
  void jointTravel(std::span<const std::int32_t> to);
  // How far part p moves relative to frame `from`, along the direction
  // whose facings (per joint) are given, or in any direction (null).
  double partTravel(std::size_t p, std::size_t from, const double* facing) const;
  // What others' travel adds to part p's travel towards the world
  // (`from` 0): nothing for a part that does not move (docs/models.md:
  // the other's own check has it where it stands).
  double others(std::size_t p, std::size_t from) const { return from == 0 && need_[p] > 0 ? othersToEnd_ : 0.0; }
  // The facings of direction n for part p's joints from `from` on.
  void face(std::size_t p, const Eigen::Vector3d& n, std::size_t from, double* out) const;

  const workcell::CollisionModel& model_;
  const workcell::CollisionData* data_ = nullptr;  // posed for the check
  std::span<const std::int32_t> at_, end_;
  std::size_t joints_ = 0;
  std::vector<std::size_t> partFrame_;  // per part: its frame (joints below it move it)
  std::vector<double> radii_;           // per part and joint: bound on its distance from the axis
  std::vector<double> nearAxes_;        // per part and joint: its distance from the axis at the check
  std::vector<double> fingers_;         // per part: its gripper-motor weight
  std::vector<double> need_;            // per part: how far it can still go, any direction
  std::vector<double> turns_;           // per joint: how far it moves (radians or length units)
  // Per joint pair i < j: |u_i × u_j| at the check (skew_) and its bound
  // over the motion (lean_); per joint j, the prefix sums over i of how
  // far joint i's turn can tilt axis j (tilt_, joints × (joints + 1)).
  std::vector<double> skew_, lean_, tilt_;
  double gripperTurn_ = 0;        // counts the gripper motor covers
  double othersToEnd_ = 0;        // othersMove()
  std::vector<double> facing_;    // the limits' facings, joints each
  std::vector<double> scratch_;   // one direction's facings
  std::vector<Limit> limits_;
};

}  // namespace rs::runtime
