#include "teach/keys.h"

namespace rs::teach {

std::optional<KeyBinding> keyBinding(std::string_view key) {
  for (const KeyBinding& k : kKeys)
    if (k.key == key) return k;
  return std::nullopt;
}

nlohmann::ordered_json keysJson() {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (const KeyBinding& k : kKeys) a.push_back({{"key", k.key}, {"action", k.name}, {"help", k.help}});
  return a;
}

}  // namespace rs::teach
