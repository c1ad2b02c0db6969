// Which lines of a program its tests ran, how often, and which way each
// conditional jump (JMPIN, JMPVAR) went: `robotsim test --coverage` prints
// it as an annotated listing and `--lcov FILE` writes it as an LCOV
// tracefile (the format of geninfo(1)), which `genhtml` turns into pages.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "diag/source_file.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::testrun {

struct Coverage {
  std::shared_ptr<const vm::Image> image;
  std::vector<std::uint64_t> runs;      ///< per instruction: times executed
  std::vector<std::uint64_t> jumped;    ///< per conditional jump: times it jumped
  std::vector<std::uint64_t> fellThrough;  ///< ... and times it went on to the next instruction
};

/// What one program ran in a test (a cell's test runs several): the
/// program's file, its text (for the listing) and the counts.
struct ProgramCoverage {
  std::string file;
  std::shared_ptr<const diag::SourceFile> source;
  Coverage counts;
};

/// The programs of `tests`, each once, in the order they first appear, the
/// counts of every test that ran it summed (the same file compiled to
/// another image, on another cell, is listed again).
std::vector<ProgramCoverage> mergedCoverage(const std::vector<std::vector<ProgramCoverage>>& tests);

/// Counts every step of a run into a Coverage (sized for its image).
class CoverageCounter final : public vm::StepObserver {
 public:
  explicit CoverageCounter(std::shared_ptr<const vm::Image> image);
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  const Coverage& coverage() const { return coverage_; }

 private:
  Coverage coverage_;
};

/// Whether instruction `i` is a conditional jump (it has two ways to go).
bool isBranch(const vm::Image& image, std::uint32_t i);

/// The program's source with, before each line, how often it ran ("#####"
/// for an instruction line that never ran) and, for a conditional jump, how
/// often it jumped and went on; a first line sums it up.
std::string annotatedListing(const diag::SourceFile& source, const Coverage& coverage);

/// One LCOV record (TN, SF, DA, BRDA, LF, LH, BRF, BRH, end_of_record).
std::string lcovRecord(const std::string& file, const Coverage& coverage);

}  // namespace rs::testrun
