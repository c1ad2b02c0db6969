#include "tests/support/build_facts.h"

namespace rs::testing {

const char* robotsimBinary() { return ROBOTSIM_BINARY; }
const char* generatedDocs() { return ROBOTSIM_GENERATED_DOCS; }
bool staticCommand() { return ROBOTSIM_STATIC_COMMAND; }

}  // namespace rs::testing
