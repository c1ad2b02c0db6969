#include "runtime/render/draw.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <memory>

#include "runtime/render/palette.h"
#include "runtime/render/png.h"

namespace rs::render {

namespace {

constexpr double kLegendSize = 13.0;    // font size, pixels
constexpr double kLegendMargin = 10.0;  // pixels

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

void setColor(cairo_t* cr, Rgb c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

// For pixels, each line is its own stroke, in the description's order:
// cairo's tessellator then never holds thousands of edges at once (for
// 5,000 lines, a quarter of the time of one path per colour; see
// docs/render.md). For SVG, one path per colour keeps the file small. Butt
// caps: square ones cost half as much again.
// `colliding`: the pass of the lines of parts in a collision (drawn last,
// wider), or of the others.
void drawLines(cairo_t* cr, const Picture& picture, bool pathPerColor, bool colliding) {
  cairo_set_line_width(cr, colliding ? kCollidingLineWidth : kLineWidth);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  if (pathPerColor) {
    std::array<std::vector<const Line2*>, 16> byColor;
    for (const Line2& l : picture.lines)
      if (l.colliding == colliding) byColor[static_cast<std::size_t>(l.color) & 15].push_back(&l);
    for (std::size_t c = 0; c < byColor.size(); ++c) {
      if (byColor[c].empty()) continue;
      for (const Line2* l : byColor[c]) {
        cairo_move_to(cr, l->a.x(), l->a.y());
        cairo_line_to(cr, l->b.x(), l->b.y());
      }
      setColor(cr, kEga[c]);
      cairo_stroke(cr);
    }
    return;
  }
  int color = -1;
  for (const Line2& l : picture.lines) {
    if (l.colliding != colliding) continue;
    if (const int c = static_cast<int>(l.color) & 15; c != color) {
      setColor(cr, kEga[static_cast<std::size_t>(c)]);
      color = c;
    }
    cairo_move_to(cr, l.a.x(), l.a.y());
    cairo_line_to(cr, l.b.x(), l.b.y());
    cairo_stroke(cr);
  }
}

// The tool centre point: a white ring with a cross.
void drawTools(cairo_t* cr, const Picture& picture) {
  cairo_set_line_width(cr, kToolLineWidth);
  for (const ToolMark& t : picture.tools) {
    const double x = t.at.x(), y = t.at.y(), r = kToolRadius;
    cairo_new_sub_path(cr);
    cairo_arc(cr, x, y, r, 0, 6.283185307179586);
    cairo_move_to(cr, x - 2 * r, y);
    cairo_line_to(cr, x + 2 * r, y);
    cairo_move_to(cr, x, y - 2 * r);
    cairo_line_to(cr, x, y + 2 * r);
  }
  setColor(cr, rgb(kToolColor));
  cairo_stroke(cr);
}

// The tool's path: one polyline per stretch, under the tool marks.
void drawPath(cairo_t* cr, const Picture& picture) {
  if (picture.path.empty()) return;
  cairo_set_line_width(cr, kPathLineWidth);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const std::vector<Eigen::Vector2d>& stretch : picture.path) {
    if (stretch.empty()) continue;
    cairo_move_to(cr, stretch[0].x(), stretch[0].y());
    for (std::size_t i = 1; i < stretch.size(); ++i) cairo_line_to(cr, stretch[i].x(), stretch[i].y());
  }
  setColor(cr, rgb(kPathColor));
  cairo_stroke(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
}

void drawLegend(cairo_t* cr, const Picture& picture) {
  if (picture.legend.empty()) return;
  cairo_select_font_face(cr, "monospace", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLegendSize);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  double width = 0;
  for (const std::string& line : picture.legend) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, line.c_str(), &ext);
    width = std::max(width, ext.x_advance);
  }
  const double pad = 6, lineHeight = font.height;
  cairo_rectangle(cr, kLegendMargin - pad, kLegendMargin - pad, width + 2 * pad,
                  lineHeight * static_cast<double>(picture.legend.size()) + 2 * pad);
  setColor(cr, kBackground, 0.8);
  cairo_fill(cr);
  setColor(cr, kEga[7]);
  double y = kLegendMargin + font.ascent;
  for (const std::string& line : picture.legend) {
    cairo_move_to(cr, kLegendMargin, y);
    cairo_show_text(cr, line.c_str());
    y += lineHeight;
  }
}

void draw(cairo_t* cr, const Picture& picture, bool vector) {
  setColor(cr, kBackground);
  cairo_paint(cr);
  drawLines(cr, picture, vector, false);
  drawLines(cr, picture, vector, true);
  drawPath(cr, picture);
  drawTools(cr, picture);
  drawLegend(cr, picture);
}

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
  out->insert(out->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}

struct Reader {
  const std::vector<std::uint8_t>* in;
  std::size_t at = 0;
};

cairo_status_t readBytes(void* closure, unsigned char* data, unsigned int length) {
  auto* r = static_cast<Reader*>(closure);
  if (r->in->size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, r->in->data() + r->at, length);
  r->at += length;
  return CAIRO_STATUS_SUCCESS;
}

diag::Diagnostic failed(cairo_status_t status) {
  return diag::refusal(std::string("cairo: ") + cairo_status_to_string(status));
}

}  // namespace

