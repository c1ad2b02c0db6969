#include "runtime/cell/devices.h"

#include "runtime/cell/box_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rs::runtime {

namespace {

using workcell::Signal;

bool boxesOverlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  for (int k = 0; k < 3; ++k)
    if (a.min()[k] >= b.max()[k] - 1e-6 || b.min()[k] >= a.max()[k] - 1e-6) return false;
  return true;
}

}  // namespace

std::string signalText(const Signal& s) {
  switch (s.kind) {
    case Signal::Kind::On: return "ON";
    case Signal::Kind::Off: return "OFF";
    case Signal::Kind::Output: return fmt::format("{}{}OUT {}", s.robot, s.robot.empty() ? "" : ".", s.number);
    case Signal::Kind::Input: return fmt::format("{}{}IN {}", s.robot, s.robot.empty() ? "" : ".", s.number);
    case Signal::Kind::Sensor: return "sensor " + s.name;
  }
  return "";
}

Eigen::Isometry3d parkedPose() {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(0, -1e7, 0);
  return p;
}

std::shared_ptr<const workcell::Workcell> withFeederSlots(std::shared_ptr<const workcell::Workcell> cell) {
  if (!cell || cell->devices.feeders.empty()) return cell;
  auto out = std::make_shared<workcell::Workcell>(*cell);
  for (const workcell::Feeder& f : cell->devices.feeders) {
    const std::size_t n = f.count ? std::min<std::size_t>(kFeederSlots, static_cast<std::size_t>(*f.count)) : kFeederSlots;
    workcell::PlacedObject slot = cell->fedParts[f.part];
    slot.F_world_design = parkedPose();
    slot.kind = workcell::ObjectKind::Part;
    slot.inCell = false;  // until a part is fed into it
    for (std::size_t i = 0; i < n; ++i) out->objects.push_back(slot);
  }
  return out;
}

// A wire: on a change of its source, schedules its input's new value
// AFTER later (the tag is the source's value then); takes it in evaluate,
// writes the input in update.
class CellDevices::Wire final : public CellProcess {
 public:
  Wire(const workcell::Wire& wire, RobotIo& io) : wire_(wire), io_(io), source_(signalText(wire.source)) {}
  void wake(const CellEvent& event, Scheduler&) override { next_ = (event.tag != 0) != wire_.inverted, has_ = true; }
  bool update(Scheduler&) override {
    if (!std::exchange(has_, false)) return false;
    InputCause cause;
    cause.kind = InputCause::Kind::Wire;
    cause.input = wire_.input, cause.on = next_, cause.line = wire_.pos.line;
    cause.source = source_;
    cause.robot = wire_.robot;
    io_.setInput(wire_.input, next_, cause);
    return true;
  }
  std::string name() const override {
    return fmt::format("wire {} TO {}{}IN {} (line {})", signalText(wire_.source), wire_.robot,
                       wire_.robot.empty() ? "" : ".", wire_.input, wire_.pos.line);
  }
  const workcell::Wire& wire() const { return wire_; }
  std::uint32_t id = 0;

 private:
  const workcell::Wire& wire_;
  RobotIo& io_;
  std::string source_;  // signalText(wire_.source), said with every change
  bool next_ = false, has_ = false;
};

namespace {

std::vector<RobotIo*> firstRobotOnly(const workcell::Workcell& cell, RobotIo& io) {
  std::vector<RobotIo*> robots(std::max<std::size_t>(cell.robots.size(), 1), nullptr);
  robots[cell.drivenRobotIndex()] = &io;
  return robots;
}

}  // namespace

CellDevices::CellDevices(const workcell::Workcell& cell, World& world, RobotIo& io, Scheduler& clock)
    : CellDevices(cell, world, firstRobotOnly(cell, io), clock) {}

