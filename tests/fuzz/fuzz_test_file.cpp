// libFuzzer target: any bytes as the test runner's text, read both ways: as
// a program's `; test:` / `; expect:` comments and as a scenario file
// (.rstest). Every bad line gets a positioned error.
#include <cstdint>
#include <string>

#include "diag/source_file.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/scenario_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  (void)rs::testrun::parseExpectations(rs::diag::SourceFile("fuzz.rsp", text));
  (void)rs::testrun::parseScenarioFile(rs::diag::SourceFile("fuzz.rstest", text));
  return 0;
}
