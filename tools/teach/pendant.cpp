#include "tools/teach/pendant.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/ascii.h"
#include "base/number_text.h"
#include "base/seconds.h"
#include "tools/teach/point_target.h"
#include "vm/io_lines.h"
#include "vm/motor_range.h"

namespace rs::teach {

namespace {

// Whether `text` (a row, its comment aside) has the word `word`, any case.
bool hasWord(std::string_view text, std::string_view word) {
  text = text.substr(0, text.find(';'));
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\t') ++end;
    if (end > i && base::sameName(text.substr(i, end - i), word)) return true;
    i = end;
  }
  return false;
}

std::string valuesText(std::span<const std::int32_t> v) {
  std::string s;
  for (std::int32_t x : v) s += (s.empty() ? "" : " ") + std::to_string(x);
  return s;
}

}  // namespace

Pendant::Pendant(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, ProgramFile file)
    : cell_(std::move(cell)), motors_(std::move(motors)), file_(std::move(file)) {
  rig_ = std::make_unique<runtime::Rig>(cell_, motors_, stimuli::Stimuli{}, runtime::CollisionMode::Error);
  // The rig's cell from now on: with its feeders' slots among the objects
  // (it lives as long as the rig, and shares the cell's ownership).
  cell_ = std::shared_ptr<const workcell::Workcell>(cell_, rig_->cell());
  start_ = rig_->snapshot();
  if (cell_->drivenRobot()->robot.chain) cartesian_.emplace(*cell_->drivenRobot());
  message_ = fmt::format("teaching {} on {}", file_.path(), cell_->name);
}

Pendant::Pendant(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, ProgramFile file,
                 std::unique_ptr<rhino::RhinoMachine> device, std::string deviceName)
    : cell_(std::move(cell)), motors_(std::move(motors)), file_(std::move(file)), device_(std::move(deviceName)) {
  rhino_ = device.get();
  rig_ = std::make_unique<runtime::Rig>(cell_, std::move(device));
  if (cell_->drivenRobot()->robot.chain) cartesian_.emplace(*cell_->drivenRobot());
  message_ = fmt::format("teaching {} on {} with the robot on {}", file_.path(), cell_->name, device_);
}

Pendant::~Pendant() = default;

Outcome Pendant::done(Outcome o) {
  cellFrames_.clear();
  if (o.ok) limit_.clear();
  message_ = o.message;
  failed_ = !o.ok;
  ++revision_;
  return o;
}

Outcome Pendant::refuse(std::string message, bool bad) {
  moved_ = false;
  limit_.clear();
  return done({false, std::move(message), bad});
}

Outcome Pendant::refuseAt(workcell::JogLimit limit, std::string message) {
  moved_ = false;
  limit_ = workcell::jogLimitName(limit);
  return done({false, std::move(message)});
}

// The one path that moves the robot: the fault check, the soft limits
// (each motor's encoder range) before anything moves or is sent, then the
// rig's machine (a joint move, or with `straight` the tool along its
// straight line, as MOVES runs it), so the world reacts as in a run. On the simulated machine
// the rig checks the move for collisions (docs/models.md); a move that
// collides is refused and undone (the rig restored to before it), so the
// robot never stands in a collision (docs/teach.md).
Outcome Pendant::moveTo(std::span<const std::int32_t> targets) { return move(targets, false); }

Outcome Pendant::move(std::span<const std::int32_t> targets, bool straight) {
  if (!fault_.empty()) return refuse("the device failed, nothing is sent: " + fault_);
  if (targets.size() != motors_.size())
    return refuse(fmt::format("{} values for {} motors", targets.size(), motors_.size()), true);
  if (const auto i = vm::firstOutOfRange(motors_, targets))
    return refuseAt(workcell::JogLimit::Range, fmt::format("motor {}: {} is {}: nothing moved", motors_[*i].letter,
                                                           targets[*i], vm::outsideRange(motors_[*i])));
  const vm::Micros start = rig_->clock();
  const runtime::CollisionWatch* watch = rig_->collisionWatch();
  std::optional<runtime::RigSnapshot> before;
  if (watch) before = rig_->snapshot();
  const std::size_t seen = watch ? watch->events().size() : 0;
  const vm::Status status = straight ? rig_->machine().moveLine(targets) : rig_->machine().moveTo(targets);
  if (watch && watch->events().size() > seen) {
    const runtime::CollisionEvent hit = watch->events()[seen];
    rig_->restore(*before);
    return refuseAt(workcell::JogLimit::Collision,
                    fmt::format("refused: the move to {} collides {} s into it: {}; nothing moved{}", valuesText(targets),
                                base::formatSeconds(hit.at - start), watch->describe(hit),
                                watch->hint(hit).empty() ? std::string() : " (" + watch->hint(hit) + ")"));
  }
  if (!status) {
    moved_ = false;
    if (!device_.empty()) fault_ = status.message;
    return done({false, status.message});
  }
  moved_ = true;
  moveStart_ = start;
  moveEnd_ = rig_->clock();
  if (rhino_) {
    // The controller's switches, read after every move: the page shows them as they are now.
    rig_->machine().input(1);
    if (!rhino_->failure().empty()) {
      fault_ = rhino_->failure();
      return done({false, fault_});
    }
  }
  return done({true, fmt::format("moved to {}", valuesText(rig_->motors()))});
}

