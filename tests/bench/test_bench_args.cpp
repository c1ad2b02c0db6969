// The small benchmark programs' command line (bench/bench_args.h): counts
// must be whole numbers from 1 up, --help and bad input stop the program
// (0 and 2), --smoke picks the smoke sizes. The programs themselves run in
// the bench-smoke tests (bench/CMakeLists.txt).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_args.h"

namespace {

using rs::bench::BenchArguments;
using rs::bench::CountArgument;

constexpr CountArgument kArgsUnderTest[] = {{"CALLS", "calls per run", 5'000'000, 1'000}, {"REPS", "runs", 5, 1}};

// What the program printed, on standard output and on standard error.
struct Printed {
  std::string out, err;
};

BenchArguments parsedArgs(std::vector<std::string> words, Printed* printed = nullptr) {
  std::string name = "x_bench";
  std::vector<char*> argv{name.data()};
  for (std::string& w : words) argv.push_back(w.data());
  std::ostringstream out, err;
  BenchArguments parsed = rs::bench::parseBenchArguments(static_cast<int>(argv.size()), argv.data(), "x_bench", "About.",
                                                         kArgsUnderTest, out, err);
  if (printed) *printed = {out.str(), err.str()};
  return parsed;
}

}  // namespace

TEST_CASE("a benchmark count is a whole number from 1 to a billion, digits only", "[bench]") {
  CHECK(rs::bench::parseCount("1") == 1);
  CHECK(rs::bench::parseCount("5000000") == 5'000'000);
  CHECK(rs::bench::parseCount("1000000000") == 1'000'000'000);
  for (const char* bad : {"", "0", "-1", "+5", " 5", "5 ", "5x", "1e6", "0x10", "1000000001", "99999999999999999999",
                          "--help", "-nan"})
    CHECK_FALSE(rs::bench::parseCount(bad));
}

TEST_CASE("a benchmark's counts: defaults, --smoke, given", "[bench]") {
  const BenchArguments none = parsedArgs({});
  CHECK_FALSE(none.exitCode);
  CHECK(none.counts == std::vector<long>{5'000'000, 5});
  CHECK_FALSE(none.smoke);
  const BenchArguments smoke = parsedArgs({"--smoke"});
  CHECK(smoke.counts == std::vector<long>{1'000, 1});
  CHECK(smoke.smoke);
  // Numbers given win over either size; those not given keep theirs.
  CHECK(parsedArgs({"--smoke", "20"}).counts == std::vector<long>{20, 1});
  CHECK(parsedArgs({"300", "7"}).counts == std::vector<long>{300, 7});
}

TEST_CASE("a benchmark's --help and bad command lines stop it", "[bench]") {
  Printed printed;
  CHECK(parsedArgs({"--help"}, &printed).exitCode == 0);
  CHECK(printed.out == rs::bench::benchUsage("x_bench", "About.", kArgsUnderTest));
  CHECK(printed.err.empty());
  CHECK(parsedArgs({"abc"}, &printed).exitCode == 2);
  CHECK(printed.out.empty());
  CHECK(printed.err == "x_bench: error: CALLS must be a whole number from 1 to 1000000000, not 'abc'\n" +
                           rs::bench::benchUsage("x_bench", "About.", kArgsUnderTest));
  CHECK(parsedArgs({"100", "-h"}).exitCode == 0);
  CHECK(parsedArgs({"0"}).exitCode == 2);     // read as 0 calls once, which printed -nan
  CHECK(parsedArgs({"abc"}).exitCode == 2);
  CHECK(parsedArgs({"1", "2", "3"}).exitCode == 2);  // more numbers than counts
  CHECK(parsedArgs({"--calls", "5"}).exitCode == 2);
}

TEST_CASE("a benchmark's usage names every count with both sizes", "[bench]") {
  const std::string usage = rs::bench::benchUsage("x_bench", "About.", kArgsUnderTest);
  CHECK(usage.starts_with("usage: x_bench [--smoke] [CALLS [REPS]]\nAbout.\n"));
  CHECK(usage.find("CALLS    calls per run (default 5000000; with --smoke 1000)") != std::string::npos);
  CHECK(usage.find("REPS     runs (default 5; with --smoke 1)") != std::string::npos);
}
