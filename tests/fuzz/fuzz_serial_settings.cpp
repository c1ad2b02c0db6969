// libFuzzer target: any bytes as a serial settings file (--serial-config),
// for both dialects' defaults. Errors are diagnostics with line and column.
#include <cstdint>
#include <string_view>

#include "runtime/rhino/settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const rs::rhino::Dialect d : {rs::rhino::Dialect::Mark3, rs::rhino::Dialect::Mark4}) {
    (void)rs::rhino::applySettingsText(rs::rhino::defaultSettings(d), text, "fuzz.cfg");
  }
  return 0;
}