Outcome Pendant::jog(std::size_t motor, std::int32_t delta) {
  if (motor >= motors_.size()) return refuse(fmt::format("there is no motor {}", motor + 1), true);
  const vm::MotorSpec& m = motors_[motor];
  std::vector<std::int32_t> targets(rig_->motors().begin(), rig_->motors().end());
  const std::int64_t wanted = std::int64_t{targets[motor]} + delta;
  const std::int32_t to = static_cast<std::int32_t>(std::clamp<std::int64_t>(wanted, m.min, m.max));
  if (to == targets[motor] && delta != 0)
    return refuseAt(workcell::JogLimit::Range, fmt::format("motor {} is at the end of its range ({})", m.letter, to));
  targets[motor] = to;
  Outcome o = moveTo(targets);
  if (o.ok && to != wanted) message_ = o.message = fmt::format("motor {} stopped at the end of its range, {}", m.letter, to);
  return o;
}

workcell::JogPose Pendant::jogStart() const {
  const std::span<const std::int32_t> now = rig_->motors();
  bool still = jogPose_.has_value() && jogPose_->encoders.size() == now.size();
  for (std::size_t i = 0; still && i < now.size(); ++i)
    if (motors_[i].kind != vm::JointKind::Gripper && jogPose_->encoders[i] != now[i]) still = false;
  workcell::JogPose from = still ? *jogPose_ : cartesian_->poseAt(now);
  from.encoders.assign(now.begin(), now.end());  // the gripper stays as it is now
  return from;
}

Outcome Pendant::jogCartesian(workcell::JogFrame frame, std::string_view axis, double amount) {
  if (!cartesian_)
    return refuse(fmt::format("robot {} has no kinematic chain: only joint jogs", cell_->drivenRobot()->robot.name));
  if (!std::isfinite(amount)) return refuse("a jog's amount is a finite number", true);
  const workcell::JogPose from = jogStart();
  const workcell::JogResult r = cartesian_->jog(from, frame, axis, amount);
  const std::string what = fmt::format("{} jog {} {}{} {}", workcell::jogFrameName(frame), axis, amount < 0 ? "" : "+",
                                       base::formatNumber(amount), r.rotation ? "degrees" : "length units");
  if (!r.ok()) {
    if (*r.limit == workcell::JogLimit::Axis) return refuse(r.message, true);
    return refuseAt(*r.limit, fmt::format("{} refused ({}): {}; nothing moved", what, workcell::jogLimitName(*r.limit),
                                          r.message));
  }
  // Along the line the jog planned, as MOVES runs it: a block lifted off
  // the pallet it stands on goes straight up, where a joint move swings it
  // through the pallet.
  Outcome o = move(r.pose.encoders, true);
  if (!o.ok) {
    if (!limit_.empty()) {
      // "world jog X +10 length units refused (collision): the move to ...", not "...: refused: the move to ...".
      std::string_view why = o.message;
      if (why.starts_with("refused: ")) why.remove_prefix(std::string_view("refused: ").size());
      message_ = o.message = fmt::format("{} refused ({}): {}", what, limit_, why);
    }
    return o;
  }
  jogPose_ = r.pose;
  const Eigen::Vector3d p = r.pose.tool.translation();
  message_ = o.message = fmt::format("{}: tool centre point at {} {} {}", what, base::formatNumber(p.x()),
                                     base::formatNumber(p.y()), base::formatNumber(p.z()));
  return o;
}

Outcome Pendant::setMotor(std::size_t motor, std::int32_t value) {
  if (motor >= motors_.size()) return refuse(fmt::format("there is no motor {}", motor + 1), true);
  std::vector<std::int32_t> targets(rig_->motors().begin(), rig_->motors().end());
  targets[motor] = value;
  return moveTo(targets);
}