CellDevices::CellDevices(const workcell::Workcell& cell, World& world, std::vector<RobotIo*> robots, Scheduler& clock)
    : cell_(cell), world_(world), robots_(std::move(robots)), clock_(clock) {
  robots_.resize(std::max<std::size_t>(cell.robots.size(), 1), nullptr);
  const workcell::Devices& d = cell.devices;
  std::size_t slots = 0;
  for (const workcell::Feeder& f : d.feeders)
    slots += f.count ? std::min<std::size_t>(kFeederSlots, static_cast<std::size_t>(*f.count)) : kFeederSlots;
  firstSlot_ = cell.objects.size() - slots;
  for (std::size_t f = 0, at = firstSlot_; f < d.feeders.size(); ++f) {
    const std::size_t n = d.feeders[f].count
                              ? std::min<std::size_t>(kFeederSlots, static_cast<std::size_t>(*d.feeders[f].count))
                              : kFeederSlots;
    slotStart_.push_back(at), slotCount_.push_back(n);
    at += n;
  }
  for (const workcell::PlacedObject& o : cell.objects) designBoxes_.push_back(workcell::boundsOf(o.shape));
  const std::size_t n = cell.objects.size();
  Eigen::Isometry3d unknown;
  unknown.matrix().setConstant(std::numeric_limits<double>::quiet_NaN());  // equal to no pose: box() works it out
  boxPose_.assign(n, unknown);
  boxOf_.assign(n, Eigen::AlignedBox3d());
  boxSeen_.assign(n, 0);
  takenScratch_.assign(n, false);
  for (const workcell::Conveyor& conveyor : d.conveyors) {
    const workcell::PlacedObject& obj = cell.objects[conveyor.object];
    runFrom_.push_back(conveyor.run.kind == Signal::Kind::Output ? robotIo(conveyor.run.robot) : nullptr);
    if (!obj.belt) {
      belts_.emplace_back();
      continue;
    }
    Geometry g;
    g.belt = transformedBox(obj.belt->surface, obj.F_world_design);
    g.dir = (obj.F_world_design.linear() * obj.belt->direction).normalized();
    g.lateral = Eigen::Vector3d::UnitY().cross(g.dir);
    if (g.lateral.norm() < 1e-9) g.lateral = Eigen::Vector3d::UnitX();
    g.lateral.normalize();
    g.end = g.dir.dot(g.belt.center()) + g.dir.cwiseAbs().dot(g.belt.sizes() / 2);
    belts_.push_back(g);
    anyOpenEnd_ |= obj.belt->endOpen;
  }
  state_.number.assign(n, 0);
  for (std::size_t o = 0; o < firstSlot_; ++o) state_.number[o] = static_cast<std::uint32_t>(o + 1);
  state_.nextNumber = static_cast<std::uint32_t>(firstSlot_ + 1);
  listParts();
  state_.sensorOn.assign(d.sensors.size(), false);
  nextSensor_ = state_.sensorOn;
  state_.sensorCount.assign(d.sensors.size(), 0);
  state_.carried.assign(d.conveyors.size(), 0);
  state_.fed.assign(d.feeders.size(), 0);
  state_.taken.assign(d.sinks.size(), 0);
  state_.ridden.assign(n, 0);
  state_.nextDue.assign(d.feeders.size(), 0);
  state_.waiting.assign(d.feeders.size(), false);
  state_.whenLevel.assign(d.feeders.size(), false);
  state_.velocity.assign(n, Eigen::Vector3d::Zero());
  state_.travel.assign(n, 0);
  state_.rides.assign(n, {});
  for (std::size_t f = 0; f < d.feeders.size(); ++f)
    if (!d.feeders[f].everyUs) state_.nextDue[f] = INT64_MAX;
  id_ = clock.add(*this);
  for (const workcell::Wire& w : d.wires) {
    RobotIo* to = robotIo(w.robot);
    if (!to) continue;  // the input of a robot that runs nothing: nothing reads it
    wires_.push_back(std::make_unique<Wire>(w, *to));
    wires_.back()->id = clock.add(*wires_.back());
  }
  wakeNow();
  for (const auto& w : wires_)
    if (signal(w->wire().source) != w->wire().inverted)
      clock.schedule(clock.now() + w->wire().afterUs, w->id, signal(w->wire().source) ? 1 : 0);
  state_.revision = world.revision();
  sights_.resize(robots_.size());
  state_.moveUntil.assign(robots_.size(), 0);
  state_.sightWakeAt.assign(robots_.size(), -1);
  state_.heldWatched.assign(robots_.size(), false);
  heldBox_.assign(n, Eigen::AlignedBox3d());
  for (std::size_t r = 0; r < robots_.size() && !d.sensors.empty(); ++r) {
    if (!robots_[r]) continue;
    sights_[r] = std::make_unique<RobotSight>(cell, world, robots_[r]->motorCount(), r);
    if (!sights_[r]->matters()) sights_[r].reset();
  }
}

