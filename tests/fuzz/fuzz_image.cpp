// libFuzzer target: any bytes as a compiled image (.rsb). The loader must
// refuse what it cannot trust with a message, and what it accepts must
// disassemble and run (bounded) on the simulated Rhino without a fault of
// our own: a verified image is safe to run; its cell section decodes or is
// refused.
//
// Built twice: fuzz_image sees the bytes as they come (most mutations die
// at the checksum, which is the point of the checksum), fuzz_image_fixed
// (ROBOTSIM_FUZZ_FIX_CHECKSUM) has a custom mutator that rewrites the header
// after each mutation (magic, version 1.0, payload size, CRC-32), so the
// decoder and the verifier behind it see every mutation.
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>

#include "model/workcell/cell_file.h"
#include "runtime/run/run.h"
#include "vm/disasm.h"
#include "vm/image_file.h"

namespace {

std::string_view view(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace

#ifdef ROBOTSIM_FUZZ_FIX_CHECKSUM
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int /*seed*/) {
  size = LLVMFuzzerMutate(data, size, maxSize);
  if (size < rs::vm::kImageHeaderBytes) return size;
  const auto le = [&](std::size_t at, std::uint32_t v, int n) {
    for (int i = 0; i < n; ++i) data[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  std::memcpy(data, rs::vm::kImageMagic.data(), rs::vm::kImageMagic.size());
  le(8, rs::vm::kImageVersionMajor, 2);
  le(10, data[10] & 1u, 2);  // 1.0 or 1.1 (the motion section), as the mutation left it
  const std::size_t payload = size - rs::vm::kImageHeaderBytes;
  le(12, static_cast<std::uint32_t>(payload), 4);
  le(16, rs::vm::crc32(data + rs::vm::kImageHeaderBytes, payload), 4);
  return size;
}
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(view(data, size));
  if (!loaded.ok()) return 0;
  (void)rs::vm::disassemble(loaded.value());
  // The cell section, as every command that loads an image decodes it.
  (void)rs::workcell::decodeCell(loaded.value().cell);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(std::move(loaded).value());
  spec.limits.maxSteps = 20'000;
  spec.limits.maxStepsPerInstant = 20'000;
  spec.limits.maxTime = rs::vm::Micros{600} * 1'000'000;
  rs::runtime::Run run(std::move(spec));
  (void)run.runToEnd();
  return 0;
}
