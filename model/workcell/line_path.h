// Straight-line moves (MOVES, APPRO, DEPART): the tool centre point along
// a line, as a sequence of small motor moves in lock-step (knots), each
// knot on the line, the arm in one configuration, and the knots close
// enough that the joint-linear motion between two of them stays within
// kLineTolerance of the line (docs/language.md, "Straight-line moves").
// Shared by the compiler's path check and the simulated cell's machine.
//
// Model and data, as for the chain: the planner is built once per robot
// and is read-only; a LinePath holds every buffer a plan writes, reused
// from plan to plan (no allocation per knot once it has grown). A planner
// given a LinePlanCache (line_plan_cache.h) answers a line it (or another
// planner of the same arm) planned before from there, with the same plan.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/ik.h"
#include "model/workcell/model.h"

namespace rs::workcell {

/// How far (length units) the motion between two knots may stray from the
/// line, before the encoders' whole counts (lineResolution) add theirs.
inline constexpr double kLineTolerance = 0.1;
/// The most the motors of one knot, each on its own, move the tool (in
/// sum, length units): what a controller that runs each motor at its own
/// speed between knots can add to the deviation (docs/serial.md).
inline constexpr double kKnotTravel = 2.0;
/// Most knots one line may take.
inline constexpr std::size_t kMaxLineKnots = 200'000;

/// Why a line cannot be run, and where on it.
struct LineProblem {
  double fraction = 0;                               ///< 0..1 along the line
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the tool centre point there, world coordinates
  std::string message;                               ///< a sentence without a position
  std::string hint;
  std::string_view code;  ///< line-unreachable, line-singular, line-out-of-range, line-configuration, line-too-long
};

class LinePlanner;
class LinePlanCache;

/// The knots of one plan, and the planner's scratch buffers.
class LinePath {
 public:
  explicit LinePath(const LinePlanner& planner);
  /// Knots after the start, the last one the line's end: one encoder count per motor each.
  std::size_t size() const { return motors_ == 0 ? 0 : knots_.size() / motors_; }
  std::span<const std::int32_t> knot(std::size_t k) const { return {knots_.data() + k * motors_, motors_}; }
  /// The motors that lead in knot k (vm::Machine::moveLockStep's `lead`):
  /// in the first half of the line those whose share of the knot carries
  /// the tool forward along it, in the second half those that carry it back.
  std::uint32_t lead(std::size_t k) const { return leads_[k]; }

 private:
  friend class LinePlanner;
  std::size_t motors_ = 0;
  std::vector<std::uint64_t> key_;  // scratch: the cache's key of the line being planned
  std::vector<std::int32_t> knots_;
  std::vector<std::uint32_t> leads_;
  kinematics::ChainData data_;
  kinematics::ChainData prevData_;  // the frames of prev_, the knot before (plan())
  std::vector<double> q0_, q1_, prev_, next_, ref_, mid_, counts_;
};

class LinePlanner {
 public:
  /// `robot` must have a chain and outlive the planner; so must `cache`
  /// (may be null: every line is planned).
  explicit LinePlanner(const PlacedRobot& robot, LinePlanCache* cache = nullptr);

  /// MOVES: from encoder counts `start` to `end` (one per motor each).
  std::optional<LineProblem> planTo(std::span<const std::int32_t> start, std::span<const std::int32_t> end,
                                    LinePath& path, std::string_view what = "MOVES") const;
  /// APPRO (distance > 0) and DEPART (< 0): along the tool's approach axis.
  std::optional<LineProblem> planAlongTool(std::span<const std::int32_t> start, double distance, LinePath& path,
                                           std::string_view what) const;

  std::size_t motorCount() const { return motors_; }
  const kinematics::ChainModel& chain() const { return ik_.model(); }
  /// Frame 0 (the base) in the world.
  const Eigen::Isometry3d& F_world_0() const { return F_world_0_; }
  /// Everything of the arm a plan depends on, as words (the cache's arm).
  std::vector<std::uint64_t> armDescription() const;

 private:
  struct Line;
  template <typename Plan>
  std::optional<LineProblem> cached(std::uint64_t kind, std::span<const std::int32_t> start,
                                    std::span<const std::int32_t> end, double distance, std::string_view what,
                                    LinePath& path, Plan&& plan) const;
  std::optional<LineProblem> plan(const Line& line, std::span<const std::int32_t> start, LinePath& path,
                                  std::span<const std::int32_t> end, std::string_view what) const;
  bool solveAt(const Line& line, double s, std::uint8_t config, LinePath& path, kinematics::IkError& error) const;
  /// Rounds joint values to counts (into path.counts_); the first joint out of range, or -1.
  int countsOf(std::span<const double> q, LinePath& path) const;
  Eigen::Vector3d tcpOf(std::span<const double> q, LinePath& path) const;
  std::string configName(std::uint8_t config) const;

  const PlacedRobot& robot_;
  kinematics::InverseKinematics ik_;
  Eigen::Isometry3d F_world_0_;
  std::size_t motors_ = 0;
  bool fullOrientation_ = false;
  LinePlanCache* cache_ = nullptr;
  std::uint32_t armId_ = 0;  // the arm's number in cache_
};

}  // namespace rs::workcell
