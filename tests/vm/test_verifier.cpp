// The verifier (vm/verify.h): images the loader accepts but that are
// unsound (jump targets, operands, points, tables, labels, the motor
// table) are refused with a message naming the instruction or entry. The
// file loader's own checks: test_image_file.cpp.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <string>

#include "tests/vm/image_support.h"
#include "vm/image_file.h"
#include "vm/verify.h"

namespace {

using rs::testing::compileOk;
using rs::testing::loadError;
using rs::testing::sample;
using rs::testing::tiny;
using rs::vm::Image;

}  // namespace

TEST_CASE("verifier: jump targets", "[verifier]") {
  Image im = sample();
  REQUIRE(loadError(im) == "");
  Image bad = im;
  bad.code[8].d = 10;
  CHECK(loadError(bad) == "image rejected by the verifier: instruction 9 (GOTO): jump target 10 outside the code");
  bad.code[8].d = -1;
  CHECK(loadError(bad) == "image rejected by the verifier: instruction 9 (GOTO): jump target -1 outside the code");
  bad = im;
  bad.code[3].d = 99;
  CHECK(loadError(bad) == "image rejected by the verifier: instruction 4 (JMPVAR): jump target 99 outside the code");
  bad = im;
  bad.code[5].d = std::numeric_limits<std::int32_t>::max();
  CHECK(loadError(bad) ==
        "image rejected by the verifier: instruction 6 (JMPIN): jump target 2147483647 outside the code");
  // The last instruction is a valid target.
  bad = im;
  bad.code[8].d = 9;
  CHECK(loadError(bad) == "");
}

TEST_CASE("verifier: operands", "[verifier]") {
  const Image im = sample();
  const auto rejected = [&](auto change, const std::string& message) {
    Image bad = im;
    change(bad);
    INFO(message);
    CHECK(loadError(bad) == "image rejected by the verifier: " + message);
    CHECK(rs::vm::verify(bad).message == message);
  };
  rejected([](Image& b) { b.code[9].a = 1; }, "instruction 10 (END): unused operand fields are not zero");
  rejected([](Image& b) { b.code[8].c = 1; }, "instruction 9 (GOTO): unused operand fields are not zero");
  rejected([](Image& b) { b.code[4].d = 1; }, "instruction 5 (OUTSIG): unused operand fields are not zero");
  rejected([](Image& b) { b.code[0].a = 1; }, "instruction 1 (MOVETO): unused operand fields are not zero");
  rejected([](Image& b) { b.code[1].c = 1; }, "instruction 2 (MOVEP): unused operand fields are not zero");
  rejected([](Image& b) { b.code[2].d = 1; }, "instruction 3 (SET): unused operand fields are not zero");
  rejected([](Image& b) { b.code[7].b = 1; }, "instruction 8 (DELAY): unused operand fields are not zero");
  rejected([](Image& b) { b.code[5].c = 1; }, "instruction 6 (JMPIN): unused operand fields are not zero");
  rejected([](Image& b) { b.code[4].a = 9; }, "instruction 5 (OUTSIG): line 9 outside 1..8");
  rejected([](Image& b) { b.code[4].a = 0; }, "instruction 5 (OUTSIG): line 0 outside 1..8");
  rejected([](Image& b) { b.code[4].b = 2; }, "instruction 5 (OUTSIG): state 2 is neither ON nor OFF");
  rejected([](Image& b) { b.code[5].a = 9; }, "instruction 6 (JMPIN): input 9 outside 1..8");
  rejected([](Image& b) { b.code[5].b = 7; }, "instruction 6 (JMPIN): state 7 is neither ON nor OFF");
  rejected([](Image& b) { b.code[0].c = 4; }, "instruction 1 (MOVETO): constant index 4 out of bounds");
  rejected([](Image& b) { b.code[0].c = -1; }, "instruction 1 (MOVETO): constant index -1 out of bounds");
  rejected([](Image& b) { b.code[6].c = 6; }, "instruction 7 (WINDOW): constant index 6 out of bounds");
  rejected([](Image& b) { b.code[0].b = 4; }, "instruction 1 (MOVETO): moves 4 motors, the image has 5");
  rejected([](Image& b) { b.constants[0] = 5000; }, "instruction 1 (MOVETO): motor E target 5000 outside its range");
  rejected([](Image& b) { b.code[1].b = 1; }, "instruction 2 (MOVEP): point index 1 out of bounds");
  rejected([](Image& b) { b.code[2].b = 1; }, "instruction 3 (SET): variable slot 1 out of bounds");
  rejected([](Image& b) { b.code[3].a = 3; }, "instruction 4 (JMPVAR): comparison 3 unknown");
  rejected([](Image& b) { b.code[7].c = -1; }, "instruction 8 (DELAY): delay -1 ms out of range");
  rejected([](Image& b) { b.code[7].c = 86'400'001; }, "instruction 8 (DELAY): delay 86400001 ms out of range");
}