std::optional<std::size_t> Pendant::gripperMotor() const {
  for (std::size_t i = 0; i < motors_.size(); ++i)
    if (motors_[i].kind == vm::JointKind::Gripper) return i;
  return std::nullopt;
}

Outcome Pendant::gripper(bool close) {
  const std::optional<std::size_t> g = gripperMotor();
  if (!g) return refuse(fmt::format("robot {} has no gripper", cell_->drivenRobot()->robot.name));
  Outcome o = setMotor(*g, close ? motors_[*g].max : motors_[*g].min);
  if (o.ok) {
    const std::optional<std::size_t> held = rig_->world() ? rig_->world()->held() : std::nullopt;
    message_ = o.message = close ? (held ? fmt::format("gripper closed: holds {}", cell_->objects[*held].shape.name)
                                         : std::string("gripper closed: holds nothing"))
                                 : std::string("gripper open");
  }
  return o;
}

Outcome Pendant::edit(const std::function<std::string(PointsText&)>& change, std::string message) {
  moved_ = false;
  if (std::string why = file_.change(change); !why.empty()) return done({false, std::move(why)});
  return done({true, std::move(message)});
}

Outcome Pendant::teach(std::string_view name) {
  const std::vector<std::int32_t> now(rig_->motors().begin(), rig_->motors().end());
  return edit([&](PointsText& p) { return p.add(name, now); },
              fmt::format("taught {} = {} (written to {})", name, valuesText(now), file_.path()));
}

Outcome Pendant::reteach(std::string_view name, std::optional<Reteach> as) {
  const std::vector<std::int32_t> now(rig_->motors().begin(), rig_->motors().end());
  const std::optional<std::size_t> p = file_.points().find(name);
  if (p && file_.points().points()[*p].pose && !as)
    return refuse(fmt::format("point {} is written as a tool pose: re-teach it as a pose or as counts", name), true);
  if (p && as == Reteach::Pose) return reteachPose(*p);
  return edit([&](PointsText& pts) { return pts.replace(name, now); },
              fmt::format("re-taught {} = {} (written to {})", name, valuesText(now), file_.path()));
}

// The tool's pose now, as a point's words: where the tool centre point is
// (world coordinates), which way the tool points and its fingers close
// (what the arm can turn: nothing for a cartesian one), the gripper's
// count where the row wrote one (a row of counts, which sets the gripper,
// always gets it). Written only if the compiler resolves it,
// with the rows above it, to the counts the arm stands at (±1 for the
// rounding of the words): else it would not be the pose taught.
Outcome Pendant::reteachPose(std::size_t index) {
  const PointRow& row = file_.points().points()[index];
  const std::string name = row.name;
  if (!cartesian_)
    return refuse(fmt::format("robot {} has no kinematic chain: {} can be re-taught as counts only",
                              cell_->robots.front().robot.name, name));
  const std::vector<std::int32_t> now(rig_->motors().begin(), rig_->motors().end());
  const workcell::JogPose pose = jogStart();  // the exact pose after a jog
  const auto words = [](const Eigen::Vector3d& v, int digits) {
    return fmt::format("{} {} {}", base::formatNumber(v.x(), digits), base::formatNumber(v.y(), digits),
                       base::formatNumber(v.z(), digits));
  };
  std::string text = "AT " + words(pose.tool.translation(), 4);
  if (!cartesian_->axes(pose, workcell::JogFrame::World).back().rotation) {
    // A cartesian arm's tool never turns: its orientation is not written.
  } else {
    text += " APPROACH " + words(pose.tool.linear().col(2), 6) + " NORMAL " + words(pose.tool.linear().col(0), 6);
  }
  const std::string_view rowText = file_.points().rowText(index);
  if (const std::optional<std::size_t> g = gripperMotor(); g && (!row.pose || hasWord(rowText, "GRIP")))
    text += fmt::format(" GRIP {}", now[*g]);
  // What the compiler makes of it, before it is written.
  PointsText trial = file_.points();
  trial.replacePose(name, text);
  const PointTarget t = pointTarget(trial, index, *cell_);
  if (!t.ok()) return refuse(fmt::format("{} as a pose does not resolve: {}; re-teach it as counts", name, t.error));
  for (std::size_t m = 0; m < now.size(); ++m) {
    if (t.keepsGripper && motors_[m].kind == vm::JointKind::Gripper) continue;
    if (std::abs(std::int64_t{t.values[m]} - now[m]) > 1)
      return refuse(fmt::format("{} as a pose ({}) resolves to {}, not to the counts the arm stands at, {} (another "
                                "of the arm's solutions): re-teach it as counts",
                                name, text, valuesText(t.values), valuesText(now)));
  }
  return edit([&](PointsText& pts) { return pts.replacePose(name, text); },
              fmt::format("re-taught {} {} (written to {})", name, text, file_.path()));
}

