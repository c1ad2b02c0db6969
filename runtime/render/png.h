// Writing PNG files: cairo draws the picture, this packs its pixels. Why
// not cairo_surface_write_to_png: it compresses at zlib's default level
// with adaptive filters, which took 35 ms of a 1024x768 still's 50 ms;
// level 1 without filters takes a quarter of that and, on wireframes
// (mostly background), makes files of about the same size.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace rs::render {

/// Writes row y (0 = top) of the image as width·3 bytes R, G, B.
using PngRowFiller = std::function<void(int y, std::uint8_t* rgb)>;

/// A PNG file (8-bit RGB, no interlace). Empty if zlib fails or the size is
/// out of range (1..65535 pixels a side).
std::vector<std::uint8_t> encodePng(int width, int height, const PngRowFiller& fillRow);

}  // namespace rs::render
