// Drawing a Picture with cairo: one drawing code for PNG and SVG (cairo
// rasterises with anti-aliasing and writes both). The bytes come back in
// memory; the caller writes the file (all or nothing).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "runtime/render/picture.h"

typedef struct _cairo cairo_t;  // cairo.h's, so that this header needs none of cairo's

namespace rs::render {

/// The tool centre point's mark: a ring of this radius (pixels) with a
/// cross twice as long, stroked this wide in this colour.
inline constexpr double kToolRadius = 5.0;
inline constexpr double kToolLineWidth = 1.5;
inline constexpr workcell::Color kToolColor = workcell::Color::White;

/// Lines are stroked this wide (pixels); the lines of a part in a collision
/// (Line2::colliding) twice as wide, over the others, so that they stand
/// out from any part drawn in its own colour, a red one included.
inline constexpr double kLineWidth = 1.25;
inline constexpr double kCollidingLineWidth = 2.5;

/// The tool's path (`render --path`) is stroked this wide, in kPathColor.
inline constexpr double kPathLineWidth = 1.5;

enum class ImageFormat : std::uint8_t { Png, Svg };

/// From the file name: ".png" or ".svg" (any case); nothing otherwise.
std::optional<ImageFormat> formatFromPath(std::string_view path);

/// The picture as a PNG or SVG file's bytes (never empty), or why not (a
/// size out of range, cairo's or zlib's refusal) as a failure with no
/// place: the caller names the output file.
diag::Result<std::vector<std::uint8_t>> encodePicture(const Picture& picture, ImageFormat format);

/// What `paint` draws on a `width` x `height` cairo surface (1..16384
/// pixels), as PNG or SVG bytes, or why not: the one encoder of pictures
/// and charts.
diag::Result<std::vector<std::uint8_t>> encodeDrawing(int width, int height, ImageFormat format,
                                                      const std::function<void(cairo_t*)>& paint);

/// A decoded image, 8-bit RGB per pixel (for tests and tools).
struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width·height·3 bytes, rows top down
};

/// Decodes PNG bytes with cairo, or says why not (a failure with no place).
diag::Result<Decoded> decodePng(const std::vector<std::uint8_t>& png);

}  // namespace rs::render