Outcome Pendant::remove(std::string_view name) {
  return edit([&](PointsText& p) { return p.remove(name); },
              fmt::format("deleted {} (written to {})", name, file_.path()));
}

Outcome Pendant::rename(std::string_view from, std::string_view to) {
  return edit([&](PointsText& p) { return p.rename(from, to); },
              fmt::format("renamed {} to {} (written to {})", from, to, file_.path()));
}

Outcome Pendant::goTo(std::string_view name) {
  const PointsText& pts = file_.points();
  const std::optional<std::size_t> p = pts.find(name);
  if (!p) return refuse(fmt::format("there is no point {}", name));
  const PointRow& row = pts.points()[*p];
  if (!row.pose && (!row.readable || row.values.size() != motors_.size()))
    return refuse(fmt::format("point {} (line {}) does not have {} whole numbers: fix it in an editor", row.name,
                              row.line + 1, motors_.size()));
  // A pose: where MOVEP goes, the gripper as it is when the pose writes no GRIP.
  const PointTarget target = pointTarget(pts, *p, *cell_);
  if (!target.ok()) return refuse(fmt::format("cannot go to {}: {}; nothing moved", row.name, target.error));
  std::vector<std::int32_t> values = target.values;
  if (target.keepsGripper)
    if (const std::optional<std::size_t> g = gripperMotor()) values[*g] = rig_->motors()[*g];
  Outcome o = moveTo(values);
  if (o.ok) message_ = o.message = fmt::format("went to {} ({:.3f} s)", row.name, (moveEnd_ - moveStart_) / 1e6);
  return o;
}

Outcome Pendant::toggleInput(int line) {
  if (!vm::isIoLine(line)) return refuse(fmt::format("inputs are 1..{}, not {}", vm::kIoCount, line), true);
  if (!device_.empty()) return refuse("with a device, the inputs are the controller's: they cannot be switched here");
  moved_ = false;
  inputs_ = vm::withLine(inputs_, line, !vm::lineIsOn(inputs_, line));
  return done({true, fmt::format("input {} {}", line, vm::lineIsOn(inputs_, line) ? "ON" : "OFF")});
}

Outcome Pendant::setOutput(int line, bool on) {
  if (!vm::isIoLine(line)) return refuse(fmt::format("outputs are 1..{}, not {}", vm::kIoCount, line), true);
  if (!fault_.empty()) return refuse("the device failed, nothing is sent: " + fault_);
  moved_ = false;
  const vm::Status st = rig_->machine().setOutput(line, on);
  if (!st && !st.notYet()) {  // NotYet: a wire acts at this instant, when the cell next runs
    if (!device_.empty()) fault_ = st.message;
    return done({false, st.message});
  }
  return done({true, fmt::format("output {} {}", line, on ? "ON" : "OFF")});
}

Outcome Pendant::runCell(double seconds) {
  if (!rig_->sim()) return refuse("with a device there is no simulated cell to run");
  if (!std::isfinite(seconds) || seconds <= 0 || seconds > kMaxRunCell)
    return refuse(fmt::format("run the cell for more than 0 and at most {} s, not {}", kMaxRunCell, seconds), true);
  moved_ = false;
  const vm::Micros start = rig_->clock(), length = static_cast<vm::Micros>(std::llround(seconds * 1e6));
  const vm::Micros step = std::max(kFrameStep, (length + 249) / 250);
  std::vector<MotionFrame> frames;
  const std::vector<std::int32_t> encoders(rig_->motors().begin(), rig_->motors().end());
  for (vm::Micros t = 0;; t = std::min(t + step, length)) {
    if (const vm::Status st = rig_->advanceCell(start + t); !st) return done({false, st.message});
    rig_->settleDevices();
    MotionFrame f;
    f.at = t, f.encoders = encoders;
    for (const runtime::ObjectView& o : rig_->objects()) f.objects.push_back(o.pose);
    frames.push_back(std::move(f));
    if (t == length) break;
  }
  const Outcome o = done({true, fmt::format("the cell ran for {} s", base::formatSeconds(length))});
  cellFrames_ = std::move(frames);
  return o;
}

