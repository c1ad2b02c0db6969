#include "tools/teach/page.h"

#include <fmt/format.h>

#include <filesystem>

#include "runtime/render/animation.h"
#include "runtime/render/camera.h"
#include "tools/teach/keys.h"

namespace rs::teach {

namespace {

std::string pageHtml(const workcell::Workcell& cell, const std::string& program, bool readOnly) {
  render::Camera camera;  // the stills' default camera, as `animate` starts with
  const std::string name = std::filesystem::path(program).filename().string();
  nlohmann::ordered_json model = {{"title", fmt::format("{} {} on {}", readOnly ? "debug" : "teach", name, cell.name)},
                                  {"cell", cell.name},
                                  {"program", program},
                                  {"readOnly", readOnly}};
  const nlohmann::ordered_json drawing = render::cellDrawing(cell, camera);
  for (const auto& [key, value] : drawing.items()) model[key] = value;
  model["keys"] = keysJson();
  model["jogDegrees"] = jogDegreesJson();
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html +=
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "style-src 'unsafe-inline'; script-src 'unsafe-inline'; connect-src 'self'; img-src data:\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += "<title>robotsim: " + render::escapeHtml(model["title"].get<std::string>()) + "</title>\n<style>\n";
  html += render::pageStyle();
  html += page::kStyle;
  html += "</style>\n</head>\n<body>\n";
  html += page::kBody;
  html += "<script type=\"application/json\" id=\"robotsim-model\">";
  html += render::scriptSafeJson(model);
  html += "</script>\n<script>\n";
  html += render::drawScript();
  html += "</script>\n<script>\n";
  html += page::kScript;
  html += "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace

std::string teachPageHtml(const workcell::Workcell& cell, const std::string& program) {
  return pageHtml(cell, program, false);
}

std::string runViewPageHtml(const workcell::Workcell& cell, const std::string& program) {
  return pageHtml(cell, program, true);
}

}  // namespace rs::teach
