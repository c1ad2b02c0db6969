// The motion profiles (runtime/sim/motion.h): durations and positions of a
// trapezoid, a triangle and a fixed-time gripper worked out by hand from
// the kinematics of constant acceleration (s = a·t²/2, v = a·t), the
// constant-speed profile unchanged, SimMachine and RunLog::stateAt on the
// same curve, and the image's 1.1 motion section.
#include <catch2/catch.hpp>

#include <random>

#include "runtime/sim/motion.h"
#include "runtime/run/run_log.h"
#include "runtime/sim/sim_machine.h"
#include "tests/vm/image_support.h"
#include "vm/image_file.h"

namespace {

using rs::runtime::coveredAt;
using rs::runtime::travelTime;
using rs::testing::loadError;
using rs::vm::JointKind;
using rs::vm::Micros;
using rs::vm::MotorSpec;

constexpr Micros kSecond = 1'000'000;

MotorSpec motor(std::int32_t speed, std::int32_t acceleration, std::int32_t actuation = 0,
                JointKind kind = JointKind::Revolute) {
  MotorSpec m{'A', kind, 0.1, -100'000, 100'000, speed};
  m.acceleration = acceleration;
  m.actuation = actuation;
  return m;
}

}  // namespace

TEST_CASE("a trapezoid's duration and positions, by hand", "[motion]") {
  // v = 1000 u/s, a = 2000 u/s², D = 3000 u. Reaching speed takes
  // v/a = 0.5 s over v²/2a = 250 u; braking the same; the 2500 u between
  // at 1000 u/s take 2.5 s: 0.5 + 2.5 + 0.5 = 3.5 s (= D/v + v/a).
  const MotorSpec m = motor(1000, 2000);
  CHECK(travelTime(m, 3000) == 3'500'000);
  CHECK(coveredAt(m, 3000, 0) == 0);
  CHECK(coveredAt(m, 3000, 250'000) == 62);      // 2000·0.25²/2 = 62.5, rounded toward the start
  CHECK(coveredAt(m, 3000, 500'000) == 250);     // v²/2a
  CHECK(coveredAt(m, 3000, 1'000'000) == 750);   // 250 + 1000·0.5
  CHECK(coveredAt(m, 3000, 1'750'000) == 1500);  // the middle
  CHECK(coveredAt(m, 3000, 3'000'000) == 2750);  // 250 + 1000·2.5: braking starts
  CHECK(coveredAt(m, 3000, 3'250'000) == 2937);  // 3000 − 2000·0.25²/2 = 2937.5
  CHECK(coveredAt(m, 3000, 3'499'999) == 2999);
  CHECK(coveredAt(m, 3000, 3'500'000) == 3000);
  CHECK(coveredAt(m, 3000, 9 * kSecond) == 3000);
  // Exactly enough room to reach speed: no cruise, 2·v/a.
  CHECK(travelTime(m, 500) == 1'000'000);
}

TEST_CASE("a move too short to reach speed is a triangle, by hand", "[motion]") {
  // v = 2000 u/s, a = 2000 u/s², D = 500 u: reaching 2000 u/s would take
  // 2·v²/2a = 2000 u. Half the way, 250 u = a·t²/2, takes t = 0.5 s (peak
  // speed 1000 u/s); the whole move 1 s.
  const MotorSpec m = motor(2000, 2000);
  CHECK(travelTime(m, 500) == 1'000'000);
  CHECK(coveredAt(m, 500, 250'000) == 62);   // 62.5
  CHECK(coveredAt(m, 500, 500'000) == 250);
  CHECK(coveredAt(m, 500, 750'000) == 437);  // 500 − 62.5
  CHECK(coveredAt(m, 500, 1'000'000) == 500);
  // sqrt(D/a) not a whole number of microseconds: D = 200, a = 2000:
  // t = sqrt(0.1) s = 316227.77 µs, rounded up to 316228; 2·316228.
  CHECK(travelTime(m, 200) == 632'456);
}

TEST_CASE("constant speed is unchanged, and a gripper's actuation time is fixed", "[motion]") {
  const MotorSpec constant = motor(3, 0);
  CHECK(travelTime(constant, 7) == 2'333'334);  // ceil(7/3 s)
  CHECK(coveredAt(constant, 7, 999'999) == 2);
  CHECK(coveredAt(constant, 7, 1'000'000) == 3);
  // 0.3 s whatever the distance, at a constant rate over it.
  const MotorSpec gripper = motor(200, 0, 300'000, JointKind::Gripper);
  CHECK(travelTime(gripper, 100) == 300'000);
  CHECK(travelTime(gripper, 1) == 300'000);
  CHECK(travelTime(gripper, 0) == 0);
  CHECK(coveredAt(gripper, 100, 150'000) == 50);
  CHECK(coveredAt(gripper, 100, 299'999) == 99);
}

TEST_CASE("every profile starts at 0, ends on the distance, never goes back nor beats its speed", "[motion]") {
  std::mt19937 random(14);
  for (int trial = 0; trial < 300; ++trial) {
    const auto speed = std::uniform_int_distribution<std::int32_t>(1, 200'000)(random);
    const std::int32_t acceleration = std::uniform_int_distribution<std::int32_t>(speed / 999 + 1, 2'000'000)(random);
    const std::int64_t distance = std::uniform_int_distribution<std::int64_t>(1, 4'000'000'000)(random);
    const MotorSpec m = motor(speed, acceleration);
    const Micros total = travelTime(m, distance);
    // Never shorter than the exact profile, at most a few microseconds longer.
    const double v = speed, a = acceleration, d = static_cast<double>(distance);
    const double exact = (d * a >= v * v ? d / v + v / a : 2 * std::sqrt(d / a)) * 1e6;
    CHECK(static_cast<double>(total) >= exact - 1e-6 * exact);
    CHECK(static_cast<double>(total) <= exact + 3 + 1e-9 * exact);
    CHECK(coveredAt(m, distance, 0) == 0);
    CHECK(coveredAt(m, distance, total) == distance);
    std::int64_t before = 0;
    Micros then = 0;
    for (int k = 1; k <= 64; ++k) {
      const Micros t = total * k / 64;
      const std::int64_t now = coveredAt(m, distance, t);
      CHECK(now >= before);
      CHECK(static_cast<double>(now - before) <= v * static_cast<double>(t - then) / 1e6 + 1);
      before = now, then = t;
    }
  }
}

TEST_CASE("SimMachine times moves by the profile, and the log replays the same curve", "[motion]") {
  std::vector<MotorSpec> motors{motor(1000, 2000), motor(1000, 0)};
  motors[1].letter = 'B';
  rs::runtime::SimMachine machine(motors, {});
  rs::runtime::RunLogger logger(machine, nullptr);
  // Motor A: the 3.5 s trapezoid above. Motor B at constant speed: 1 s.
  REQUIRE(machine.moveTo(std::vector<std::int32_t>{3000, 1000}));
  CHECK(machine.now() == 3'500'000);
  CHECK(machine.positionAt(0, 250'000) == 62);
  CHECK(machine.positionAt(0, 3'250'000) == 2937);
  CHECK(machine.positionAt(1, 250'000) == 250);
  CHECK(machine.positionAt(1, 2 * kSecond) == 1000);
  rs::vm::Image image;
  image.motors = motors;
  image.code.push_back({rs::vm::Op::MoveTo, 0, 2, 0, 0});
  image.lines.push_back(1), image.columns.push_back(1);
  image.constants = {3000, 1000};
  rs::vm::Interpreter vm(image, machine);
  logger.afterStep(vm, 0);
  for (const Micros t : {Micros{0}, Micros{250'000}, Micros{1'750'000}, Micros{3'250'000}, Micros{4 * kSecond}}) {
    const rs::runtime::RunState s = rs::runtime::stateAt(logger.log(), t);
    CHECK(s.encoders[0] == machine.positionAt(0, t));
    CHECK(s.encoders[1] == machine.positionAt(1, t));
  }
}

TEST_CASE("an image keeps its 1.0 bytes unless a motor has an acceleration or an actuation time", "[motion]") {
  rs::vm::Image image;
  image.motors = {motor(400, 0), motor(200, 0, 0, JointKind::Gripper)};
  image.motors[1].letter = 'B';
  image.code.push_back({rs::vm::Op::End, 0, 0, 0, 0});
  image.lines.push_back(1), image.columns.push_back(1);
  const std::vector<std::uint8_t> plain = rs::vm::writeImage(image);
  CHECK(plain[10] == 0);  // minor version 0
  image.motors[0].acceleration = 4000;
  image.motors[1].actuation = 250'000;
  const std::vector<std::uint8_t> timed = rs::vm::writeImage(image);
  CHECK(timed[10] == 1);
  CHECK(timed.size() == plain.size() + 2 * 8);
  const rs::diag::Result<rs::vm::Image> back = rs::vm::loadImage({reinterpret_cast<const char*>(timed.data()), timed.size()});
  REQUIRE(back.ok());
  CHECK(back.value().motors == image.motors);
  // A 1.1 header over a motion section of zeros: refused, since a 1.0
  // image says the same.
  std::vector<std::uint8_t> zeros = plain;
  zeros.insert(zeros.end(), 2 * 8, 0);
  zeros[10] = 1;
  const auto le32 = [&](std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) zeros[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  const std::size_t payload = zeros.size() - rs::vm::kImageHeaderBytes;
  le32(12, static_cast<std::uint32_t>(payload));
  le32(16, rs::vm::crc32(zeros.data() + rs::vm::kImageHeaderBytes, payload));
  CHECK_THAT(loadError(rs::vm::loadImage({reinterpret_cast<const char*>(zeros.data()), zeros.size()})),
             Catch::Contains("a motion section in which no motor has an acceleration or an actuation time"));
  // The verifier refuses a motor that would take 1000 s to reach its speed
  // (which keeps motion.h's arithmetic in 128 bits), a negative
  // acceleration, and an actuation time on an arm joint.
  const auto refused = [&](const rs::vm::Image& im) {
    const std::vector<std::uint8_t> b = rs::vm::writeImage(im);
    return loadError(rs::vm::loadImage({reinterpret_cast<const char*>(b.data()), b.size()}));
  };
  rs::vm::Image slow = image;
  slow.motors[0].speed = 5000, slow.motors[0].acceleration = 5;
  CHECK_THAT(refused(slow), Catch::Contains("takes 1000 s or more to reach its speed"));
  slow.motors[0].acceleration = 6;
  CHECK(refused(slow).empty());
  slow.motors[0].acceleration = -1;
  CHECK_THAT(refused(slow), Catch::Contains("acceleration -1 is outside"));
  image.motors[0].actuation = 1000;
  const std::vector<std::uint8_t> bad = rs::vm::writeImage(image);
  CHECK_THAT(loadError(rs::vm::loadImage({reinterpret_cast<const char*>(bad.data()), bad.size()})),
             Catch::Contains("has an actuation time but is not a gripper"));
}

TEST_CASE("a lock-step move: every motor at a constant rate, all arriving together, leaders a count ahead",
          "[motion][straight]") {
  // Motor 1: 10 counts at 1000/s is 10 ms; motor 2: 3 counts at 100/s is
  // 30 ms: the move takes 30 ms, and motor 1 is slowed to keep pace. At
  // 4 ms motor 1 has done 10 * 4 / 30 = 1.33 counts and motor 2 0.4: rounded
  // toward where they started, 1 and 0; a leader rounds toward where it
  // goes, 2 and 1. At 0 both are where they started, at 30 ms where they go.
  const MotorSpec fast{'A', JointKind::Revolute, 1.0, -100, 100, 1000};
  const MotorSpec slow{'B', JointKind::Revolute, 1.0, -100, 100, 100, 5000};  // its acceleration does not apply
  CHECK(rs::runtime::lockStepTime(fast, 10) == 10'000);
  CHECK(rs::runtime::lockStepTime(slow, 3) == 30'000);
  for (const std::uint32_t lead : {0u, 3u}) {
    rs::runtime::SimMachine sim({fast, slow}, {});
    REQUIRE(sim.moveLockStep(std::vector<std::int32_t>{10, -3}, lead));
    CHECK(sim.now() == 30'000);
    CHECK(sim.positionAt(0, 0) == 0);
    CHECK(sim.positionAt(1, 0) == 0);
    CHECK(sim.positionAt(0, 4'000) == (lead ? 2 : 1));
    CHECK(sim.positionAt(1, 4'000) == (lead ? -1 : 0));
    CHECK(sim.positionAt(0, 29'999) == (lead ? 10 : 9));
    CHECK(sim.positionAt(0, 30'000) == 10);
    CHECK(sim.positionAt(1, 30'000) == -3);
    CHECK(sim.segment(0).end == sim.segment(1).end);
  }
}

TEST_CASE("counts covered between two times add up the knots of a line that turns back", "[motion][straight]") {
  // One motor at 1000 counts a second: the line's first knot goes 0 -> 10
  // in 10 ms, the second back to 0 in the next 10 ms. Between 0 and 20 ms
  // it covers 20 counts though it ends where it began; from 5 to 15 ms,
  // 5 out and 5 back; within the first knot, what it went.
  const MotorSpec fast{'A', JointKind::Revolute, 1.0, -100, 100, 1000};
  rs::runtime::SimMachine sim({fast}, {});
  sim.beginPath();
  REQUIRE(sim.moveLockStep(std::vector<std::int32_t>{10}, 0));
  REQUIRE(sim.moveLockStep(std::vector<std::int32_t>{0}, 0));
  CHECK(sim.now() == 20'000);
  CHECK(sim.coveredBetween(0, 0, 20'000) == 20);
  CHECK(sim.coveredBetween(0, 5'000, 15'000) == 10);
  CHECK(sim.coveredBetween(0, 2'000, 7'000) == 5);
  CHECK(sim.coveredBetween(0, 20'000, 30'000) == 0);
  // A plain move: the counts between its positions.
  REQUIRE(sim.moveTo(std::vector<std::int32_t>{-50}));
  CHECK(sim.coveredBetween(0, 20'000, 70'000) == 50);
}
