#include "runtime/render/cell_moment.h"

#include <algorithm>

#include "model/workcell/tool_tracker.h"

namespace rs::render {

namespace {

// A take or let-go of robot `robot` (an index in Workcell::robots).
struct CellGrasp {
  std::size_t robot = 0;
  const runtime::GraspEvent* event = nullptr;
};

// Every motor of `log` at time t, by time: the last move that started by
// then.
std::vector<std::int32_t> motorsAt(const runtime::RunLog& log, vm::Micros t) {
  std::vector<std::int32_t> out(log.motors.size(), 0);
  for (std::size_t m = 0; m < log.motors.size(); ++m) {
    const std::vector<runtime::MotorMove>& moves = log.moves[m];
    const auto after = std::upper_bound(moves.begin(), moves.end(), t,
                                        [](vm::Micros v, const runtime::MotorMove& x) { return v < x.start; });
    if (after != moves.begin()) out[m] = runtime::positionAt(*(after - 1), log.motors[m], t);
  }
  return out;
}

}  // namespace

CellMoment cellMomentOf(const runtime::CellRun& run, vm::Micros at) {
  const workcell::Workcell& cell = run.cell();
  CellMoment m;
  m.at = at;
  m.encoders.resize(cell.robots.size());
  m.held.resize(cell.robots.size());
  std::vector<CellGrasp> grasps;
  for (std::size_t p = 0; p < run.size(); ++p) {
    const runtime::Run& robot = run.robot(p);
    const std::size_t r = robot.rig().robotIndex();
    const runtime::RunLog* log = robot.log();
    // After its last logged step the robot's machine knows best: a robot
    // the cell stopped in the middle of a move never logged that step.
    if (log && !log->steps.empty() && at < log->steps.back().end) {
      m.encoders[r] = motorsAt(*log, at);
    } else {
      m.encoders[r] = robot.rig().motorsAt(at);
    }
    if (log)
      for (const runtime::GraspRecord& g : log->grasps) grasps.push_back({r, &g.event});
  }
  // In the order they happened; at one microsecond, in the cell's robot order.
  std::stable_sort(grasps.begin(), grasps.end(), [](const CellGrasp& a, const CellGrasp& b) {
    return a.event->at != b.event->at ? a.event->at < b.event->at : a.robot < b.robot;
  });

  // Each part's last motion by then (a belt's, a feeder's, a sink's, a
  // settle): the devices log each in the log of the robot whose step it
  // came in, so every log is looked at.
  std::vector<const runtime::PartMotion*> motion(cell.objects.size(), nullptr);
  for (std::size_t p = 0; p < run.size(); ++p)
    if (const runtime::RunLog* log = run.robot(p).log())
      for (const runtime::MotionRecord& r : log->motions)
        if (r.motion.at <= at && r.motion.object < motion.size() &&
            (!motion[r.motion.object] || motion[r.motion.object]->at <= r.motion.at))
          motion[r.motion.object] = &r.motion;
  std::vector<std::optional<std::size_t>> carrier(cell.objects.size());
  std::vector<Eigen::Isometry3d> offset(cell.objects.size(), Eigen::Isometry3d::Identity());
  std::vector<vm::Micros> letGo(cell.objects.size(), -1);  // its last let-go by then
  for (std::size_t o = 0; o < cell.objects.size(); ++o) m.objects.push_back(cell.objects[o].F_world_design);
  for (const CellGrasp& g : grasps) {
    const runtime::GraspEvent& e = *g.event;
    if (e.at > at || e.object >= cell.objects.size()) continue;
    if (e.held) {
      carrier[e.object] = g.robot, offset[e.object] = e.pose;
    } else if (!e.other) {  // a hand-over's let-go: the other robot has it now
      carrier[e.object].reset(), m.objects[e.object] = e.pose, letGo[e.object] = e.at;
    }
  }
  // A motion logged at or after the part's let-go is where it went next
  // (no further than where the run stopped it).
  const vm::Micros until = std::min(at, run.clock());
  for (std::size_t o = 0; o < cell.objects.size(); ++o)
    if (!carrier[o] && motion[o] && motion[o]->at >= letGo[o]) m.objects[o] = motion[o]->poseAt(until);
  for (std::size_t o = 0; o < cell.objects.size(); ++o) {
    if (!carrier[o]) continue;
    const std::size_t r = *carrier[o];
    workcell::ToolTracker tool(cell.robots[r]);
    m.objects[o] = tool.frame(m.encoders[r]) * offset[o];
    m.held[r] = o;
  }
  return m;
}

}  // namespace rs::render
