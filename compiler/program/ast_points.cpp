// A POINTS row: a point's encoder values, or its tool pose
// ("AT [WORLD|ROBOT] x y z ...") read into a PointPose for the checker to
// solve (translator.cpp, with workcell::PoseSolver).
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "compiler/program/ast_builder_detail.h"

namespace rs::compiler::detail {

void Builder::point(const RawToken& head, const std::vector<Word>& words) {
  PointDef& p = point_;
  std::vector<Value> values = std::move(p.values);
  values.clear();
  p = PointDef{};
  p.values = std::move(values);
  p.name = textOf(src_, head);
  p.pos = posOf(head);
  if (vm::opByName(p.name)) {
    diag_.error(p.pos, fmt::format("instruction {} after POINTS: instructions come before the POINTS line (line {})",
                                   p.name, pointsHeader_.line),
                "instruction-after-points");
    return;
  }
  if (!checkName("a point", p.name, p.pos)) return;
  if (!words.empty() && words[0].type == P::IDENT && sameName(words[0].text, "AT")) {
    p.isPose = true;
    if (pose(p, words)) sink_.point(p);
    return;
  }
  const bool ok = integers(words, "an encoder value", p.values);
  if (ok && p.values.size() != motors_.size())
    diag_.error(p.pos, fmt::format("point {} has {} values, expected {} (one per motor: {})", p.name, p.values.size(),
                                   motors_.size(), motorLetters()),
                "operand-count");
  sink_.point(p);
}

// "AT [WORLD|ROBOT] x y z [APPROACH ax ay az] [NORMAL nx ny nz] [GRIP g]":
// the clauses after the position in any order, each at most once.
bool Builder::pose(PointDef& p, const std::vector<Word>& w) {
  PointPose& pose = p.pose;
  const char* end = w.back().text.data() + w.back().text.size();
  pose.text = std::string_view(w[0].text.data(), static_cast<std::size_t>(end - w[0].text.data()));
  std::size_t i = 1;
  if (i < w.size() && w[i].type == P::IDENT && (sameName(w[i].text, "WORLD") || sameName(w[i].text, "ROBOT")))
    pose.robotFrame = sameName(w[i++].text, "ROBOT");
  bool ok = poseVector(w, i, "AT", pose.at);
  pose.at.pos = w[0].pos;
  while (ok && i < w.size()) {
    const Word& key = w[i];
    PoseVector* vector = nullptr;
    if (key.type == P::IDENT && sameName(key.text, "APPROACH")) vector = &pose.approach;
    if (key.type == P::IDENT && sameName(key.text, "NORMAL")) vector = &pose.normal;
    const bool grip = key.type == P::IDENT && sameName(key.text, "GRIP");
    if (!vector && !grip) {
      diag_.error(key.pos,
                  fmt::format("point {}: unexpected '{}' in a tool pose: after AT x y z come APPROACH ax ay az, "
                              "NORMAL nx ny nz and GRIP g",
                              p.name, diag::excerpt(key.text)),
                  "bad-operand");
      return false;
    }
    const std::string_view keyword = vector == &pose.approach ? "APPROACH" : vector ? "NORMAL" : "GRIP";
    if ((vector && vector->given) || (grip && pose.gripGiven)) {
      diag_.error(key.pos, fmt::format("point {}: {} is written twice", p.name, keyword), "bad-operand");
      return false;
    }
    ++i;
    if (vector) {
      ok = poseVector(w, i, keyword, *vector);
      vector->pos = key.pos;
    } else if (i >= w.size()) {
      diag_.error(key.pos, fmt::format("point {}: GRIP needs the gripper's encoder value", p.name), "operand-count");
      return false;
    } else {
      ok = integer(w[i++], "the gripper's encoder value", pose.grip);
      pose.gripGiven = ok;
    }
  }
  return ok;
}

// Three numbers after a keyword, each a decimal coordinate.
bool Builder::poseVector(const std::vector<Word>& w, std::size_t& i, std::string_view what, PoseVector& out) {
  const diag::Pos keyPos = w[i - 1].pos;
  std::size_t have = 0;
  while (have < 3 && i + have < w.size() && w[i + have].type == P::NUMBER) ++have;
  if (have < 3) {
    const diag::Pos at = i + have < w.size() ? w[i + have].pos : keyPos;
    diag_.error(at,
                have < w.size() - i ? fmt::format("{} expects three numbers (x y z), found '{}'", what,
                                                  diag::excerpt(w[i + have].text))
                                    : fmt::format("{} expects three numbers (x y z), found {}", what, have),
                "operand-count");
    return false;
  }
  bool ok = true;
  for (std::size_t k = 0; k < 3; ++k) ok = coordinate(w[i + k], what, out.v[k]) && ok;
  i += 3;
  out.given = ok;
  return ok;
}

bool Builder::coordinate(const Word& w, std::string_view what, double& out) {
  const std::string_view digits = w.text[0] == '+' ? w.text.substr(1) : w.text;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
  if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(out) || std::abs(out) > 1e9) {
    diag_.error(w.pos, fmt::format("{}: '{}' is not a coordinate (a number up to 1e9)", what, diag::excerpt(w.text)),
                "number-out-of-range");
    return false;
  }
  return true;
}

}  // namespace rs::compiler::detail
