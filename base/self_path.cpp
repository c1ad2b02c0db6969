#include "base/self_path.h"

#include <system_error>

namespace rs::base {

std::filesystem::path runningExecutable() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self;
}

}  // namespace rs::base
