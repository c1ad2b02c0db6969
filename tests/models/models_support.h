// Helpers for the description-language tests (tests/models): a scratch
// library directory, diagnostics as "file:line:col: message" strings with
// the directory stripped, and a scoped ROBOTSIM_PATH.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/description/library.h"
#include "tests/cli/cli_support.h"

namespace rs::testing {

/// Joins lines with '\n' (and a final one), so a test can count lines.
inline std::string lines(const std::vector<std::string>& ls) {
  std::string s;
  for (const std::string& l : ls) s += l + '\n';
  return s;
}

/// "file:line:col: message" for every diagnostic, with `dir/` removed from
/// file names so expectations stay short.
inline std::vector<std::string> diagnosticList(const std::vector<rs::diag::Diagnostic>& diags,
                                               const std::string& dir) {
  std::vector<std::string> out;
  for (const rs::diag::Diagnostic& d : diags) {
    std::string file = d.file;
    const std::string prefix = dir + "/";
    if (file.rfind(prefix, 0) == 0) file.erase(0, prefix.size());
    out.push_back(fmt::format("{}:{}:{}: {}{}", file, d.pos.line, d.pos.col,
                              d.severity == rs::diag::Severity::Error ? "" : "(not an error) ", d.message));
  }
  return out;
}

inline std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += i + '\n';
  return s;
}

/// Sets (or, with nullopt, unsets) ROBOTSIM_PATH; puts it back on exit.
class ScopedRobotsimPath {
 public:
  explicit ScopedRobotsimPath(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("ROBOTSIM_PATH")) old_ = std::string(old);
    if (value) ::setenv("ROBOTSIM_PATH", value->c_str(), 1);
    else ::unsetenv("ROBOTSIM_PATH");
  }
  ~ScopedRobotsimPath() {
    if (old_) ::setenv("ROBOTSIM_PATH", old_->c_str(), 1);
    else ::unsetenv("ROBOTSIM_PATH");
  }
  ScopedRobotsimPath(const ScopedRobotsimPath&) = delete;
  ScopedRobotsimPath& operator=(const ScopedRobotsimPath&) = delete;

 private:
  std::optional<std::string> old_;
};

/// The workcell of a whole `.rsd` text (its own OBJECT descriptions and the
/// WORKCELL block), read as `robotsim` reads one from a directory of the
/// library search path; fails the test, with the diagnostics, if it does not compile.
inline rs::workcell::Workcell workcellFromText(const std::string& text) {
  TempDir dir;
  dir.write("c.rsd", text);
  rs::compiler::Library lib(rs::compiler::librarySearchPath({dir.path().string()}));
  const auto cell = lib.workcell(dir.file("c.rsd"));
  for (const auto& d : lib.diagnostics()) INFO(d.message);
  REQUIRE(cell);
  return *cell;
}

}  // namespace rs::testing
