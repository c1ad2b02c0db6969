// The file form of an image (`.rsb`): writing, and loading with
// verification. The byte layout is documented in docs/bytecode.md.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "vm/image.h"

namespace rs::vm {

inline constexpr std::array<std::uint8_t, 8> kImageMagic{0x89, 'R', 'S', 'B', '\r', '\n', 0x1A, '\n'};
inline constexpr std::uint16_t kImageVersionMajor = 1;
/// 1.0: constant-speed motors. 1.1 adds a motion section after the cell
/// (each motor's acceleration and actuation time); it is written only when
/// a motor has one, so every other image keeps its 1.0 bytes.
inline constexpr std::uint16_t kImageVersionMinor = 1;
inline constexpr std::size_t kImageHeaderBytes = 20;
inline constexpr std::size_t kMaxImageBytes = std::size_t{1} << 30;  // 1 GiB

/// Serialises an image; same image, same bytes.
std::vector<std::uint8_t> writeImage(const Image& image);
/// The same bytes, written to `out` without being held whole (64 KiB at a
/// time; the payload is serialised twice, once for its CRC). False when
/// `out` fails.
bool writeImage(const Image& image, std::ostream& out);

/// True if the bytes start with the image magic number (whatever the name).
bool looksLikeImage(std::string_view bytes);

/// Decodes and verifies. Never trusts a count or an index from the file:
/// a truncated, corrupt or hostile file gets a diagnostic for the whole
/// of `file` (the name it is reported under), not undefined behaviour.
diag::Result<Image> loadImage(std::string_view bytes, const std::string& file = {});

std::uint32_t crc32(const std::uint8_t* data, std::size_t size);
/// The CRC of what `crc` was the CRC of, followed by `data` (crc32Update(0, ...) = crc32).
std::uint32_t crc32Update(std::uint32_t crc, const std::uint8_t* data, std::size_t size);

}  // namespace rs::vm