CellDevices::~CellDevices() = default;

void CellDevices::robotMoves(vm::Micros until, std::size_t robot) {
  if (robot >= state_.moveUntil.size() || until == state_.moveUntil[robot]) return;
  state_.moveUntil[robot] = until;
  // Its part stands in riders' way (or over their belt): the devices look
  // where it is at the move's end (docs/models.md, "Belts").
  if (state_.heldWatched[robot]) clock_.schedule(until, id_);
  if (robot >= sights_.size() || !sights_[robot]) return;
  sync();  // a take or a let-go just before the move: the sensors look again now
  watchRobot(clock_.now(), robot);
}

void CellDevices::watchRobot(vm::Micros now, std::size_t robot) {
  if (!sights_[robot] || state_.moveUntil[robot] <= now || !sights_[robot]->watches()) return;
  RobotIo* io = robots_[robot];
  const std::optional<vm::Micros> next = sights_[robot]->firstChange(
      now, state_.moveUntil[robot], [io](vm::Micros t, std::span<std::int32_t> out) { io->motorsAt(t, out); },
      [io, now](std::vector<std::uint64_t>& key) { return io->motionKey(now, key); });
  if (!next || *next == state_.sightWakeAt[robot]) return;
  state_.sightWakeAt[robot] = *next;
  clock_.schedule(*next, id_);
}

bool CellDevices::signal(const Signal& s) const {
  switch (s.kind) {
    case Signal::Kind::On: return true;
    case Signal::Kind::Off: return false;
    case Signal::Kind::Output: {
      const RobotIo* from = robotIo(s.robot);
      return from && from->output(s.number);
    }
    case Signal::Kind::Input: return false;  // another robot's input: issue 36
    case Signal::Kind::Sensor: return s.sensor < state_.sensorOn.size() && state_.sensorOn[s.sensor];
  }
  return false;
}

bool CellDevices::names(const std::string& label, std::size_t robot) const {
  return label.empty() ? robot == cell_.drivenRobotIndex() : cell_.robotLabeled(label) == robot;
}

RobotIo* CellDevices::robotIo(const std::string& label) const {
  const std::size_t r = label.empty() ? cell_.drivenRobotIndex() : cell_.robotLabeled(label);
  return r < robots_.size() ? robots_[r] : nullptr;
}

bool CellDevices::running(std::size_t c) const {
  // A robot's output, the usual RUN, by the robot found once (every wake asks).
  const Signal& run = cell_.devices.conveyors[c].run;
  if (run.kind == Signal::Kind::Output) return runFrom_[c] && runFrom_[c]->output(run.number);
  return signal(run);
}

std::uint64_t CellDevices::sightsRemembered() const {
  std::uint64_t n = 0;
  for (const auto& sight : sights_) n += sight ? sight->remembered() : 0;
  return n;
}

std::uint64_t CellDevices::sightsSearched() const {
  std::uint64_t n = 0;
  for (const auto& sight : sights_) n += sight ? sight->searched() : 0;
  return n;
}

const Eigen::AlignedBox3d& CellDevices::worldBox(std::size_t o) const {
  // Worked out at a revision after which the world set no resting pose of it: as it was.
  if (boxSeen_[o] != 0 && !world_.restMayDifferSince(o, boxSeen_[o] - 1)) return boxOf_[o];
  const Eigen::Isometry3d& pose = world_.restingPose(o);
  if (pose.matrix() != boxPose_[o].matrix()) boxPose_[o] = pose, boxOf_[o] = transformedBox(designBoxes_[o], pose);
  boxSeen_[o] = world_.revision() + 1;
  return boxOf_[o];
}

