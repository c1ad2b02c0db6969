#include "runtime/render/tool_path.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdlib>

#include "model/workcell/tool_tracker.h"

namespace rs::render {

namespace {

// A joint move is sampled every this many counts of each motor (at most
// kMaxPieces pieces): its tool centre point bends little over a few counts.
constexpr std::int64_t kCountsPerPiece = 4;
constexpr std::int64_t kMaxPieces = 256;
// The points a thinned stretch may leave out before one is kept anyway:
// bounds the work per point.
constexpr std::size_t kMaxPending = 64;

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 <= 0) return (p - a).norm();
  const double s = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (p - (a + s * ab)).norm();
}

// Keeps a point only where leaving it out would put a point of the path
// farther than `tolerance` from the polyline kept.
class Thinner {
 public:
  Thinner(double tolerance, std::vector<PathPoint>& out) : tolerance_(tolerance), out_(out) {}

  void add(const PathPoint& p) {
    if (out_.empty() || p.jump) {
      flush();
      out_.push_back(p);
      return;
    }
    const Eigen::Vector3d& a = out_.back().p;
    // Near the last point kept, as everything since: any line on from there
    // passes within the tolerance of them all (a motor jiggling by a count
    // costs nothing).
    const bool near = (p.p - a).norm() <= tolerance_;
    if (near && nearSince_) {
      pending_.assign(1, p);
      return;
    }
    nearSince_ = nearSince_ && near;
    pending_.push_back(p);
    if (pending_.size() < 2) return;
    bool covered = pending_.size() <= kMaxPending;
    for (std::size_t i = 0; covered && i + 1 < pending_.size(); ++i)
      covered = distanceToSegment(pending_[i].p, a, p.p) <= tolerance_;
    if (covered) return;
    // The point before p stands for everything since the last one kept
    // (it was covered when it came), and becomes the one kept.
    out_.push_back(pending_[pending_.size() - 2]);
    pending_.erase(pending_.begin(), pending_.end() - 1);
    nearSince_ = (pending_.back().p - out_.back().p).norm() <= tolerance_;
  }
  void flush() {
    if (!pending_.empty()) out_.push_back(pending_.back());
    pending_.clear();
    nearSince_ = true;
  }

 private:
  double tolerance_;
  std::vector<PathPoint>& out_;
  std::vector<PathPoint> pending_;
  bool nearSince_ = true;  // every point pending is within the tolerance of the last one kept
};

}  // namespace

std::vector<PathPoint> toolPathOf(const runtime::RunLog& log, const workcell::PlacedRobot& robot, double tolerance) {
  std::vector<PathPoint> path;
  if (!robot.robot.chain) return path;
  workcell::ToolTracker tracker(robot);
  const std::size_t motors = log.motors.size();
  std::vector<std::int32_t> encoders(motors, 0);
  const auto tcpNow = [&] {
    const std::array<double, 3> p = tracker.tcp(encoders);
    return Eigen::Vector3d(p[0], p[1], p[2]);
  };
  Thinner thinner(tolerance, path);
  thinner.add({0, tcpNow(), false});

  // Per motor: the next move not yet reached, and the one under way.
  std::vector<std::size_t> next(motors, 0);
  std::vector<std::ptrdiff_t> current(motors, -1);
  std::vector<std::int32_t> lastTo(motors, 0);  // where each motor's last move took it
  std::vector<vm::Micros> times;
  std::vector<vm::Micros> jumps;
  for (std::size_t s = 0; s < log.steps.size(); ++s) {
    times.clear();
    jumps.clear();
    for (std::size_t m = 0; m < motors; ++m) {
      if (log.motors[m].kind == vm::JointKind::Gripper) continue;  // it does not move the tool centre point
      const std::vector<runtime::MotorMove>& list = log.moves[m];
      for (std::size_t i = next[m]; i < list.size() && list[i].step <= s; ++i) {
        const runtime::MotorMove& mv = list[i];
        times.push_back(mv.start);
        times.push_back(mv.end);
        // A jump (RESET) takes no time; the log gives it as a move from its end to its end.
        if (mv.start == mv.end && mv.to != lastTo[m]) jumps.push_back(mv.start);
        lastTo[m] = mv.to;
        if (mv.lockStep || mv.end <= mv.start) continue;
        const std::int64_t counts = std::llabs(static_cast<std::int64_t>(mv.to) - mv.from);
        const std::int64_t pieces = std::clamp<std::int64_t>(counts / kCountsPerPiece, 1, kMaxPieces);
        for (std::int64_t k = 1; k < pieces; ++k) times.push_back(mv.start + (mv.end - mv.start) * k / pieces);
      }
    }
    if (times.empty()) continue;
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    for (const vm::Micros t : times) {
      for (std::size_t m = 0; m < motors; ++m) {
        const std::vector<runtime::MotorMove>& list = log.moves[m];
        // The move under way at t: the last of this step's or an earlier one's to have started.
        while (next[m] < list.size() && list[next[m]].step <= s && list[next[m]].start <= t)
          current[m] = static_cast<std::ptrdiff_t>(next[m]++);
        if (current[m] >= 0)
          encoders[m] = runtime::positionAt(list[static_cast<std::size_t>(current[m])], log.motors[m], t);
      }
      const bool jump = std::find(jumps.begin(), jumps.end(), t) != jumps.end();
      thinner.add({t, tcpNow(), jump});
    }
  }
  thinner.flush();
  return path;
}

std::vector<PathPoint> pathUntil(const std::vector<PathPoint>& path, vm::Micros t, const Eigen::Vector3d& tcp) {
  const auto end = std::upper_bound(path.begin(), path.end(), t, [](vm::Micros v, const PathPoint& p) { return v < p.at; });
  std::vector<PathPoint> out(path.begin(), end);
  if (out.empty() || (out.back().p - tcp).norm() > 1e-9) out.push_back({t, tcp, false});
  return out;
}

}  // namespace rs::render
