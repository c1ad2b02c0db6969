// The HTML pages' fixed parts: the style sheet and the drawing script
// every page shares (page_style.cpp, page_draw_script.cpp), and the
// animation's body and script (page_style.cpp, page_script.cpp).
// animation.cpp puts them around the model of a run; the teach pendant's
// page (tools/teach/) around a cell's drawing and its own panel.
#pragma once

#include <string_view>

namespace rs::render::page {

extern const std::string_view kStyle;
extern const std::string_view kBody;
extern const std::string_view kScript;
/// robotsimDrawing(model, canvas): kinematics, camera, palette, mouse.
extern const std::string_view kDrawScript;

}  // namespace rs::render::page
