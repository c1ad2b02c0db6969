// `robotsim test [PATH ...]`: the programs under PATH checked against the
// expectations written in them (docs/testing.md), one line per test, a
// summary, JUnit XML or JSON for CI.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rs::cli {

struct TestOptions {
  std::vector<std::string> paths;
  std::vector<std::string> libDirs;
  std::string junit;   // --junit FILE
  std::string format = "text";
  std::string filter;  // --filter TEXT
  unsigned jobs = 0;   // -j N; 0: the cores
  std::string shard;   // --shard K/N
  bool coverage = false;  // --coverage
  std::string lcov;       // --lcov FILE
  std::string spec;       // --spec FILE.rstest: grade every program against it
  bool update = false;    // --update: write golden traces
  std::string collisions; // --collisions error|warn|off
};

void addTestOptions(CLI::App* cmd, TestOptions& o);
int testCommand(const TestOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
