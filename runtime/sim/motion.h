// How one motor moves from one encoder count to another: how long it takes
// and where it is at every moment. The one place the motion profile is
// written: SimMachine times its moves with it, RunLog::stateAt (and so the
// stills, the animation and any check along a move) replays them with it.
// Integer arithmetic only, so every machine gives the same answer; the
// animation page's script mirrors it with BigInt (runtime/render/page_script.cpp).
//
// Three profiles, by the motor's settings (vm::MotorSpec):
//  - constant speed (acceleration 0, the default and the paper's model):
//    the motor starts and stops at full speed v. Duration ceil(D / v).
//  - trapezoid (acceleration a > 0): accelerate at a to v, cruise, brake at
//    a. With ta = ceil(v / a) and, when D·a >= v², tc = ceil((D·a − v²) /
//    (v·a)): duration 2·ta + tc (the exact D/v + v/a, rounded up to the
//    microsecond at most twice). When the move is too short to reach v
//    (D·a < v²), a triangle: th = the least whole microseconds with
//    a·th² >= D, duration 2·th.
//  - fixed time (a gripper with an actuation time T): every move takes T,
//    at a constant rate, whatever its length (a pneumatic or force-
//    controlled gripper).
// Positions: the curve u(τ) is τ² while accelerating, 2·ta·τ − ta² while
// cruising and U − (T − τ)² while braking (U = u(T)), τ in whole
// microseconds; the motor has covered floor(D·u(τ) / U) units, rounded
// toward the start like the constant-speed profile. The curve lands on D
// exactly at the move's whole-microsecond end, and never runs faster than
// v nor accelerates harder than a (the roundings only make it slower).
#pragma once

#include <cstdint>

#include "vm/image.h"
#include "vm/machine.h"

namespace rs::runtime {

/// A motor's move: it left `from` at `start` and reaches `to` at `end`.
/// Motors that did not move have from == to and start == end. A lock-step
/// move (one small move of a straight line, every motor arriving together)
/// runs at a constant rate from start to end whatever the motor's profile.
struct MotorSegment {
  std::int32_t from = 0;
  std::int32_t to = 0;
  vm::Micros start = 0;
  vm::Micros end = 0;
  bool lockStep = false;
  /// Lock-step only: the motor takes each whole count as soon as it is
  /// begun (rounded toward `to`), not when it is finished.
  bool lead = false;
  bool operator==(const MotorSegment&) const = default;
};

/// Microseconds `motor` takes to cover `distance` (>= 0) encoder units; 0
/// for none. The motor's settings must pass vm::verify (a speed > 0, an
/// acceleration within its bounds).
vm::Micros travelTime(const vm::MotorSpec& motor, std::int64_t distance);

/// Encoder units covered `elapsed` microseconds into a move of `distance`
/// units (0 <= elapsed, the move takes travelTime(motor, distance)):
/// 0 at the start, `distance` from the end on, never decreasing.
std::int64_t coveredAt(const vm::MotorSpec& motor, std::int64_t distance, vm::Micros elapsed);

/// Microseconds a lock-step move of `distance` (>= 0) takes `motor` at its
/// full speed, without its acceleration: ceil(distance / speed).
vm::Micros lockStepTime(const vm::MotorSpec& motor, std::int64_t distance);

/// Encoder position at time `t` of `motor` running `segment`: `from` until
/// the start, `to` from the end, and in between from + or − coveredAt (a
/// lock-step segment: distance · elapsed / duration, rounded toward from,
/// or toward `to` when it leads).
/// What "where is the arm at time t" means everywhere.
std::int32_t positionAt(const MotorSegment& segment, const vm::MotorSpec& motor, vm::Micros t);

}  // namespace rs::runtime