void CellDevices::listParts() {
  parts_.clear();
  for (std::size_t o = 0; o < state_.number.size(); ++o)
    if (present(o) && cell_.objects[o].kind == workcell::ObjectKind::Part) parts_.push_back(o);
}

void CellDevices::wakeNow() {
  if (state_.lookAt == clock_.now()) return;  // one waits for this instant already: it sees this change too
  state_.lookAt = clock_.now();
  clock_.schedule(clock_.now(), id_);
}

void CellDevices::place(std::size_t o, const Eigen::Vector3d& shift) {
  Eigen::Isometry3d p = world_.restingPose(o);
  p.translation() += shift;
  world_.place(o, p);
}

void CellDevices::restore(const State& s) {
  state_ = s;
  listParts();
  for (const auto& sight : sights_)
    if (sight) sight->forget();
  nextSensor_ = s.sensorOn;
  events_.clear();
  fault_.reset();
  emitted_.clear(), motions_.clear();
}

// A riding part's place is worked out from where its ride began and the
// whole microseconds it has ridden since, not summed a wake at a time: a
// part that rides the same way for the same time lands on the same bits,
// so a production loop repeats exactly and the sweep's memory answers its
// moves (runtime/sim/sweep_memo.h).
void CellDevices::moveTo(vm::Micros now) {
  const vm::Micros dtUs = now - state_.planAt;
  state_.planAt = now;
  if (dtUs <= 0) return;
  for (const std::size_t o : parts_) {
    const Eigen::Vector3d& w = state_.velocity[o];
    if (w.isZero() || state_.travel[o] <= 0) continue;
    if (world_.holder(o)) {
      state_.velocity[o].setZero();
      continue;
    }
    Ride& ride = state_.rides[o];
    Eigen::Isometry3d pose = world_.restingPose(o);
    // Another ride, or moved by something else since: the ride begins here.
    if (ride.velocity != w || pose.translation() != ride.at) {
      ride.from = pose.translation(), ride.velocity = w, ride.micros = 0, ride.done = 0;
    }
    const double speed = w.norm();
    const double dist = speed * static_cast<double>(dtUs) / 1e6;
    if (dist >= state_.travel[o]) {
      // To the end of its travel: the stop is where it rests now.
      ride.done += state_.travel[o];
      state_.travel[o] = 0;
    } else {
      ride.micros += dtUs;
      state_.travel[o] -= dist;
    }
    pose.translation() = ride.from + w / speed * (speed * static_cast<double>(ride.micros) / 1e6 + ride.done);
    ride.at = pose.translation();
    world_.place(o, pose);
  }
}

void CellDevices::commit() {
  moveTo(clock_.now());
  state_.revision = world_.revision();
}

void CellDevices::sync() {
  if (world_.revision() != state_.revision) wakeNow();
}

bool CellDevices::outputChanged(int output, std::size_t robot) {
  const workcell::Devices& d = cell_.devices;
  bool reads = false, feeds = false, wiredNow = false;
  const auto isOutput = [&](const Signal& s) {
    return s.kind == Signal::Kind::Output && s.number == output && names(s.robot, robot);
  };
  for (const workcell::Conveyor& c : d.conveyors) reads |= isOutput(c.run);
  for (const workcell::Feeder& f : d.feeders) feeds |= f.when && isOutput(*f.when);
  if (reads || feeds) wakeNow();
  for (const auto& w : wires_)
    if (isOutput(w->wire().source)) {
      clock_.schedule(clock_.now() + w->wire().afterUs, w->id, robots_[robot]->output(output) ? 1 : 0);
      wiredNow |= w->wire().afterUs == 0;
    }
  // A belt started or stopped moves nothing at this instant; a part fed may
  // be in a sensor's zone at once.
  return wiredNow || (feeds && !wires_.empty());
}

