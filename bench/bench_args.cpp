#include "bench/bench_args.h"

#include <fmt/format.h>

#include <charconv>

namespace rs::bench {

std::optional<long> parseCount(std::string_view text) {
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > kMaxCount) return std::nullopt;
  return value;
}

std::string benchUsage(std::string_view program, std::string_view about, std::span<const CountArgument> counts) {
  std::string names, nested;
  for (const CountArgument& c : counts) {
    names += fmt::format(" [{}", c.name);
    nested += "]";
  }
  std::string usage = fmt::format("usage: {} [--smoke]{}{}\n{}\n", program, names, nested, about);
  for (const CountArgument& c : counts)
    usage += fmt::format("  {:<8} {} (default {}; with --smoke {})\n", c.name, c.meaning, c.full, c.smoke);
  usage += "  --smoke  the smallest sizes: checks that the benchmark runs and prints, measures nothing\n";
  return usage;
}

BenchArguments parseBenchArguments(int argc, char** argv, std::string_view program, std::string_view about,
                                   std::span<const CountArgument> counts, std::ostream& out, std::ostream& err) {
  BenchArguments parsed;
  std::vector<std::string_view> given;
  const auto refuse = [&](const std::string& why) {
    err << program << ": error: " << why << "\n" << benchUsage(program, about, counts);
    parsed.exitCode = 2;
    return parsed;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      out << benchUsage(program, about, counts);
      parsed.exitCode = 0;
      return parsed;
    }
    if (arg == "--smoke")
      parsed.smoke = true;
    else if (arg.starts_with("--"))
      return refuse(fmt::format("unknown option '{}'", arg));
    else
      given.push_back(arg);
  }
  if (given.size() > counts.size())
    return refuse(fmt::format("{} numbers given, at most {} taken", given.size(), counts.size()));
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (i < given.size()) {
      const std::optional<long> n = parseCount(given[i]);
      if (!n)
        return refuse(fmt::format("{} must be a whole number from 1 to {}, not '{}'", counts[i].name, kMaxCount, given[i]));
      parsed.counts.push_back(*n);
    } else {
      parsed.counts.push_back(parsed.smoke ? counts[i].smoke : counts[i].full);
    }
  }
  return parsed;
}

}  // namespace rs::bench
