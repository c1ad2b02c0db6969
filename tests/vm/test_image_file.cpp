// The image file loader: round trips, and every kind of damaged or hostile
// image (the verifier's own checks: test_verifier.cpp). The file layout
// (vm/image_file.cpp):
//
//   header  0..7 magic, 8..9 major, 10..11 minor, 12..15 payload size,
//           16..19 CRC-32 of the payload
//   payload str sourceName, str robotName, u16 call depth, u16 reserved,
//           u32 motor count, motors (24 bytes each), u32 instruction count,
//           instructions (12 bytes each), lines, columns, constants,
//           variables, points, labels
//   (str = u16 length + bytes; all little-endian)
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "runtime/run/run.h"
#include "stdlib/default_robot.h"
#include "tests/vm/image_support.h"
#include "vm/disasm.h"
#include "vm/image_file.h"
#include "vm/interpreter.h"
#include "vm/verify.h"

namespace {

using rs::testing::Bytes;
using rs::testing::compileOk;
using rs::testing::kSample;
using rs::testing::loadError;
using rs::testing::rhino;
using rs::testing::sample;
using rs::testing::tiny;
using rs::testing::view;
using rs::vm::Image;
using rs::vm::Instr;
using rs::vm::Op;

constexpr std::size_t kHeader = rs::vm::kImageHeaderBytes;


std::uint32_t u32At(const Bytes& b, std::size_t at) {
  return std::uint32_t{b[at]} | std::uint32_t{b[at + 1]} << 8 | std::uint32_t{b[at + 2]} << 16 |
         std::uint32_t{b[at + 3]} << 24;
}
void putU16(Bytes& b, std::size_t at, std::uint16_t v) {
  for (int i = 0; i < 2; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}
void putU32(Bytes& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

// Makes the header agree with the payload again (size and CRC), so that a
// change to the payload reaches the decoder and the verifier.
void fixHeader(Bytes& b) {
  putU32(b, 12, static_cast<std::uint32_t>(b.size() - kHeader));
  putU32(b, 16, rs::vm::crc32(b.data() + kHeader, b.size() - kHeader));
}

// File offsets of the counts, for an image whose names are known.
std::size_t motorCountOffset(const Image& im) { return kHeader + 2 + im.sourceName.size() + 2 + im.robotName.size() + 4; }
std::size_t codeCountOffset(const Image& im) { return motorCountOffset(im) + 4 + 24 * im.motors.size(); }
std::size_t constantCountOffset(const Image& im) { return codeCountOffset(im) + 4 + 20 * im.code.size(); }

bool printable(const std::string& s) {
  for (char c : s)
    if (c < 0x20 || c > 0x7E) return false;
  return true;
}

// Whatever an accepted image holds, it must verify, list and run without
// crashing (the interpreter trusts the verifier for every index).
void exerciseAccepted(const Image& im) {
  REQUIRE(rs::vm::verify(im).message.empty());
  const std::string listing = rs::vm::disassemble(im);
  CHECK(!listing.empty());
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const Image>(im);
  spec.limits = rs::vm::RunLimits{200, 100 * 1'000'000LL};
  rs::runtime::Run run(std::move(spec));
  const rs::vm::RunOutcome o = run.runToEnd();
  CHECK(o.index < im.code.size());
}

}  // namespace

TEST_CASE("write then load gives back the same image", "[verifier]") {
  const std::vector<std::string> programs = {
      kSample,
      "END\n",
      "start: SET Count 0\nloop: ADD count 1\nJMPVAR COUNT < 10 loop\nGOSUB sub\nEND\nsub: MOVEP Home\nRETURN\n"
      "POINTS\nHome 0 0 0 0 0\nPick -1000 550 -350 700 120\n",
      "MOVE 1 2 3 4 5\nVIEW -1 -2 -3\nSETSOFT 0 0 0 0 120\nGOSOFT\nHRDHOME\nRESET\nWAITFOR 8 OFF\nEND\n",
  };
  for (const std::string& text : programs) {
    INFO(text);
    const Image im = compileOk(text);
    const Bytes bytes = rs::vm::writeImage(im);
    const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(view(bytes));
    REQUIRE(loaded.ok());
    CHECK(loaded.value() == im);
    // Same image, same bytes.
    CHECK(rs::vm::writeImage(loaded.value()) == bytes);
    CHECK(rs::vm::looksLikeImage(view(bytes)));
  }
}

TEST_CASE("the header of an image is laid out as documented", "[verifier]") {
  const Bytes b = rs::vm::writeImage(tiny());
  REQUIRE(b.size() > kHeader);
  CHECK(Bytes(b.begin(), b.begin() + 8) == Bytes{0x89, 'R', 'S', 'B', '\r', '\n', 0x1A, '\n'});
  CHECK(b[8] == 1);   // major, little-endian
  CHECK(b[9] == 0);
  CHECK(b[10] == 0);  // minor
  CHECK(b[11] == 0);
  CHECK(u32At(b, 12) == b.size() - kHeader);
  CHECK(u32At(b, 16) == rs::vm::crc32(b.data() + kHeader, b.size() - kHeader));
  // CRC-32 of "123456789" is the well-known check value.
  const std::string check = "123456789";
  CHECK(rs::vm::crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()) == 0xCBF43926u);
}

// Regression (a bug these tests found, fixed since): the compiler accepted
// names of any length, but the loader only accepts names of at most 64
// characters, so `robotsim compile` wrote images that `robotsim run` then
// rejected as malformed. Now: 64 characters round-trip, 65 do not compile.
TEST_CASE("every image the compiler produces loads back", "[verifier]") {
  const std::string n64(64, 'N');
  const Image im = compileOk(n64 + ": SET " + n64 + " 1\nMOVEP " + n64 + "\nEND\nPOINTS\n" + n64 + " 0 0 0 0 0\n");
  REQUIRE(im.variables == std::vector<std::string>{n64});
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(view(rs::vm::writeImage(im)));
  CHECK(loaded.ok());
  CHECK(loaded.value() == im);

  const std::string n65(65, 'V');
  for (const std::string& text : {"SET " + n65 + " 1\nEND\n", n65 + ": SET N 1\nEND\n",
                                  "MOVEP " + n65 + "\nEND\nPOINTS\n" + n65 + " 0 0 0 0 0\n"}) {
    INFO(text);
    const rs::compiler::CompileResult r = rs::compiler::compile(rs::diag::SourceFile("v.rsp", text), rhino());
    CHECK_FALSE(r.ok());
  }
  const rs::compiler::CompileResult r =
      rs::compiler::compile(rs::diag::SourceFile("v.rsp", "SET " + n65 + " 1\nEND\n"), rhino());
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].pos == rs::diag::Pos{1, 5});
  CHECK(r.diagnostics[0].message ==
        "'VVVVVVVVVVVVVVVV...' is too long for a variable: names have at most 64 characters");
}

