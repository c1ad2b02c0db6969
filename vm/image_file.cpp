#include "vm/image_file.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <unordered_map>

#include "base/ascii.h"
#include "base/byte_io.h"
#include "base/text.h"
#include "vm/verify.h"

namespace rs::vm {

namespace {

using base::ByteReader;
using base::ByteWriter;

// An identifier of the language, as the lexer reads IDENT: [A-Za-z_][A-Za-z0-9_]*.
bool isIdentifier(std::string_view s) {
  if (s.empty() || s.size() > kMaxNameLength) return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool alpha = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
    if (!alpha && !(i > 0 && c >= '0' && c <= '9')) return false;
  }
  return true;
}

// The variable, point or label names of an image, checked one by one as
// they are read: each must be a name the compiler could have written (an
// identifier of at most 64 characters, not a reserved word) and none may
// repeat another of its kind. Names ignore case, as in programs.
class NameRules {
 public:
  explicit NameRules(std::string_view kind) : kind_(kind) {}

  /// Fails `r` with a message naming the entry `index` (0-based) if `name` breaks a rule.
  void check(ByteReader& r, std::size_t index, std::string_view name) {
    if (r.failed) return;
    if (!isIdentifier(name)) return r.fail(fmt::format("{} {} has a bad name", kind_, index + 1));
    // From here on the name is an identifier: safe to quote.
    if (isReservedWord(name)) return r.fail(fmt::format("{} {} is named {}, a reserved word", kind_, index + 1, name));
    std::string key(name);
    for (char& c : key) c = base::asciiUpper(c);
    const auto [it, fresh] = seen_.try_emplace(std::move(key), index);
    if (!fresh)
      r.fail(fmt::format("{} {} has the same name as {} {} ({})", kind_, index + 1, kind_, it->second + 1, name));
  }

