// The teach pendant's web page: self-contained (every script and style
// inlined, no network but its own server), drawn with the animation
// page's shared drawing code and style sheet (runtime/render/page.h).
#pragma once

#include <string>
#include <string_view>

#include "model/workcell/model.h"

namespace rs::teach {

namespace page {
extern const std::string_view kStyle;   // page_body.cpp: the pendant's own rules
extern const std::string_view kBody;    // page_body.cpp
extern const std::string_view kScript;  // page_script.cpp
}  // namespace page

/// The page for teaching `program` on `cell`: its model is the cell's
/// drawing (render::cellDrawing), the title, the program's name and the
/// key map (keys.h); the state comes from the server.
std::string teachPageHtml(const workcell::Workcell& cell, const std::string& program);
/// The same page in its read-only mode, for a run stopped in the debugger
/// (run_source.h): the robot, objects, inputs, outputs and clock of the
/// stopped moment, no pendant controls (the model's "readOnly"); a key
/// that would move the robot gets the server's refusal shown.
std::string runViewPageHtml(const workcell::Workcell& cell, const std::string& program);

}  // namespace rs::teach