// docs/bytecode.md: the writer cuts strings (the source name) at 255 bytes.
TEST_CASE("a source name longer than 255 bytes is cut, the image still loads", "[verifier]") {
  Image im = tiny();
  im.sourceName = std::string(300, 's');
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(view(rs::vm::writeImage(im)));
  REQUIRE(loaded.ok());
  CHECK(loaded.value().sourceName == std::string(255, 's'));
}

TEST_CASE("an image cut short at any length is rejected", "[verifier]") {
  const Bytes full = rs::vm::writeImage(sample());
  for (std::size_t n = 0; n < full.size(); ++n) {
    const Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
    const std::string e = loadError(cut);
    INFO("length " << n);
    if (n < 8) REQUIRE(e == "not a robotsim image (bad magic number)");
    else if (n < kHeader) REQUIRE(e == "truncated image header");
    else
      REQUIRE(e == "image payload is " + std::to_string(n - kHeader) + " bytes, the header says " +
                       std::to_string(full.size() - kHeader));
  }
}

TEST_CASE("a payload cut short with a matching header is rejected by the decoder", "[verifier]") {
  const Bytes full = rs::vm::writeImage(sample());
  for (std::size_t n = kHeader; n < full.size(); ++n) {
    Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
    fixHeader(cut);
    const std::string e = loadError(cut);
    INFO("length " << n << ": " << e);
    REQUIRE(e.rfind("malformed image: ", 0) == 0);
  }
  // Cut right after the two names and the call depth: the reserved u16 is missing.
  Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(kHeader + 2 + 5 + 2 + 11 + 2));
  fixHeader(cut);
  CHECK(loadError(cut) == "malformed image: unexpected end of file");
}