std::optional<ImageFormat> formatFromPath(std::string_view path) {
  if (path.size() < 4) return std::nullopt;
  std::string ext(path.substr(path.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".svg") return ImageFormat::Svg;
  return std::nullopt;
}

diag::Result<std::vector<std::uint8_t>> encodeDrawing(int width, int height, ImageFormat format,
                                                      const std::function<void(cairo_t*)>& paint) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    return diag::refusal("image size out of range (1..16384 pixels)");
  std::vector<std::uint8_t> bytes;
  Surface surface(format == ImageFormat::Png ? cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)
                                             : cairo_svg_surface_create_for_stream(appendBytes, &bytes, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return failed(cairo_surface_status(surface.get()));
  {
    Context cr(cairo_create(surface.get()));
    paint(cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) return failed(cairo_status(cr.get()));
  }
  if (format == ImageFormat::Png) {
    cairo_surface_flush(surface.get());
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    bytes = encodePng(width, height, [&](int y, std::uint8_t* rgb) {
      const unsigned char* row = data + static_cast<std::ptrdiff_t>(y) * stride;
      for (int x = 0; x < width; ++x, rgb += 3) {
        std::uint32_t px;
        std::memcpy(&px, row + 4 * x, 4);  // native-endian 0x00RRGGBB
        rgb[0] = static_cast<std::uint8_t>(px >> 16);
        rgb[1] = static_cast<std::uint8_t>(px >> 8);
        rgb[2] = static_cast<std::uint8_t>(px);
      }
    });
    if (bytes.empty()) return diag::refusal("zlib: cannot compress the image");
  } else {
    cairo_surface_finish(surface.get());
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return failed(cairo_surface_status(surface.get()));
  }
  return bytes;
}

diag::Result<std::vector<std::uint8_t>> encodePicture(const Picture& picture, ImageFormat format) {
  return encodeDrawing(picture.width, picture.height, format,
                       [&](cairo_t* cr) { draw(cr, picture, format == ImageFormat::Svg); });
}

diag::Result<Decoded> decodePng(const std::vector<std::uint8_t>& png) {
  Reader reader{&png};
  Surface surface(cairo_image_surface_create_from_png_stream(readBytes, &reader));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return failed(cairo_surface_status(surface.get()));
  cairo_surface_flush(surface.get());
  const cairo_format_t format = cairo_image_surface_get_format(surface.get());
  if (format != CAIRO_FORMAT_RGB24 && format != CAIRO_FORMAT_ARGB32)
    return diag::refusal("unsupported PNG pixel format");
  Decoded out;
  out.width = cairo_image_surface_get_width(surface.get());
  out.height = cairo_image_surface_get_height(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  out.rgb.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 3);
  std::size_t k = 0;
  for (int y = 0; y < out.height; ++y) {
    const unsigned char* row = data + static_cast<std::ptrdiff_t>(y) * stride;
    for (int x = 0; x < out.width; ++x) {
      std::uint32_t px;
      std::memcpy(&px, row + 4 * x, 4);  // native-endian 0xAARRGGBB
      out.rgb[k++] = static_cast<std::uint8_t>(px >> 16);
      out.rgb[k++] = static_cast<std::uint8_t>(px >> 8);
      out.rgb[k++] = static_cast<std::uint8_t>(px);
    }
  }
  return out;
}

}  // namespace rs::render

// fontconfig, behind cairo's text, keeps its caches for the life of the
// process by design; LeakSanitizer would report them at the exit of every
// program that draws a legend. (Read only when LeakSanitizer is linked in.)
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }
// ...and says nothing of them at exit: "Suppressions used:" on stderr would
// make a drawing command's output differ from the same command's elsewhere.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