TEST_CASE("verifier: points, tables and labels", "[verifier]") {
  const Image im = sample();
  Image bad = im;
  bad.points[0].values[4] = 121;
  CHECK(loadError(bad) == "image rejected by the verifier: point P1 value 121 outside motor A range");
  // A point with the wrong arity cannot even be written consistently (the
  // file stores one value per motor); the verifier names it.
  bad = im;
  bad.points[0].values.pop_back();
  CHECK(rs::vm::verify(bad).message == "point P1 has 4 values for 5 motors");
  CHECK(loadError(bad) != "");

  bad = tiny();
  bad.code.clear();
  bad.lines.clear();
  bad.columns.clear();
  CHECK(loadError(bad) == "image rejected by the verifier: the image has no code");
  bad = tiny();
  bad.lines.clear();
  CHECK(rs::vm::verify(bad).message == "line table has 0 entries for 1 instructions");
  bad = tiny();
  rs::testing::setLine(bad, 0, 0);
  CHECK(loadError(bad) == "image rejected by the verifier: instruction 1 has no source position");
  bad = tiny();
  bad.callDepthLimit = 0;
  CHECK(loadError(bad) == "image rejected by the verifier: call depth limit 0 outside 1..4096");
  bad.callDepthLimit = 4097;
  CHECK(loadError(bad) == "image rejected by the verifier: call depth limit 4097 outside 1..4096");

  bad = compileOk("a: SET N 1\nb: END\n");
  bad.labels[1].index = 2;
  CHECK(loadError(bad) == "image rejected by the verifier: label b outside the code");
  bad = compileOk("a: SET N 1\nb: END\n");
  bad.labels.clear();
  bad.labelNames.clear();
  bad.addLabel(1, "b");
  bad.addLabel(0, "a");
  CHECK(loadError(bad) == "image rejected by the verifier: labels are not sorted");
}

TEST_CASE("verifier: motor table", "[verifier]") {
  const auto rejected = [](auto change, const std::string& message) {
    Image bad = tiny();
    change(bad);
    INFO(message);
    CHECK(loadError(bad) == "image rejected by the verifier: " + message);
  };
  rejected([](Image& b) { b.motors.clear(); }, "motor table has 0 motors (1..26 allowed)");
  rejected(
      [](Image& b) {
        b.motors.clear();
        for (char c = 'A'; c <= 'Z'; ++c) b.motors.push_back({c, rs::vm::JointKind::Revolute, 1.0, -1, 1, 1});
        b.motors.push_back({'A', rs::vm::JointKind::Revolute, 1.0, -1, 1, 1});
      },
      "motor table has 27 motors (1..26 allowed)");
  rejected([](Image& b) { b.motors[1].letter = 'E'; }, "motor letter E appears twice");
  rejected([](Image& b) { b.motors[0].letter = 'e'; }, "motor 1 has no letter A..Z");
  rejected([](Image& b) { b.motors[4].letter = '@'; }, "motor 5 has no letter A..Z");
  rejected(
      [](Image& b) {
        b.motors[2].min = 10;
        b.motors[2].max = -10;
      },
      "motor C range 10..-10 is empty");
  rejected(
      [](Image& b) {
        b.motors[2].min = 10;
        b.motors[2].max = 20;
      },
      "motor C range 10..20 does not include 0, where every motor starts");
  rejected([](Image& b) { b.motors[1].max = -1; }, "motor D range -550..-1 does not include 0, where every motor starts");
  rejected([](Image& b) { b.motors[3].speed = 0; }, "motor B speed 0 is not positive");
  rejected([](Image& b) { b.motors[3].speed = -5; }, "motor B speed -5 is not positive");
  rejected([](Image& b) { b.motors[4].precision = 0.0; }, "motor A precision is not a positive number");
  rejected([](Image& b) { b.motors[4].precision = std::nan(""); }, "motor A precision is not a positive number");
  rejected([](Image& b) { b.motors[4].precision = std::numeric_limits<double>::infinity(); },
           "motor A precision is not a positive number");
  Image kind = tiny();
  kind.motors[0].kind = static_cast<rs::vm::JointKind>(3);
  CHECK(rs::vm::verify(kind).message == "motor E has an unknown joint kind");
  // 26 motors are fine.
  Image many = tiny();
  many.motors.clear();
  for (char c = 'A'; c <= 'Z'; ++c) many.motors.push_back({c, rs::vm::JointKind::Revolute, 1.0, -1, 1, 1});
  CHECK(loadError(many) == "");
}
