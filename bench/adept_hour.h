// examples/adept_hour.rsp, the hour of production on adept-cell, as the
// benchmark and the tests run it: read from the source tree (one text,
// the example's), with its loop's count of blocks set to `blocks` (the
// file's 600 is the hour). Throws std::runtime_error when the file cannot
// be read or no longer has its `JMPVAR PARTS < 600` line.
#pragma once

#include <string>

namespace rs::bench {

std::string adeptHourProgram(int blocks);

}  // namespace rs::bench
