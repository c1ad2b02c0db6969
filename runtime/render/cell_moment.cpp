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

  // Where the run left the parts no grasp moved (a belt's, a feeder's); the
  // grasps then put the others where they were at `at`.
  const std::vector<runtime::ObjectView> left =
      run.size() ? run.robot(0).rig().objects() : std::vector<runtime::ObjectView>{};
  std::vector<bool> grasped(cell.objects.size(), false);
  for (const CellGrasp& g : grasps)
    if (g.event->object < grasped.size()) grasped[g.event->object] = true;
  std::vector<std::optional<std::size_t>> carrier(cell.objects.size());
  std::vector<Eigen::Isometry3d> offset(cell.objects.size(), Eigen::Isometry3d::Identity());
  for (std::size_t o = 0; o < cell.objects.size(); ++o)
    m.objects.push_back(grasped[o] || o >= left.size() ? cell.objects[o].F_world_design : left[o].pose);
  for (const CellGrasp& g : grasps) {
    const runtime::GraspEvent& e = *g.event;
    if (e.at > at || e.object >= cell.objects.size()) continue;
    if (e.held) {
      carrier[e.object] = g.robot, offset[e.object] = e.pose;
    } else if (!e.other) {  // a hand-over's let-go: the other robot has it now
      carrier[e.object].reset(), m.objects[e.object] = e.pose;
    }
  }
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