TEST_CASE("flipping any single bit of an image is detected", "[verifier]") {
  const Image original = sample();
  const Bytes good = rs::vm::writeImage(original);
  std::vector<std::string> problems;
  std::size_t minorRefused = 0;
  for (std::size_t bit = 0; bit < good.size() * 8; ++bit) {
    Bytes b = good;
    b[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    const rs::diag::Result<rs::vm::Image> r = rs::vm::loadImage(view(b));
    const std::size_t byte = bit / 8;
    if (byte == 10 || byte == 11) {
      // The minor version is not covered by the CRC; 1.1 and later carry
      // a motion section after the cell, which this 1.0 image lacks: any
      // flipped minor bit makes the reader look for it and stop.
      if (loadError(r) == "malformed image: unexpected end of file") ++minorRefused;
      else problems.push_back("minor version bit " + std::to_string(bit) + ": " + loadError(r));
      continue;
    }
    if (r.ok()) problems.push_back("bit " + std::to_string(bit) + " accepted");
    else if (byte >= kHeader && loadError(r) != "image checksum mismatch (the file is corrupt)")
      problems.push_back("payload bit " + std::to_string(bit) + ": " + loadError(r));
  }
  INFO((problems.empty() ? std::string() : problems.front()));
  CHECK(problems.empty());
  CHECK(minorRefused == 16);
}

TEST_CASE("hostile payloads with a correct CRC: rejected clearly, or sound", "[verifier]") {
  // Every bit of the payload flipped, then size and CRC fixed: the decoder
  // and verifier see the damage. Each result is either a clear error or an
  // image that verifies, disassembles and runs.
  for (const Image& original : {sample(), compileOk("loop: ADD N 1\nJMPVAR N < 3 loop\nGOSUB s\nEND\ns: RETURN\n")}) {
    const Bytes good = rs::vm::writeImage(original);
    std::size_t accepted = 0, rejected = 0;
    std::vector<std::string> unclear;
    for (std::size_t bit = kHeader * 8; bit < good.size() * 8; ++bit) {
      Bytes b = good;
      b[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
      fixHeader(b);
      const rs::diag::Result<rs::vm::Image> r = rs::vm::loadImage(view(b));
      if (!r.ok()) {
        ++rejected;
        const bool known = loadError(r).rfind("malformed image: ", 0) == 0 ||
                           loadError(r).rfind("image rejected by the verifier: ", 0) == 0;
        if (!known || !printable(loadError(r))) unclear.push_back(loadError(r));
        continue;
      }
      ++accepted;
      exerciseAccepted(r.value());
    }
    INFO((unclear.empty() ? std::string() : unclear.front()));
    CHECK(unclear.empty());
    CHECK(rejected > 0);
    CHECK(accepted > 0);  // e.g. a changed constant or a renamed variable
  }
}

TEST_CASE("header errors have exact messages", "[verifier]") {
  const Bytes good = rs::vm::writeImage(tiny());
  SECTION("bad magic") {
    Bytes b = good;
    b[1] = 'X';
    CHECK(loadError(b) == "not a robotsim image (bad magic number)");
    CHECK(loadError(Bytes{}) == "not a robotsim image (bad magic number)");
    CHECK_FALSE(rs::vm::looksLikeImage(view(b)));
  }
  SECTION("wrong major version") {
    Bytes b = good;
    putU16(b, 8, 2);
    putU16(b, 10, 7);
    CHECK(loadError(b) == "image version 2.7 is not supported (this robotsim reads 1.x)");
    putU16(b, 8, 0);
    CHECK(loadError(b) == "corrupt image header (version 0.7: robotsim images start at 1.0)");
  }
  SECTION("payload size disagrees") {
    Bytes b = good;
    b.push_back(0);
    CHECK(loadError(b) == "image payload is " + std::to_string(good.size() - kHeader + 1) + " bytes, the header says " +
                              std::to_string(good.size() - kHeader));
  }
  SECTION("checksum") {
    Bytes b = good;
    b[16] ^= 1;
    CHECK(loadError(b) == "image checksum mismatch (the file is corrupt)");
  }
  SECTION("trailing bytes inside the payload") {
    Bytes b = good;
    b.push_back(0);
    b.push_back(0);
    fixHeader(b);
    CHECK(loadError(b) == "malformed image: 2 unexpected bytes after the last section");
  }
}

TEST_CASE("decoder errors have exact messages", "[verifier]") {
  const Image im = tiny();
  const Bytes good = rs::vm::writeImage(im);
  SECTION("reserved header bytes") {
    Bytes b = good;
    b[motorCountOffset(im) - 1] = 1;
    fixHeader(b);
    CHECK(loadError(b) == "malformed image: reserved header bytes are not zero");
  }
  SECTION("reserved motor bytes") {
    Bytes b = good;
    b[motorCountOffset(im) + 4 + 2] = 1;
    fixHeader(b);
    CHECK(loadError(b) == "malformed image: reserved motor bytes are not zero");
  }
  SECTION("joint kind") {
    Bytes b = good;
    b[motorCountOffset(im) + 4 + 1] = 3;
    fixHeader(b);
    CHECK(loadError(b) == "malformed image: motor 1 has joint kind 3");
  }
  SECTION("a name longer than 255 bytes") {
    Bytes b = good;
    putU16(b, kHeader, 300);
    fixHeader(b);
    CHECK(loadError(b) == "malformed image: string of 300 bytes");
  }
  SECTION("unknown opcode") {
    Image bad = im;
    // The first number past the table: unknown whatever instructions are added.
    const std::size_t firstUnknown = rs::vm::kOpCount;
    bad.code[0].op = static_cast<Op>(firstUnknown);
    CHECK(loadError(bad) == "malformed image: instruction 1: unknown opcode " + std::to_string(firstUnknown));
    bad.code[0].op = static_cast<Op>(255);
    CHECK(loadError(bad) == "malformed image: instruction 1: unknown opcode 255");
    CHECK(rs::vm::verify(bad).message == "instruction 1: unknown opcode 255");
  }
  SECTION("bad names") {
    Image bad = compileOk("SET N 1\nMOVEP P\nEND\nPOINTS\nP 0 0 0 0 0\n");
    bad.variables[0] = "1N";
    CHECK(loadError(bad) == "malformed image: variable 1 has a bad name");
    bad = compileOk("SET N 1\nMOVEP P\nEND\nPOINTS\nP 0 0 0 0 0\n");
    bad.points[0].name = "";
    CHECK(loadError(bad) == "malformed image: point 1 has a bad name");
    bad = compileOk("x: END\n");
    rs::testing::setLabelName(bad, 0, "a b");
    CHECK(loadError(bad) == "malformed image: label 1 has a bad name");
  }
}

// Names the compiler could never have written: each is refused with the
// entry it concerns (1-based), and a refused name is quoted only once it is
// known to be an identifier.
TEST_CASE("loader: names the compiler could never write", "[verifier]") {
  const std::string program =
      "a: SET N 1\n"
      "b: SET M 2\n"
      "   MOVEP P\n"
      "   MOVEP Q\n"
      "   END\n"
      "POINTS\n"
      "P 0 0 0 0 0\n"
      "Q 0 0 0 0 0\n";
  const Image im = compileOk(program);
  REQUIRE(im.variables == std::vector<std::string>{"N", "M"});
  REQUIRE(im.labels.size() == 2);
  REQUIRE(loadError(im) == "");
  const auto refused = [&](auto change, const std::string& message) {
    Image bad = im;
    change(bad);
    INFO(message);
    CHECK(loadError(bad) == "malformed image: " + message);
  };
  SECTION("control characters and other non-identifiers") {
    refused([](Image& b) { b.variables[1] = "N\x1b]0;pwned\x07"; }, "variable 2 has a bad name");
    refused([](Image& b) { rs::testing::setLabelName(b, 0, "\x1b[2J"); }, "label 1 has a bad name");
    refused([](Image& b) { b.points[1].name = "Q\n"; }, "point 2 has a bad name");
    refused([](Image& b) { b.variables[0] = "caf\xC3\xA9"; }, "variable 1 has a bad name");
    refused([](Image& b) { b.variables[0] = "A-B"; }, "variable 1 has a bad name");
    refused([](Image& b) { rs::testing::setLabelName(b, 1, std::string(65, 'x')); }, "label 2 has a bad name");
    Image longest = im;
    rs::testing::setLabelName(longest, 1, std::string(64, 'x'));
    CHECK(loadError(longest) == "");
  }
  SECTION("reserved words, in any case") {
    refused([](Image& b) { b.variables[0] = "MOVE"; }, "variable 1 is named MOVE, a reserved word");
    refused([](Image& b) { rs::testing::setLabelName(b, 1, "points"); }, "label 2 is named points, a reserved word");
    refused([](Image& b) { b.points[0].name = "On"; }, "point 1 is named On, a reserved word");
    refused([](Image& b) { b.points[0].name = "OFF"; }, "point 1 is named OFF, a reserved word");
  }
  SECTION("duplicates, ignoring case as programs do") {
    refused([](Image& b) { b.variables[1] = "N"; }, "variable 2 has the same name as variable 1 (N)");
    refused([](Image& b) { b.variables[1] = "n"; }, "variable 2 has the same name as variable 1 (n)");
    refused([](Image& b) { rs::testing::setLabelName(b, 1, "A"); }, "label 2 has the same name as label 1 (A)");
    refused([](Image& b) { b.points[1].name = "P"; }, "point 2 has the same name as point 1 (P)");
    // One name per kind: a label, a point and a variable may share a name.
    Image shared = im;
    rs::testing::setLabelName(shared, 0, "N");
    shared.points[0].name = "N";
    CHECK(loadError(shared) == "");
  }
  SECTION("the robot name") {
    refused([](Image& b) { b.robotName = "rhino\x1b]0;pwned\x07"; }, "the robot name holds a control character");
    refused([](Image& b) { b.robotName = "rhino\tscara"; }, "the robot name holds a control character");
  }
  SECTION("the source name may be any bytes: it is kept and escaped when printed") {
    Image odd = im;
    odd.sourceName = "\x1b]0;pwned\x07.rsp";
    const rs::diag::Result<rs::vm::Image> r = rs::vm::loadImage(view(rs::vm::writeImage(odd)));
    REQUIRE(r.ok());
    CHECK(r.value().sourceName == odd.sourceName);
  }
}

// The listing prints every name the image holds through base::safeText, so
// even an image that never passed the loader cannot reach the terminal raw.
TEST_CASE("disassembler: names are printed with control characters escaped", "[verifier]") {
  Image im = compileOk("loop: SET N 1\nMOVEP P\nJMPVAR N < 3 loop\nEND\nPOINTS\nP 0 0 0 0 0\n");
  im.sourceName = "\x1b]0;pwned\x07.rsp";
  im.robotName = "robot\x1b[31m";
  im.variables[0] = "N\x1b[2J";
  rs::testing::setLabelName(im, 0, "loop\x07");
  im.points[0].name = "P\r";
  const std::string listing = rs::vm::disassemble(im);
  INFO(listing);
  for (char c : listing) CHECK((static_cast<unsigned char>(c) >= 0x20 || c == '\n'));
  CHECK(listing.find("; \\x1b]0;pwned\\x07.rsp (") != std::string::npos);
  CHECK(listing.find("; robot robot\\x1b[31m:") != std::string::npos);
  CHECK(listing.find("SET     N\\x1b[2J 1") != std::string::npos);
  CHECK(listing.find("loop\\x07") != std::string::npos);
  CHECK(listing.find("P\\x0d = 0 0 0 0 0") != std::string::npos);
}

// No timing here (timed unit tests flake on a shared machine): a count that
// did allocate would fail the ASan+UBSan run (allocation-size-too-big).
TEST_CASE("huge counts are refused before anything is allocated", "[verifier]") {
  const Image im = sample();
  const Bytes good = rs::vm::writeImage(im);
  struct Case {
    std::size_t offset;
    const char* what;
  };
  const Case cases[] = {{motorCountOffset(im), "motor"}, {codeCountOffset(im), "instruction"},
                        {constantCountOffset(im), "constant"}};
  for (const Case& c : cases) {
    // Sanity: the offset really holds the count.
    REQUIRE(u32At(good, motorCountOffset(im)) == im.motors.size());
    REQUIRE(u32At(good, codeCountOffset(im)) == im.code.size());
    REQUIRE(u32At(good, constantCountOffset(im)) == im.constants.size());
    for (std::uint32_t count : {0xFFFFFFFFu, 0x80000000u, 1'000'000u}) {
      Bytes b = good;
      putU32(b, c.offset, count);
      fixHeader(b);
      CHECK(loadError(b) == "malformed image: " + std::string(c.what) + " count " + std::to_string(count) +
                                " larger than the file");
    }
  }
}

namespace {

// A stream that cannot seek (tellp() gives -1), as a pipe: what it was
// given, in order.
class PipeLikeBuffer final : public std::streambuf {
 public:
  std::string written;

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) written += traits_type::to_char_type(c);
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    written.append(s, static_cast<std::size_t>(n));
    return n;
  }
};

}  // namespace

