// A teach pendant over a workcell: the paper's WORKCELL module with TEACH.
// The robot stands in a runtime::Rig, with no program: the pendant drives
// its machine directly, so the world reacts to every move exactly as in a
// run (objects taken at the end of a closing move, carried, let go), the
// tool centre point and every object come from the rig's one
// forward-kinematics path, and on the simulated machine "reset cell" is a
// restore of the rig's first snapshot. With a device, the rig's machine is
// the Rhino controller: every jog moves the real robot, after the same soft-limit
// check.
//
// Every operation returns an Outcome and leaves its message in the state;
// nothing throws. Not thread-safe: a server calls it under one lock.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/workcell/cartesian_jog.h"
#include "model/workcell/model.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/run/rig.h"
#include "tools/teach/pendant_state.h"
#include "tools/teach/program_file.h"
#include "vm/io_lines.h"
#include "vm/machine.h"

namespace rs::rhino {
class RhinoMachine;
}

namespace rs::teach {

struct Outcome {
  bool ok = true;
  std::string message;
  bool badRequest = false;  ///< the request itself was malformed (a server answers 400)
};

class Pendant {
 public:
  /// On the simulated machine. `cell` must have a robot; its first one is
  /// taught, with `motors` (launch::cellTarget) as its motor table.
  Pendant(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, ProgramFile file);
  /// On a device (launch::openRhino): it moves with every jog.
  Pendant(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, ProgramFile file,
          std::unique_ptr<rhino::RhinoMachine> device, std::string deviceName);
  ~Pendant();
  Pendant(const Pendant&) = delete;
  Pendant& operator=(const Pendant&) = delete;

  /// Motor `motor` by `delta` counts; stops at its range's end.
  Outcome jog(std::size_t motor, std::int32_t delta);
  /// The tool by `amount` (length units, or degrees for a turn) along or
  /// about `axis` of the cell's frame (World) or the tool's own (Tool):
  /// through the inverse kinematics, on the configuration the arm stands
  /// in, the tool moving along its straight line as MOVES moves it, with
  /// the same path check; refused, with nothing moved, at the limit it
  /// meets (the state's `limit`: range, reach, singularity, step,
  /// collision). Repeated jogs start
  /// from the exact pose the last one reached, so they do not drift by the
  /// rounding to encoder counts.
  Outcome jogCartesian(workcell::JogFrame frame, std::string_view axis, double amount);
  /// Motor `motor` to `value` (refused outside its range).
  Outcome setMotor(std::size_t motor, std::int32_t value);
  /// Every motor to `targets`, at motor speed (refused outside a range).
  Outcome moveTo(std::span<const std::int32_t> targets);
  Outcome gripper(bool close);
  /// The current encoder values become point `name` (a new one).
  Outcome teach(std::string_view name);
  /// How re-teach writes a point that is written as a tool pose.
  enum class Reteach : std::uint8_t {
    Counts,  ///< the current encoder counts (a row of counts; the only way for a row of counts)
    Pose,    ///< a tool pose again: `AT` the tool centre point, the tool's orientation, GRIP if the row wrote one
  };
  /// Point `name` gets the current pose. A point written as a tool pose
  /// must say which way (`as`; a row of counts may be re-taught as a pose
  /// too); the pose is written only where the compiler resolves it to the
  /// current counts (else refused).
  Outcome reteach(std::string_view name, std::optional<Reteach> as = std::nullopt);
  Outcome remove(std::string_view name);
  Outcome rename(std::string_view from, std::string_view to);
  /// Every motor to point `name`, at motor speed (the state's motion has
  /// the move, time-stepped). A point written as a tool pose goes where
  /// the program's MOVEP takes the arm (point_target.h): resolved with the
  /// rows above it, the gripper left as it is when it writes no GRIP.
  Outcome goTo(std::string_view name);
  /// Input `line` (1..vm::kIoCount) flips (simulation: a switch on the pendant).
  Outcome toggleInput(int line);
  Outcome setOutput(int line, bool on);
  /// The cell's devices act for `seconds` of simulated time with the robot
  /// standing still (simulation only): a belt an output runs carries its
  /// parts, feeders feed, sensors and the inputs they drive switch. The
  /// state's motion has it, time-stepped as a move.
  Outcome runCell(double seconds);
  static constexpr double kMaxRunCell = 600;
  /// Motors home, objects back where the cell placed them, lines OFF.
  Outcome resetCell();
  /// The controller's encoder counts become the current pose (device only).
  Outcome readPosition();
  /// The program file read again (after someone edited it).
  Outcome reload();

  PendantState state() const;
  std::uint64_t revision() const { return revision_; }
  /// Where the cell placed each object (F_world_design), for pendantJson.
  std::vector<Eigen::Isometry3d> placements() const;
  /// The rig's cell: a feeder's slots are among its objects.
  const workcell::Workcell& cell() const { return *cell_; }
  /// The frame step of a move's motion: 40 ms, longer for moves of more than 10 s.
  static constexpr vm::Micros kFrameStep = 40'000;

 private:
  /// moveTo's checks and move; with `straight`, along the tool's straight line (vm::Machine::moveLine).
  Outcome move(std::span<const std::int32_t> targets, bool straight);
  Outcome done(Outcome o);
  Outcome refuse(std::string message, bool bad = false);
  Outcome refuseAt(workcell::JogLimit limit, std::string message);
  /// Where a Cartesian jog starts: the last jog's exact pose while the arm's motors are still where it put
  /// them, else the pose at the motors' counts.
  workcell::JogPose jogStart() const;
  Outcome reteachPose(std::size_t index);
  Outcome edit(const std::function<std::string(PointsText&)>& change, std::string message);
  std::optional<std::size_t> gripperMotor() const;
  std::vector<MotionFrame> frames() const;

  std::shared_ptr<const workcell::Workcell> cell_;
  std::vector<vm::MotorSpec> motors_;
  ProgramFile file_;
  std::unique_ptr<runtime::Rig> rig_;
  std::string device_;
  rhino::RhinoMachine* rhino_ = nullptr;      // the device, when it is a Rhino (owned by rig_)
  std::optional<runtime::RigSnapshot> start_;  // simulation: what reset cell restores
  vm::IoMask inputs_ = 0;                      // simulation: the pendant's input switches
  bool moved_ = false;                         // the last operation was a move
  vm::Micros moveStart_ = 0, moveEnd_ = 0;
  std::optional<workcell::CartesianJog> cartesian_;  // when the robot has a chain
  std::optional<workcell::JogPose> jogPose_;         // the last Cartesian jog's exact pose
  std::string message_, fault_, limit_;
  bool failed_ = false;
  std::uint64_t revision_ = 1;
  std::vector<MotionFrame> cellFrames_;  // the last operation ran the cell (runCell)
};

}  // namespace rs::teach
