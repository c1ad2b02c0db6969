// A scenario file (`.rstest`): one program, several worlds, and what a
// teacher grades them by (docs/testing.md, "Scenario files", "Grading"):
//
//   program lab3.rsp          ; optional with --spec
//   test: cell gantry-cell    ; before the first scenario: shared by all
//
// On a cell of several robots (cell_test.h), `program LABEL FILE` gives a
// robot its program (before the first scenario, or in one), `test: robot
// LABEL` the robot the program under test runs on, and `LABEL.` before an
// expectation the robot it is about (`expect: feeder.output 1 on`).
//
//   scenario a part arrives
//   points 4                  ; all or nothing
//   test: input 1=ON@2
//   expect: finished
//
//   scenario no part
//   expect: deadlock          points 1   ; partial credit: each expectation
//   expect: output 1 off      points 2   ; that holds earns its points
//
// `;` starts a comment. Every bad line is a positioned diagnostic.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/source_file.h"
#include "tools/testrun/expectation.h"

namespace rs::testrun {

/// Points are counted in hundredths, so that 0.5 and 2.25 add up exactly.
using Hundredths = std::int64_t;
/// The most points a scenario or an expectation may give.
inline constexpr Hundredths kMaxPoints = 1'000'000 * 100;

/// One world a program is checked in: its settings and expectations.
struct Scenario {
  std::string name;
  diag::Pos pos;
  ParsedExpectations parsed;  ///< its own settings: settingsOf adds the shared ones
  /// `points N`: what passing it earns; none: its expectations' points, or 1.
  std::optional<Hundredths> points;
};

struct ScenarioFile {
  std::string program;
  diag::Pos programPos;
  TestSettings shared;  ///< the `test:` lines before the first scenario
  std::vector<Scenario> scenarios;
  std::vector<diag::Diagnostic> errors;  ///< every bad line
};

ScenarioFile parseScenarioFile(const diag::SourceFile& source);

/// What scenario `s` runs with: its own settings, and the shared ones it
/// does not set (its `input` lines come after the shared ones).
TestSettings settingsOf(const ScenarioFile& file, const Scenario& s);

/// The most scenario `s` can earn: its `points`, else the sum of its
/// expectations' points when any has some, else 1 point.
Hundredths maxPointsOf(const Scenario& s);

/// Whether `s` gives partial credit (points on its expectations).
bool partialCredit(const Scenario& s);

/// "4", "0.5", "2.25": points as a teacher wrote them.
std::string pointsText(Hundredths points);

}  // namespace rs::testrun