void CellDevices::feed(std::size_t f, vm::Micros now) {
  const workcell::Feeder& feeder = cell_.devices.feeders[f];
  const workcell::PlacedObject& part = cell_.fedParts[feeder.part];
  const Eigen::Vector3d shift = feeder.at - workcell::atCorner(part.shape);
  const Eigen::AlignedBox3d spot = workcell::boundsOf(part.shape).translated(shift);
  for (const std::size_t o : parts_) {
    if (world_.holder(o)) continue;
    if (boxesOverlap(partBox(o), spot)) {
      if (!state_.waiting[f]) events_.push_back({DeviceEvent::Kind::Waits, now, f, o, state_.number[o], feeder.at});
      state_.waiting[f] = true;
      return;
    }
  }
  std::size_t slot = slotStart_[f] + slotCount_[f];
  for (std::size_t s = slotStart_[f]; s < slotStart_[f] + slotCount_[f]; ++s)
    if (!present(s)) {
      slot = s;
      break;
    }
  if (slot == slotStart_[f] + slotCount_[f]) {
    if (!fault_)
      fault_ = fmt::format("feeder {} has {} parts in the cell at once, the most a feeder may have: take them away "
                           "(a SINK) or feed fewer (EVERY, COUNT)",
                           feeder.name, slotCount_[f]);
    state_.waiting[f] = false;
    return;
  }
  state_.waiting[f] = false;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = shift;
  world_.replace(slot, pose, true);
  worldBox(slot);
  state_.number[slot] = state_.nextNumber++;
  parts_.insert(std::lower_bound(parts_.begin(), parts_.end(), slot), slot);
  state_.ridden[slot] = 0;
  state_.velocity[slot].setZero(), state_.travel[slot] = 0;
  ++state_.fed[f];
  events_.push_back({DeviceEvent::Kind::Fed, now, f, slot, state_.number[slot], feeder.at});
}