 private:
  std::string_view kind_;
  std::unordered_map<std::string, std::size_t> seen_;  // upper-case name -> first index
};

// A 1.1 image: some motor does not simply run at constant speed.
bool hasMotionSection(const Image& im) {
  for (const MotorSpec& m : im.motors)
    if (m.acceleration != 0 || m.actuation != 0) return true;
  return false;
}

// On a little-endian machine an instruction's 12 bytes in memory are its
// 12 bytes in the file (op, a, b, c, d; no padding), and a constant's 4
// bytes are too: they are copied as they are, a piece at a time, instead
// of field by field (a third of writing an image).
constexpr bool kInstrInFileLayout = std::endian::native == std::endian::little && sizeof(Instr) == kInstrBytes &&
                                    offsetof(Instr, a) == 1 && offsetof(Instr, b) == 2 && offsetof(Instr, c) == 4 &&
                                    offsetof(Instr, d) == 8;

template <class T>
void bulk(ByteWriter& w, const std::vector<T>& items) {
  constexpr std::size_t kPiece = 4096;  // items a copy: the writer spills between them
  static_assert(std::is_trivially_copyable_v<T>);
  for (std::size_t i = 0; i < items.size(); i += kPiece)
    w.bytes(reinterpret_cast<const std::uint8_t*>(items.data() + i), std::min(kPiece, items.size() - i) * sizeof(T));
}

void writePayload(ByteWriter& w, const Image& im) {
  w.str(im.sourceName);
  w.str(im.robotName);
  w.u16(im.callDepthLimit);
  w.u16(0);
  w.u32(static_cast<std::uint32_t>(im.motors.size()));
  for (const MotorSpec& m : im.motors) {
    w.u8(static_cast<std::uint8_t>(m.letter));
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.u16(0);
    w.i32(m.min);
    w.i32(m.max);
    w.i32(m.speed);
    w.f64(m.precision);
  }
  w.u32(static_cast<std::uint32_t>(im.code.size()));
  if constexpr (kInstrInFileLayout) {
    bulk(w, im.code);
  } else {
    for (const Instr& in : im.code) {
      w.u8(static_cast<std::uint8_t>(in.op));
      w.u8(in.a);
      w.u16(in.b);
      w.i32(in.c);
      w.i32(in.d);
    }
  }
  for (std::uint32_t line : im.lines) w.u32(line);
  for (std::uint32_t col : im.columns) w.u32(col);
  w.u32(static_cast<std::uint32_t>(im.constants.size()));
  if constexpr (std::endian::native == std::endian::little) {
    bulk(w, im.constants);
  } else {
    for (std::int32_t k : im.constants) w.i32(k);
  }
  w.u32(static_cast<std::uint32_t>(im.variables.size()));
  for (const std::string& v : im.variables) w.str(v);
  w.u32(static_cast<std::uint32_t>(im.points.size()));
  for (const Point& p : im.points) {
    w.str(p.name);
    for (std::int32_t v : p.values) w.i32(v);
  }
  w.u32(static_cast<std::uint32_t>(im.labels.size()));
  for (std::size_t i = 0; i < im.labels.size(); ++i) {
    w.u32(im.labels[i].index);
    w.str(im.labelName(i));
  }
  w.u32(static_cast<std::uint32_t>(im.cell.size()));
  w.bytes(im.cell);
  if (!hasMotionSection(im)) return;
  for (const MotorSpec& m : im.motors) {
    w.i32(m.acceleration);
    w.i32(m.actuation);
  }
}

// The exact size writePayload writes, so that the buffer is allocated once.
std::size_t payloadBytes(const Image& im) {
  const auto str = [](std::string_view s) { return 2 + std::min(s.size(), base::kMaxStoredString); };
  std::size_t n = str(im.sourceName) + str(im.robotName) + 4 + 4 + im.motors.size() * 24;
  n += 4 + im.code.size() * kInstrBytes + im.lines.size() * 4 + im.columns.size() * 4;
  n += 4 + im.constants.size() * 4 + 4;
  for (const std::string& v : im.variables) n += str(v);
  n += 4;
  for (const Point& p : im.points) n += str(p.name) + p.values.size() * 4;
  n += 4;
  for (std::size_t i = 0; i < im.labels.size(); ++i) n += 4 + str(im.labelName(i));
  return n + 4 + im.cell.size() + (hasMotionSection(im) ? im.motors.size() * 8 : 0);
}

// 1.1's motion section: each motor's acceleration and actuation time (the
// verifier checks their values).
void readMotion(ByteReader& r, Image& im) {
  for (MotorSpec& m : im.motors) {
    m.acceleration = r.i32();
    m.actuation = r.i32();
  }
  if (!r.failed && !hasMotionSection(im)) r.fail("a motion section in which no motor has an acceleration or an actuation time");
}

void readMotors(ByteReader& r, Image& im) {
  const std::size_t n = r.count(24, "motor");
  for (std::size_t i = 0; i < n && !r.failed; ++i) {
    MotorSpec m;
    m.letter = static_cast<char>(r.u8());
    const std::uint8_t kind = r.u8();
    if (kind > static_cast<std::uint8_t>(JointKind::Gripper)) r.fail(fmt::format("motor {} has joint kind {}", i + 1, kind));
    m.kind = static_cast<JointKind>(kind);
    if (r.u16() != 0) r.fail("reserved motor bytes are not zero");
    m.min = r.i32();
    m.max = r.i32();
    m.speed = r.i32();
    m.precision = r.f64();
    im.motors.push_back(m);
  }
}

void readCode(ByteReader& r, Image& im) {
  const std::size_t n = r.count(kInstrBytes + 8, "instruction");
  im.code.reserve(n);
  for (std::size_t i = 0; i < n && !r.failed; ++i) {
    const std::uint8_t op = r.u8();
    if (op >= kOpCount) r.fail(fmt::format("instruction {}: unknown opcode {}", i + 1, op));
    Instr in;
    in.op = static_cast<Op>(op);
    in.a = r.u8();
    in.b = r.u16();
    in.c = r.i32();
    in.d = r.i32();
    im.code.push_back(in);
  }
  im.lines.reserve(n);
  for (std::size_t i = 0; i < n && !r.failed; ++i) im.lines.push_back(r.u32());
  im.columns.reserve(n);
  for (std::size_t i = 0; i < n && !r.failed; ++i) im.columns.push_back(r.u32());
}

void readNames(ByteReader& r, Image& im) {
  const std::size_t nk = r.count(4, "constant");
  im.constants.reserve(nk);
  for (std::size_t i = 0; i < nk && !r.failed; ++i) im.constants.push_back(r.i32());
  const std::size_t nv = r.count(2, "variable");
  NameRules variables("variable"), points("point"), labels("label");
  for (std::size_t i = 0; i < nv && !r.failed; ++i) {
    im.variables.push_back(r.str());
    variables.check(r, i, im.variables.back());
  }
  const std::size_t np = r.count(2 + 4 * im.motors.size(), "point");
  for (std::size_t i = 0; i < np && !r.failed; ++i) {
    Point p;
    p.name = r.str();
    points.check(r, i, p.name);
    for (std::size_t m = 0; m < im.motors.size(); ++m) p.values.push_back(r.i32());
    im.points.push_back(std::move(p));
  }
  const std::size_t nl = r.count(6, "label");
  for (std::size_t i = 0; i < nl && !r.failed; ++i) {
    const std::uint32_t index = r.u32();
    const std::string name = r.str();
    labels.check(r, i, name);
    im.addLabel(index, name);
  }
  // The cell section is opaque here; runtime/workcell decodes and checks it.
  const std::size_t nc = r.count(1, "cell byte");
  im.cell.reserve(nc);
  for (std::size_t i = 0; i < nc && !r.failed; ++i) im.cell.push_back(r.u8());
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) { return crc32Update(0, data, size); }

std::uint32_t crc32Update(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
  // zlib's CRC-32 (Debian's zlib1g, which robotsim links for PNG already):
  // the same IEEE 802.3 CRC, several bytes a step, about three times the
  // speed of the four-bytes-a-step table it replaced (docs/performance.md).
  if (size == 0) return crc;
  return static_cast<std::uint32_t>(crc32_z(crc, data, size));
}

namespace {

std::vector<std::uint8_t> imageHeader(const Image& image, std::size_t payloadSize, std::uint32_t crc) {
  ByteWriter header;
  header.out.assign(kImageMagic.begin(), kImageMagic.end());
  header.u16(kImageVersionMajor);
  header.u16(hasMotionSection(image) ? kImageVersionMinor : 0);
  header.u32(static_cast<std::uint32_t>(payloadSize));
  header.u32(crc);
  return std::move(header.out);
}

}  // namespace

std::vector<std::uint8_t> writeImage(const Image& image) {
  // The payload is written after room for the header, which is filled in
  // last (it holds the payload's size and CRC): no copy of the payload.
  ByteWriter w;
  w.out.reserve(kImageHeaderBytes + payloadBytes(image));
  w.out.resize(kImageHeaderBytes);
  writePayload(w, image);
  const std::size_t size = w.out.size() - kImageHeaderBytes;
  const std::vector<std::uint8_t> header = imageHeader(image, size, crc32(w.out.data() + kImageHeaderBytes, size));
  std::copy(header.begin(), header.end(), w.out.begin());
  return std::move(w.out);  // a member: not moved by itself
}

bool writeImage(const Image& image, std::ostream& out) {
  // The header comes first and holds the payload's size and CRC. On a
  // stream that can seek (a file, a string stream) the payload is written
  // once, behind a header of zeros that is rewritten at the end; on one
  // that cannot (a pipe), one pass through the payload computes them and a
  // second writes it. 64 KiB at a time either way: the bytes are
  // writeImage(image)'s, never held whole.
  constexpr std::size_t kChunk = std::size_t{64} << 10;
  const auto put = [&out](const std::vector<std::uint8_t>& piece) {
    out.write(reinterpret_cast<const char*>(piece.data()), static_cast<std::streamsize>(piece.size()));
  };
  std::uint32_t crc = 0;
  std::size_t size = 0;
  const auto sum = [&](const std::vector<std::uint8_t>& piece) {
    crc = crc32Update(crc, piece.data(), piece.size());
    size += piece.size();
  };
  const std::ostream::pos_type start = out.tellp();
  if (start != std::ostream::pos_type(-1)) {
    put(imageHeader(image, 0, 0));
    ByteWriter writing(
        [&](const std::vector<std::uint8_t>& piece) {
          sum(piece);
          put(piece);
        },
        kChunk);
    writePayload(writing, image);
    writing.flush();
    const std::ostream::pos_type end = out.tellp();
    out.seekp(start);
    put(imageHeader(image, size, crc));
    out.seekp(end);
    return static_cast<bool>(out);
  }
  ByteWriter summing(sum, kChunk);
  writePayload(summing, image);
  summing.flush();
  put(imageHeader(image, size, crc));
  ByteWriter writing(put, kChunk);
  writePayload(writing, image);
  writing.flush();
  return static_cast<bool>(out);
}

bool looksLikeImage(std::string_view bytes) {
  return bytes.size() >= kImageMagic.size() &&
         std::memcmp(bytes.data(), kImageMagic.data(), kImageMagic.size()) == 0;
}

namespace {

struct LoadResult {
  Image image;
  std::string error;  // empty when the image loaded and verified
};

LoadResult decodeImage(std::string_view bytes) {
  LoadResult result;
  if (!looksLikeImage(bytes)) return {{}, "not a robotsim image (bad magic number)"};
  if (bytes.size() > kMaxImageBytes) return {{}, "image larger than 1 GiB"};
  ByteReader header(bytes.substr(kImageMagic.size()));
  const std::uint16_t major = header.u16();
  const std::uint16_t minor = header.u16();
  const std::uint32_t size = header.u32();
  const std::uint32_t crc = header.u32();
  if (header.failed) return {{}, "truncated image header"};
  // No robotsim ever wrote a version 0: the header is damaged, not new.
  if (major == 0) return {{}, fmt::format("corrupt image header (version {}.{}: robotsim images start at 1.0)", major, minor)};
  if (major != kImageVersionMajor)
    return {{}, fmt::format("image version {}.{} is not supported (this robotsim reads {}.x)", major, minor,
                            kImageVersionMajor)};
  const std::string_view payload = bytes.substr(kImageHeaderBytes);
  if (payload.size() != size)
    return {{}, fmt::format("image payload is {} bytes, the header says {}", payload.size(), size)};
  if (crc32(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size()) != crc)
    return {{}, "image checksum mismatch (the file is corrupt)"};

  ByteReader r(payload);
  Image& im = result.image;
  // The source name is the file name the compiler was given: any bytes, so
  // it is kept as it is and printers escape it. A robot name comes from a
  // description, whose names never hold control characters.
  im.sourceName = r.str();
  im.robotName = r.str();
  if (!r.failed && base::hasControlCharacter(im.robotName)) r.fail("the robot name holds a control character");
  im.callDepthLimit = r.u16();
  if (r.u16() != 0) r.fail("reserved header bytes are not zero");
  readMotors(r, im);
  readCode(r, im);
  readNames(r, im);
  if (minor >= 1) readMotion(r, im);
  if (!r.failed && r.remaining() != 0) r.fail(fmt::format("{} unexpected bytes after the last section", r.remaining()));
  if (r.failed) return {{}, "malformed image: " + r.error};
  if (VerifyError e = verify(im); !e.message.empty()) return {{}, "image rejected by the verifier: " + e.message};
  return result;
}

}  // namespace

diag::Result<Image> loadImage(std::string_view bytes, const std::string& file) {
  LoadResult decoded = decodeImage(bytes);
  if (!decoded.error.empty()) return diag::Diagnostic{file, {}, diag::Severity::Error, std::move(decoded.error)};
  return std::move(decoded.image);
}

}  // namespace rs::vm