Outcome Pendant::resetCell() {
  if (start_) {
    rig_->restore(*start_);
    inputs_ = 0;
    moved_ = false;
    return done({true, "cell reset: motors at 0, every object where the cell placed it, lines OFF"});
  }
  if (!fault_.empty()) return refuse("the device failed, nothing is sent: " + fault_);
  const vm::Micros start = rig_->clock();
  const vm::Status st = rig_->machine().reset();
  if (!st) {
    fault_ = st.message;
    moved_ = false;
    return done({false, st.message});
  }
  moved_ = true;
  moveStart_ = start;
  moveEnd_ = rig_->clock();
  return done({true, "cell reset: the robot back where teach found it, every object where the cell placed it"});
}

Outcome Pendant::readPosition() {
  moved_ = false;
  if (!rhino_) return refuse("read position needs a device (--device): in simulation the pose is what the pendant set");
  if (!fault_.empty()) return refuse("the device failed, nothing is sent: " + fault_);
  const vm::Status st = rhino_->readPositions();
  if (!st) {
    fault_ = st.message;
    return done({false, st.message});
  }
  if (!rhino_->reportsPositions())
    return done({true, fmt::format("a Mark III cannot report its encoders: the counts are those tracked since teach "
                                   "started, {}",
                                   valuesText(rig_->motors()))});
  return done({true, fmt::format("read from the controller: {}", valuesText(rig_->motors()))});
}

Outcome Pendant::reload() {
  moved_ = false;
  if (std::string why = file_.reload(); !why.empty()) return done({false, std::move(why)});
  return done({true, fmt::format("{} read again: {} points", file_.path(), file_.points().points().size())});
}

std::vector<Eigen::Isometry3d> Pendant::placements() const {
  std::vector<Eigen::Isometry3d> p;
  for (const workcell::PlacedObject& o : cell_->objects) p.push_back(o.F_world_design);
  return p;
}

// The last move, every kFrameStep (at most 250 frames), then its end: the
// rig knows where each motor was at any time of its last move
// (Rig::motorsAt) and where each object was (Rig::objects).
std::vector<MotionFrame> Pendant::frames() const {
  if (!cellFrames_.empty()) return cellFrames_;
  std::vector<MotionFrame> out;
  if (!moved_ || !rig_->sim() || moveEnd_ <= moveStart_) return out;
  const vm::Micros length = moveEnd_ - moveStart_;
  const vm::Micros step = std::max(kFrameStep, (length + 249) / 250);
  for (vm::Micros t = 0;; t = std::min(t + step, length)) {
    MotionFrame f;
    f.at = t;
    f.encoders = rig_->motorsAt(moveStart_ + t);
    for (const runtime::ObjectView& o : rig_->objects(moveStart_ + t)) f.objects.push_back(o.pose);
    out.push_back(std::move(f));
    if (t == length) break;
  }
  return out;
}

PendantState Pendant::state() const {
  PendantState s;
  s.revision = revision_;
  s.program = file_.path();
  s.cell = cell_->name;
  s.device = device_;
  s.motors = motors_;
  s.encoders.assign(rig_->motors().begin(), rig_->motors().end());
  s.tcp = rig_->tcp();
  if (cartesian_) {
    const workcell::JogPose pose = jogStart();
    const Eigen::Matrix3d R = pose.tool.linear();
    s.approach = std::array<double, 3>{R(0, 2), R(1, 2), R(2, 2)};
    s.normal = std::array<double, 3>{R(0, 0), R(1, 0), R(2, 0)};
    for (const workcell::JogFrame frame : {workcell::JogFrame::World, workcell::JogFrame::Tool})
      for (const workcell::JogAxis& a : cartesian_->axes(pose, frame))
        (frame == workcell::JogFrame::World ? s.worldAxes : s.toolAxes).push_back({a.name, a.rotation, a.help});
  }
  s.gripper = gripperState(motors_, s.encoders);
  // In simulation, the pendant's switches and what the cell's wires drive.
  s.inputs = device_.empty() ? static_cast<vm::IoMask>(inputs_ | rig_->machine().inputs()) : rig_->machine().inputs();
  s.outputs = rig_->machine().outputs();
  for (const runtime::ObjectView& o : rig_->objects())
    s.objects.push_back({std::string(o.name), o.pose, o.held, o.moved, o.present});
  addDeviceStates(*cell_, rig_->devices(), s);
  for (const PointRow& p : file_.points().points()) s.points.push_back({p.name, p.values, p.line + 1, p.readable, p.pose});
  s.clock = rig_->clock();
  s.motion = frames();
  s.message = message_;
  s.failed = failed_;
  s.limit = limit_;
  s.fault = fault_;
  s.fileHash = file_.hash();
  return s;
}

}  // namespace rs::teach
