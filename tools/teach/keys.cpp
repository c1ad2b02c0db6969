#include "tools/teach/keys.h"

namespace rs::teach {

std::optional<KeyBinding> keyBinding(std::string_view key) {
  for (const KeyBinding& k : kKeys)
    if (k.key == key) return k;
  return std::nullopt;
}

std::string_view jogModeName(JogMode mode) {
  switch (mode) {
    case JogMode::Joint: return "joint";
    case JogMode::World: return "world";
    case JogMode::Tool: return "tool";
  }
  return "joint";
}

JogMode nextJogMode(JogMode mode) {
  return mode == JogMode::Joint ? JogMode::World : mode == JogMode::World ? JogMode::Tool : JogMode::Joint;
}

nlohmann::ordered_json jogDegreesJson() {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const std::int32_t step : {1, 10, 100}) j[std::to_string(step)] = jogDegrees(step);
  return j;
}

nlohmann::ordered_json keysJson() {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (const KeyBinding& k : kKeys) a.push_back({{"key", k.key}, {"action", k.name}, {"help", k.help}});
  return a;
}

}  // namespace rs::teach
