// The command line of the small benchmark programs (kinematics_bench,
// ik_bench, describe_bench, teach_bench, collision_bench): a few whole
// numbers in a fixed order, each with a full size (what `make bench` runs)
// and a smoke size (`--smoke`: what the test suite runs, to see that the
// program still runs and prints; docs/performance.md). `--help` prints the
// usage; anything else that is not a whole number from 1 up is refused with the
// usage, so `ik_bench --help` can no longer read as 0 calls.
#pragma once

#include <iostream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rs::bench {

/// One positional count: its name in the usage, what it is, its sizes.
struct CountArgument {
  std::string_view name;     // "CALLS"
  std::string_view meaning;  // "calls per run"
  long full = 1;             // when not given
  long smoke = 1;            // when not given, with --smoke
};

struct BenchArguments {
  std::vector<long> counts;  // one per CountArgument, in order
  bool smoke = false;
  /// Set when the program must exit at once with this code: 0 after
  /// --help, 2 after a bad command line (the usage is printed either way).
  std::optional<int> exitCode;
  long operator[](std::size_t i) const { return counts.at(i); }
};

/// Reads `[--smoke] [COUNT...]` (counts given override their sizes).
/// `program` names the program in the usage, `about` says in one line
/// what it measures. The usage goes to `out` after --help, the error and
/// the usage to `err` after a bad command line.
BenchArguments parseBenchArguments(int argc, char** argv, std::string_view program, std::string_view about,
                                   std::span<const CountArgument> counts, std::ostream& out = std::cout,
                                   std::ostream& err = std::cerr);

/// The usage text parseBenchArguments prints.
std::string benchUsage(std::string_view program, std::string_view about, std::span<const CountArgument> counts);

/// The largest count taken (it fits in an int, which repetitions are).
inline constexpr long kMaxCount = 1'000'000'000;

/// A whole number from 1 to kMaxCount written in decimal digits, nothing
/// else around it (no sign, no spaces); nullopt otherwise.
std::optional<long> parseCount(std::string_view text);

}  // namespace rs::bench
