#include "tools/testrun/coverage.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "base/text.h"

namespace rs::testrun {

bool isBranch(const vm::Image& image, std::uint32_t i) {
  return vm::has(image.code[i].op, vm::kBranches);
}

CoverageCounter::CoverageCounter(std::shared_ptr<const vm::Image> image) {
  const std::size_t n = image->code.size();
  coverage_.image = std::move(image);
  coverage_.runs.assign(n, 0);
  coverage_.jumped.assign(n, 0);
  coverage_.fellThrough.assign(n, 0);
}

bool CoverageCounter::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  ++coverage_.runs[index];
  if (isBranch(*coverage_.image, index)) {
    // A jump to the next instruction counts as a jump.
    if (vm.pc() == static_cast<std::uint32_t>(coverage_.image->code[index].d)) ++coverage_.jumped[index];
    else ++coverage_.fellThrough[index];
  }
  return false;
}

namespace {

struct LineCount {
  std::uint64_t runs = 0;
  std::uint64_t jumped = 0, fellThrough = 0;
  bool branch = false;
};

std::map<std::uint32_t, LineCount> byLine(const Coverage& c) {
  std::map<std::uint32_t, LineCount> lines;
  for (std::uint32_t i = 0; i < c.runs.size(); ++i) {
    LineCount& l = lines[c.image->lines[i]];
    l.runs = std::max(l.runs, c.runs[i]);
    if (isBranch(*c.image, i)) l.branch = true, l.jumped += c.jumped[i], l.fellThrough += c.fellThrough[i];
  }
  return lines;
}

}  // namespace

namespace {

// A source line as a terminal may show it: control characters escaped
// (base::safeText), tabs kept for the indentation.
std::string printableLine(std::string_view line) {
  std::string out;
  for (std::size_t from = 0; from <= line.size();) {
    const std::size_t tab = std::min(line.find('\t', from), line.size());
    out += base::safeText(line.substr(from, tab - from));
    if (tab < line.size()) out += '\t';
    from = tab + 1;
  }
  return out;
}

}  // namespace

std::string annotatedListing(const diag::SourceFile& source, const Coverage& coverage) {
  const std::map<std::uint32_t, LineCount> lines = byLine(coverage);
  std::size_t ran = 0, branches = 0, directions = 0;
  for (const auto& [n, l] : lines) {
    ran += l.runs > 0;
    if (l.branch) branches += 2, directions += (l.jumped > 0) + (l.fellThrough > 0);
  }
  std::string out = fmt::format("coverage of {}: {} of {} instruction lines ran, {} of {} jump directions taken\n",
                                base::safeText(source.name()), ran, lines.size(), directions, branches);
  for (std::uint32_t n = 1; n <= source.lineCount(); ++n) {
    const auto it = lines.find(n);
    std::string count = it == lines.end() ? "-" : it->second.runs ? std::to_string(it->second.runs) : "#####";
    std::string ways;
    if (it != lines.end() && it->second.branch)
      ways = fmt::format("   [jumped {}, went on {}]", it->second.jumped, it->second.fellThrough);
    std::string row = fmt::format("{:>9}: {:>5}: {}{}", count, n, printableLine(source.line(n)), ways);
    out += row + '\n';
  }
  return out;
}

std::string lcovRecord(const std::string& file, const Coverage& coverage) {
  const std::map<std::uint32_t, LineCount> lines = byLine(coverage);
  std::string out = fmt::format("TN:\nSF:{}\n", file);
  std::size_t hit = 0, branches = 0, branchesHit = 0;
  for (const auto& [n, l] : lines)
    if (l.branch) {
      // A block per line, two branches: 0 jumps, 1 goes on ("-": the line never ran).
      const bool ran = l.runs > 0;
      const auto taken = [ran](std::uint64_t k) { return ran ? std::to_string(k) : std::string("-"); };
      out += fmt::format("BRDA:{},0,0,{}\nBRDA:{},0,1,{}\n", n, taken(l.jumped), n, taken(l.fellThrough));
      branches += 2;
      branchesHit += (l.jumped > 0) + (l.fellThrough > 0);
    }
  for (const auto& [n, l] : lines) {
    out += fmt::format("DA:{},{}\n", n, l.runs);
    hit += l.runs > 0;
  }
  out += fmt::format("BRF:{}\nBRH:{}\nLF:{}\nLH:{}\nend_of_record\n", branches, branchesHit, lines.size(), hit);
  return out;
}

std::vector<ProgramCoverage> mergedCoverage(const std::vector<std::vector<ProgramCoverage>>& tests) {
  // A cell's PROGRAM and a scenario's `program` line may name one file by two paths.
  const auto key = [](const std::string& file) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::weakly_canonical(file, ec);
    return ec ? file : p.string();
  };
  std::vector<ProgramCoverage> out;
  std::vector<std::string> keys;
  for (const std::vector<ProgramCoverage>& test : tests)
    for (const ProgramCoverage& c : test) {
      const std::string k = key(c.file);
      std::size_t i = 0;
      while (i < out.size() && !(keys[i] == k && out[i].counts.image && c.counts.image &&
                                 out[i].counts.image->code == c.counts.image->code))
        ++i;
      if (i == out.size()) {
        out.push_back(c), keys.push_back(k);
        continue;
      }
      ProgramCoverage* same = &out[i];
      for (std::size_t i = 0; i < c.counts.runs.size(); ++i) {
        same->counts.runs[i] += c.counts.runs[i];
        same->counts.jumped[i] += c.counts.jumped[i];
        same->counts.fellThrough[i] += c.counts.fellThrough[i];
      }
    }
  return out;
}

}  // namespace rs::testrun
