// libFuzzer target: any bytes as a serial settings file (--serial-config),
// for both dialects' defaults. Errors are diagnostics with line and column.
#include <cstdint>
#include <string_view>

#include "runtime/serial/settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const rs::serial::Dialect d : {rs::serial::Dialect::Mark3, rs::serial::Dialect::Mark4}) {
    rs::serial::RhinoSettings settings = rs::serial::defaultSettings(d);
    (void)rs::serial::applySettingsText(settings, text, "fuzz.cfg");
  }
  return 0;
}
