// The HTML animation's fixed parts: its style sheet, its body and its
// script (page_style.cpp, page_script.cpp). animation.cpp puts them around
// the model of a run.
#pragma once

#include <string_view>

namespace rs::render::page {

extern const std::string_view kStyle;
extern const std::string_view kBody;
extern const std::string_view kScript;

}  // namespace rs::render::page