TEST_CASE("an image streamed to a file has the bytes of the image in memory", "[verifier]") {
  // 20,000 instructions: 400 KB of payload, several of the writer's 64 KiB
  // pieces; and a one-instruction image, less than one piece. A stream that
  // seeks gets the payload in one pass and its header last; one that cannot
  // gets two passes: the same bytes.
  std::string big;
  for (int i = 0; i < 20000; ++i) big += "MOVE " + std::to_string(i % 90) + " 2 3 4 5\n";
  for (const std::string& text : {big + "END\n", std::string("END\n")}) {
    const Image im = compileOk(text);
    const Bytes inMemory = rs::vm::writeImage(im);
    std::ostringstream streamed;
    streamed << "before";  // the image need not start the stream
    REQUIRE(rs::vm::writeImage(im, streamed));
    streamed << "after";
    const std::string s = streamed.str();
    REQUIRE(s.size() == 6 + inMemory.size() + 5);
    CHECK(s.substr(0, 6) == "before");
    CHECK(s.substr(s.size() - 5) == "after");
    CHECK(Bytes(s.begin() + 6, s.end() - 5) == inMemory);
    CHECK(rs::vm::loadImage(s.substr(6, inMemory.size())).ok());

    PipeLikeBuffer pipe;
    std::ostream piped(&pipe);
    REQUIRE(piped.tellp() == std::ostream::pos_type(-1));
    REQUIRE(rs::vm::writeImage(im, piped));
    CHECK(Bytes(pipe.written.begin(), pipe.written.end()) == inMemory);
  }
}