void CellDevices::wake(const CellEvent& event, Scheduler& clock) {
  // A plan's wake (tag != 0) that a later plan replaced: that plan has
  // scheduled its own. Acting on it would keep the old plan's chain of
  // wakes going beside the new one's, one more chain with every change
  // (adept_hour's hour of production took 3.9 s of CPU instead of 0.03 s,
  // growing with the square of the run's length).
  if (event.tag != 0 && event.tag != static_cast<std::uint32_t>(state_.wakeTag)) return;
  const vm::Micros now = clock.now();
  if (event.tag == 0 && state_.lookAt == now) state_.lookAt = -1;
  if (event.tag != 0) state_.planWakeAt = -1;  // the plan's wake, now
  const workcell::Devices& d = cell_.devices;
  // A RESET put every object back where the workcell placed it: a fed
  // part has no place there, so it left the cell with its slot.
  for (std::size_t i = 0; i < parts_.size();) {
    const std::size_t o = parts_[i];
    if (o < firstSlot_ || world_.inCell(o)) {
      ++i;
      continue;
    }
    state_.number[o] = 0;
    state_.velocity[o].setZero(), state_.travel[o] = 0, state_.ridden[o] = 0;
    parts_.erase(parts_.begin() + static_cast<std::ptrdiff_t>(i));
  }
  moveTo(now);
  for (const std::size_t o : parts_) worldBox(o);  // partBox() holds from here on, kept so as the devices move parts
  // Parts past an open end run off and settle, as a let-go does.
  if (anyOpenEnd_) runOff(now);
  // Sinks take the parts whose centre is in their zone.
  for (std::size_t i = 0; i < parts_.size();) {
    const std::size_t o = parts_[i];
    bool gone = false;
    if (!world_.holder(o)) {
      const Eigen::Vector3d centre = partBox(o).center();
      for (std::size_t s = 0; s < d.sinks.size() && !gone; ++s) {
        if (!boxesTouch(Eigen::AlignedBox3d(centre, centre), d.sinks[s].zone)) continue;
        events_.push_back({DeviceEvent::Kind::Taken, now, s, o, state_.number[o], centre});
        ++state_.taken[s];
        state_.number[o] = 0;
        world_.replace(o, parkedPose(), false);
        state_.velocity[o].setZero(), state_.travel[o] = 0, state_.ridden[o] = 0;
        gone = true;
      }
    }
    if (gone) parts_.erase(parts_.begin() + static_cast<std::ptrdiff_t>(i));
    else ++i;
  }
  // Feeders: a part due, or waiting for its place.
  for (std::size_t f = 0; f < d.feeders.size(); ++f) {
    const workcell::Feeder& feeder = d.feeders[f];
    const bool full = feeder.count && state_.fed[f] >= static_cast<std::uint64_t>(*feeder.count);
    if (feeder.everyUs) {
      if (state_.nextDue[f] <= now) {
        bool due = false;
        while (state_.nextDue[f] <= now) state_.nextDue[f] += *feeder.everyUs, due = true;
        if (due && !full && !state_.waiting[f]) feed(f, now);
      } else if (state_.waiting[f] && !full) {
        feed(f, now);
      }
      if (full) state_.nextDue[f] = INT64_MAX, state_.waiting[f] = false;
    } else if (feeder.when) {
      const bool level = signal(*feeder.when);
      const bool rising = level && !state_.whenLevel[f];
      state_.whenLevel[f] = level;
      if (!full && (rising || state_.waiting[f])) feed(f, now);
    }
  }
  // The sensors as they are now: committed in update.
  for (std::size_t s = 0; s < d.sensors.size(); ++s) {
    const workcell::Sensor& sensor = d.sensors[s];
    bool sees = false;
    if (sensor.sees != workcell::Sensor::Sees::Robots)
      for (std::size_t i = 0; i < parts_.size() && !sees; ++i) {
        // A carried part shows itself through its robot's sight; one two
        // hands hold stays put where it rests.
        const std::size_t o = parts_[i];
        if (world_.holder(o) && !world_.shared(o)) continue;
        const Eigen::AlignedBox3d& b = partBox(o);
        sees = sensor.shape == workcell::Sensor::Shape::Beam ? beamTouches(sensor.a, sensor.b, b)
                                                             : boxesTouch(b, sensor.zone);
      }
    nextSensor_[s] = sees;
  }
  // What the robot and the part it carries show them, where they are now.
  for (std::size_t r = 0; r < sights_.size(); ++r) {
    if (!sights_[r] || !sights_[r]->watches()) continue;  // it shows them nothing now
    watchRobot(now, r);
    // Mid-move, the search just asked knows what it shows them now.
    if (state_.moveUntil[r] <= now || !sights_[r]->seenAsAsked(now, state_.moveUntil[r], robotSees_)) {
      motorsNow_.assign(robots_[r]->motorCount(), 0);
      robots_[r]->motorsAt(now, motorsNow_);
      sights_[r]->sees(motorsNow_, robotSees_);
    }
    for (std::size_t s = 0; s < d.sensors.size(); ++s) nextSensor_[s] = nextSensor_[s] || robotSees_[s];
  }
  plan(now);
  state_.revision = world_.revision();
  if (recordMotions_) recordChangedMotions(now);
}

bool CellDevices::update(Scheduler& clock) {
  const workcell::Devices& d = cell_.devices;
  bool changed = false;
  for (std::size_t s = 0; s < d.sensors.size(); ++s) {
    if (nextSensor_[s] == state_.sensorOn[s]) continue;
    changed = true;
    state_.sensorOn[s] = nextSensor_[s];
    if (nextSensor_[s]) ++state_.sensorCount[s];
    events_.push_back({nextSensor_[s] ? DeviceEvent::Kind::SensorOn : DeviceEvent::Kind::SensorOff, clock.now(), s});
    for (const auto& w : wires_)
      if (w->wire().source.kind == Signal::Kind::Sensor && w->wire().source.sensor == s)
        clock.schedule(clock.now() + w->wire().afterUs, w->id, nextSensor_[s] ? 1 : 0);
  }
  if (changed) {
    bool reads = false;
    for (const workcell::Conveyor& c : d.conveyors) reads |= c.run.kind == Signal::Kind::Sensor;
    for (const workcell::Feeder& f : d.feeders) reads |= f.when && f.when->kind == Signal::Kind::Sensor;
    if (reads) wakeNow();
  }
  return changed;
}
}  // namespace rs::runtime
