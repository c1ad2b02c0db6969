// Helpers for tests that drive the whole `robotsim` command in-process
// (rs::cli::runCommand) and need scratch files.
#pragma once

#include <unistd.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "tools/cli/lib/app.h"

namespace rs::testing {

struct CliResult {
  int code = -1;
  std::string out;
  std::string err;
};

/// Runs `robotsim ARGS...` in this process and captures both streams.
inline CliResult runCli(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"robotsim"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  std::ostringstream out, err;
  CliResult r;
  r.code = rs::cli::runCommand(static_cast<int>(argv.size() - 1), argv.data(), out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

/// A fresh directory, removed with everything in it when it goes away.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("robotsim-tests-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Writes `bytes` to NAME in the directory and returns its full path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path p = path_ / name;
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string readBytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

/// With ROBOTSIM_UPDATE_GOLDEN set, writes `actual` to the golden file
/// `path` and fails the check, so that an update run can never pass as a
/// test run; returns true then. Otherwise returns false (compare as usual).
inline bool rewriteGolden(const std::string& path, const std::string& actual) {
  if (!std::getenv("ROBOTSIM_UPDATE_GOLDEN")) return false;
  std::ofstream(path, std::ios::binary) << actual;
  FAIL_CHECK("rewrote " << path << ": review the diff, then run again without ROBOTSIM_UPDATE_GOLDEN");
  return true;
}

}  // namespace rs::testing
