#include "tools/testrun/golden_trace.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "launch/confined_path.h"

namespace rs::testrun {

namespace fs = std::filesystem;
using launch::isInside;
using launch::resolve;

namespace {

// The most of a differing line a message quotes.
constexpr std::size_t kQuotedLine = 4096;

}  // namespace

bool staysUnderFolder(std::string_view name) {
  const fs::path p(name);
  if (p.empty() || p.is_absolute() || p.has_root_name() || p.has_root_directory()) return false;
  const fs::path normal = p.lexically_normal();
  return !normal.empty() && *normal.begin() != ".." && normal != ".";
}

diag::Result<std::string> goldenFile(const std::string& testFile, const std::string& name) {
  const fs::path folder = fs::path(testFile).parent_path();
  std::string path = (folder / name).lexically_normal().string();
  if (!staysUnderFolder(name))
    return diag::refusal(fmt::format(
        "the golden trace '{}' is not under the test's folder: name it relative to the folder, "
        "without '..' leading out",
        name));
  const diag::Result<fs::path> home = resolve(folder.empty() ? fs::path(".") : folder, true);
  const diag::Result<fs::path> target = resolve(path, false);
  if (!home || !target)
    return diag::refusal(fmt::format("cannot follow the golden trace {}: {}", path,
                                     home ? target.failure().message : home.failure().message));
  if (!isInside(*home, *target))
    return diag::refusal(
        fmt::format("the golden trace {} leads out of the test's folder (to {}): refused", path, target->string()));
  return path;
}

std::string TraceComparer::expected() const {
  const std::size_t end = golden_.find('\n', lineStart_);
  const std::string_view line = golden_.substr(lineStart_, end == std::string_view::npos ? end : end - lineStart_);
  return std::string(line.substr(0, kQuotedLine));
}

std::string TraceComparer::got() const { return got_; }

// The trace's differing line: what matched of it, then what came.
void TraceComparer::differAt(char c) {
  differs_ = true;
  got_.assign(golden_.substr(lineStart_, std::min(pos_ - lineStart_, kQuotedLine)));
  capturing_ = c != '\n';
  if (capturing_ && got_.size() < kQuotedLine) got_ += c;
}

std::streamsize TraceComparer::xsputn(const char* s, std::streamsize n) {
  const auto size = static_cast<std::size_t>(n);
  std::size_t i = 0;
  if (!differs_) {  // the whole piece at once while it matches
    const std::size_t same = std::min(size, golden_.size() - pos_);
    // (memcmp's pointers may not be null, even for no bytes: a missing
    // golden file is an empty view)
    if (same == 0 || std::memcmp(s, golden_.data() + pos_, same) == 0)
      i = same;
    else
      while (s[i] == golden_[pos_ + i]) ++i;
    for (std::size_t k = 0; k < i; ++k)
      if (s[k] == '\n') ++line_, lineStart_ = pos_ + k + 1;
    pos_ += i;
    if (i < size) differAt(s[i++]);
  }
  for (; i < size && capturing_; ++i) {
    if (s[i] == '\n')
      capturing_ = false;
    else if (got_.size() < kQuotedLine)
      got_ += s[i];
  }
  return n;
}

TraceComparer::int_type TraceComparer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  xsputn(&ch, 1);
  return c;
}

}  // namespace rs::testrun
