#include "tools/cli/lib/grade_table.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/seconds.h"
#include "base/text.h"
#include "tools/testrun/scenario_file.h"

namespace rs::cli {

namespace {

std::string firstProblemOf(const testrun::TestResult& r) {
  const diag::Diagnostic& d = r.problems.front();
  return (r.name.empty() ? "" : "[" + r.name + "] ") +
         (d.pos.line ? fmt::format("{}:{}:{}: {}", d.file, d.pos.line, d.pos.col, d.message)
                     : fmt::format("{}: {}", d.file, d.message));
}

// The scenarios of the spec: those of the row that has the most (a row that
// could not be graded, a refused link, has none).
const GradeRow* fullest(const std::vector<GradeRow>& rows) {
  const GradeRow* best = nullptr;
  for (const GradeRow& r : rows)
    if (!best || r.scenarios.size() > best->scenarios.size()) best = &r;
  return best;
}

std::string quote(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string pointsOutOf(std::int64_t points, std::int64_t most) {
  return fmt::format("{}/{}", testrun::pointsText(points), testrun::pointsText(most));
}

}  // namespace

std::vector<GradeRow> gradeRows(const std::vector<testrun::TestResult>& results) {
  std::vector<GradeRow> rows;
  for (const testrun::TestResult& r : results) {
    if (rows.empty() || rows.back().file != r.file) rows.push_back({r.file});  // as read; printers escape it
    GradeRow& row = rows.back();
    if (!r.name.empty()) {
      row.scenarios.push_back({r.name, r.points, r.maxPoints, r.simulated, r.status, r.ran});
      ++row.total;
      row.passed += r.status == testrun::TestStatus::Passed;
      row.points += r.points;
      row.maxPoints += r.maxPoints;
    }
    if (row.firstProblem.empty() && !r.problems.empty()) row.firstProblem = firstProblemOf(r);
  }
  // A row that could not be graded at all is out of what the others are.
  if (const GradeRow* full = fullest(rows)) {
    const std::size_t total = full->total;
    const std::int64_t most = full->maxPoints;
    for (GradeRow& row : rows)
      if (row.scenarios.empty()) row.total = total, row.maxPoints = most;
  }
  return rows;
}

std::string gradeText(const std::vector<testrun::TestResult>& results) {
  std::vector<GradeRow> rows = gradeRows(results);
  for (GradeRow& r : rows) r.file = base::safeText(r.file), r.firstProblem = base::safeText(r.firstProblem);
  const GradeRow* full = fullest(rows);
  const std::size_t columns = full ? full->scenarios.size() : 0;
  std::string out;
  if (columns > 0) {
    out += "scenarios:";
    for (std::size_t k = 0; k < columns; ++k) {
      const ScenarioGrade& s = full->scenarios[k];
      out += fmt::format("{} [{}] {} ({} point{})", k == 0 ? "" : ",", k + 1, base::safeText(s.name),
                         testrun::pointsText(s.maxPoints), s.maxPoints == 100 ? "" : "s");
    }
    out += '\n';
  }
  // Each scenario's cell: its points and the simulated time ("-" where it did not run).
  std::vector<std::vector<std::string>> cells(rows.size(), std::vector<std::string>(columns, "-"));
  std::vector<std::size_t> widths(columns, 0);
  std::size_t fileWidth = 7, pointsWidth = 6;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    fileWidth = std::max(fileWidth, rows[i].file.size());
    pointsWidth = std::max(pointsWidth, pointsOutOf(rows[i].points, rows[i].maxPoints).size());
    for (std::size_t k = 0; k < columns && k < rows[i].scenarios.size(); ++k) {
      const ScenarioGrade& s = rows[i].scenarios[k];
      cells[i][k] = fmt::format("{} {}", testrun::pointsText(s.points),
                                s.ran ? base::formatSeconds(s.time) + " s" : std::string("-"));
    }
  }
  for (std::size_t k = 0; k < columns; ++k) {
    widths[k] = fmt::format("[{}]", k + 1).size();
    for (const auto& row : cells) widths[k] = std::max(widths[k], row[k].size());
  }
  std::string header = fmt::format("{:<{}}  {:>{}}  passed", "program", fileWidth, "points", pointsWidth);
  for (std::size_t k = 0; k < columns; ++k) header += fmt::format("  {:>{}}", fmt::format("[{}]", k + 1), widths[k]);
  out += header + "  first problem\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const GradeRow& r = rows[i];
    std::string line = fmt::format("{:<{}}  {:>{}}  {:>6}", r.file, fileWidth, pointsOutOf(r.points, r.maxPoints),
                                   pointsWidth, fmt::format("{}/{}", r.passed, r.total));
    for (std::size_t k = 0; k < columns; ++k) line += fmt::format("  {:>{}}", cells[i][k], widths[k]);
    line += "  " + r.firstProblem;
    while (line.back() == ' ') line.pop_back();
    out += line + '\n';
  }
  return out;
}

std::string gradeCsv(const std::vector<testrun::TestResult>& results) {
  std::vector<GradeRow> rows = gradeRows(results);
  const GradeRow* full = fullest(rows);
  const std::size_t columns = full ? full->scenarios.size() : 0;
  std::string out = "file,points,max_points,passed,scenarios";
  for (std::size_t k = 0; k < columns; ++k) {
    const std::string name = base::safeText(full->scenarios[k].name);
    out += fmt::format(",{},{}", quote("points [" + name + "]"), quote("simulated_seconds [" + name + "]"));
  }
  out += ",first_problem\n";
  for (const GradeRow& r : rows) {
    out += fmt::format("{},{},{},{},{}", quote(base::safeText(r.file)), testrun::pointsText(r.points),
                       testrun::pointsText(r.maxPoints), r.passed, r.total);
    for (std::size_t k = 0; k < columns; ++k) {
      if (k < r.scenarios.size())
        out += fmt::format(",{},{}", testrun::pointsText(r.scenarios[k].points),
                           r.scenarios[k].ran ? base::formatSeconds(r.scenarios[k].time) : std::string());
      else
        out += ",,";
    }
    out += ',' + quote(base::safeText(r.firstProblem)) + '\n';
  }
  return out;
}

nlohmann::json gradeJson(const std::vector<testrun::TestResult>& results) {
  nlohmann::json programs = nlohmann::json::array();
  for (const GradeRow& row : gradeRows(results)) {
    nlohmann::json scenarios = nlohmann::json::array();
    vm::Micros time = 0;
    for (const ScenarioGrade& s : row.scenarios) {
      time += s.time;
      scenarios.push_back({{"scenario", s.name},
                           {"status", testrun::statusName(s.status)},
                           {"points", static_cast<double>(s.points) / 100},
                           {"max_points", static_cast<double>(s.maxPoints) / 100},
                           {"time", s.ran ? nlohmann::json(static_cast<double>(s.time) / 1e6) : nlohmann::json()}});
    }
    programs.push_back({{"file", row.file},
                        {"points", static_cast<double>(row.points) / 100},
                        {"max_points", static_cast<double>(row.maxPoints) / 100},
                        {"passed", row.passed},
                        {"scenarios", row.total},
                        {"time", static_cast<double>(time) / 1e6},
                        {"by_scenario", scenarios},
                        {"first_problem", row.firstProblem}});
  }
  return programs;
}

}  // namespace rs::cli
