// What a test needs to know about the build it runs in: its robotsim
// command, its generated docs, whether that command is linked statically.
// These are the only facts that differ between the Release build and the
// sanitizer build; they live in one small file compiled in each build
// (build_facts.cpp), so the test files themselves compile once and serve
// both (tests/CMakeLists.txt, ROBOTSIM_TEST_OBJECTS_FROM).
#pragma once

namespace rs::testing {

/// The robotsim command of this build (build/robotsim, build-asan/robotsim).
const char* robotsimBinary();
/// This build's generated man pages and completions (robotsim_docs).
const char* generatedDocs();
/// Whether that command is linked statically (ROBOTSIM_STATIC).
bool staticCommand();

}  // namespace rs::testing
