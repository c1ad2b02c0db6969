#include "bench/adept_hour.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rs::bench {

std::string adeptHourProgram(int blocks) {
  const std::string path = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/adept_hour.rsp";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  std::string program = text.str();
  // The loop's test, as the example writes it: the one number to change.
  const std::string count = "JMPVAR PARTS < 600 ";
  const std::size_t at = program.find(count);
  if (at == std::string::npos || program.find(count, at + 1) != std::string::npos)
    throw std::runtime_error(path + " no longer has exactly one '" + count + "' line");
  program.replace(at, count.size(), fmt::format("JMPVAR PARTS < {} ", blocks));
  return program;
}

}  // namespace rs::bench
