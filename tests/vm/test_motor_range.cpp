// vm/motor_range.h: the one range check of a motor target, and its words,
// which the compiler, the interpreter, the machines and the pendant say.
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "vm/motor_range.h"
#include "vm/opcodes.h"

namespace {

constexpr rs::vm::MotorSpec motor(char letter, std::int32_t min, std::int32_t max) {
  rs::vm::MotorSpec m;
  m.letter = letter, m.min = min, m.max = max;
  return m;
}

}  // namespace

TEST_CASE("inRange includes both ends and holds 64-bit sums", "[vm][motor-range]") {
  const rs::vm::MotorSpec e = motor('E', -1000, 1000);
  CHECK(rs::vm::inRange(e, -1000));
  CHECK(rs::vm::inRange(e, 1000));
  CHECK(rs::vm::inRange(e, 0));
  CHECK_FALSE(rs::vm::inRange(e, -1001));
  CHECK_FALSE(rs::vm::inRange(e, 1001));
  // A relative move's sum past 32 bits is out of range, not wrapped into it.
  const rs::vm::MotorSpec wide =
      motor('B', std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max());
  CHECK_FALSE(rs::vm::inRange(wide, std::int64_t{std::numeric_limits<std::int32_t>::max()} + 1));
  CHECK_FALSE(rs::vm::inRange(wide, std::int64_t{std::numeric_limits<std::int32_t>::min()} - 1));
  static_assert(rs::vm::inRange(motor('A', 0, 120), 120) && !rs::vm::inRange(motor('A', 0, 120), 121));
}

TEST_CASE("the range words are the same everywhere", "[vm][motor-range]") {
  CHECK(rs::vm::outsideRange(motor('A', 0, 120)) == "outside its range 0..120");
  CHECK(rs::vm::targetOutsideRange(motor('C', -350, 350), -351) ==
        "motor C target -351 is outside its range -350..350");
  CHECK(rs::vm::targetOutsideRange(motor('E', -1000, 1000), 5'000'000'000) ==
        "motor E target 5000000000 is outside its range -1000..1000");
}

TEST_CASE("firstOutOfRange names the first motor out of range, in motor order", "[vm][motor-range]") {
  const std::vector<rs::vm::MotorSpec> motors{motor('E', -1000, 1000), motor('D', -550, 550), motor('A', 0, 120)};
  CHECK_FALSE(rs::vm::firstOutOfRange(motors, std::vector<std::int32_t>{1000, -550, 0}).has_value());
  CHECK(rs::vm::firstOutOfRange(motors, std::vector<std::int32_t>{0, 551, 121}) == std::optional<std::size_t>{1});
  CHECK(rs::vm::firstOutOfRange(motors, std::vector<std::int32_t>{0, 0, -1}) == std::optional<std::size_t>{2});
  // Fewer targets than motors: only those given are checked.
  CHECK_FALSE(rs::vm::firstOutOfRange(motors, std::vector<std::int32_t>{5}).has_value());
}

// The flags kOps gives the control-flow facts, by hand from the paper's
// meaning of each instruction (the static_asserts only check consistency).
TEST_CASE("call, return, branch, wait and end are the instructions that do so", "[vm][opcodes]") {
  using rs::vm::Op;
  const auto with = [](rs::vm::OpFlag flag) {
    std::vector<Op> out;
    for (const rs::vm::OpInfo& op : rs::vm::kOps)
      if (op.flags & flag) out.push_back(op.op);
    return out;
  };
  CHECK(with(rs::vm::kCalls) == std::vector<Op>{Op::Gosub});
  CHECK(with(rs::vm::kReturns) == std::vector<Op>{Op::Return});
  CHECK(with(rs::vm::kBranches) == std::vector<Op>{Op::JmpIn, Op::JmpVar});
  CHECK(with(rs::vm::kWaits) == std::vector<Op>{Op::WaitFor, Op::Delay});
  CHECK(with(rs::vm::kEnds) == std::vector<Op>{Op::End});
}
