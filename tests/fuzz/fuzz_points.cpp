// libFuzzer target: any bytes as a program whose POINTS section teach
// edits (tools/teach/points_edit.h). Reading keeps every byte; every edit gives a
// text that reads back to the same rows and keeps every line but its own;
// nothing crashes or goes superlinear.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tools/teach/points_edit.h"

namespace {

void require(bool ok) {
  if (!ok) __builtin_trap();
}

// The text's line count (a final unterminated line counts).
std::size_t lineCount(std::string_view text) {
  std::size_t n = 0;
  for (std::size_t pos = 0; pos < text.size(); ++n) {
    const std::size_t nl = text.find('\n', pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
  }
  return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const rs::teach::PointsText original(bytes);
  require(original.text() == bytes);
  const std::vector<std::int32_t> values{1, -2, 30, -400, 5000};
  rs::teach::PointsText added = original;
  if (added.add("FUZZ_NEW", values).empty()) {
    require(added.points().back().name == "FUZZ_NEW" && added.points().back().values == values);
    require(rs::teach::PointsText(added.text()).text() == added.text());
    require(lineCount(added.text()) == lineCount(bytes) + (original.pointsLine() ? 1 : 2));
  }
  if (!original.points().empty()) {
    const std::string name = original.points().front().name;
    rs::teach::PointsText edited = original;
    if (edited.replace(name, values).empty()) require(lineCount(edited.text()) == lineCount(bytes));
    edited = original;
    if (edited.rename(name, "FUZZ_RENAMED").empty()) require(edited.find("FUZZ_RENAMED").has_value());
    edited = original;
    if (edited.remove(name).empty()) require(lineCount(edited.text()) + 1 == lineCount(bytes));
  }
  return 0;
}
