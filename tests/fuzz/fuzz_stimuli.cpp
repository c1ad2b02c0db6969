// libFuzzer target: any bytes as a stimuli file (.stim). Every bad line
// gets a positioned error; nothing crashes or goes superlinear.
#include <cstdint>
#include <string_view>

#include "compiler/stimuli/stimuli.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)rs::stimuli::parseStimuli(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.stim");
  return 0;
}
