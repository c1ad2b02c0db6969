#include "compiler/checks.h"

#include <fmt/format.h>
#include <string>
#include <unordered_map>

#include "base/ascii.h"

namespace rs::compiler {

namespace {

constexpr std::size_t kMaxSlots = 65535;

// Names are case-insensitive, like keywords. The tables key on the name as
// written (a view into the source, which outlives them), hashed and compared
// without regard to ASCII case: no copy per lookup.
struct CaseInsensitiveHash {
  std::size_t operator()(std::string_view s) const {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a
    for (char c : s) h = (h ^ static_cast<unsigned char>(base::asciiUpper(c))) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

struct CaseInsensitiveEqual {
  bool operator()(std::string_view a, std::string_view b) const { return base::sameName(a, b); }
};

struct Named {
  std::uint32_t index;
  diag::Pos pos;
};

class Checker {
 public:
  Checker(const Program& p, std::span<const vm::MotorSpec> motors, diag::Diagnostics& d)
      : program_(p), motors_(motors), diag_(d) {
    const std::size_t n = p.instructions.size();
    res_.target.assign(n, 0);
    res_.slot.assign(n, 0);
  }

  Resolution run() {
    if (program_.instructions.empty()) diag_.error({1, 1}, "the program has no instructions");
    collectLabels();
    collectPoints();
    for (const Instruction& in : program_.instructions)
      if (in.known) instruction(in);
    warnUnassignedVariables();
    analyseFlow();
    return std::move(res_);
  }

 private:
  void collectLabels();
  void collectPoints();
  void instruction(const Instruction& in);
  void resolveJump(const Instruction& in);
  void resolvePoint(const Instruction& in);
  void resolveVariable(const Instruction& in);
  void checkIo(const Instruction& in);
  void checkTargets(const Instruction& in);
  void warnUnassignedVariables();
  void analyseFlow();
  std::vector<bool> reachable(const std::vector<std::uint32_t>& starts) const;

  const Program& program_;
  std::span<const vm::MotorSpec> motors_;
  diag::Diagnostics& diag_;
  Resolution res_;
  using NameTable = std::unordered_map<std::string_view, Named, CaseInsensitiveHash, CaseInsensitiveEqual>;
  NameTable labels_, points_, variables_;
  std::vector<bool> assigned_;        // per slot: some SET or ADD writes it
  std::vector<diag::Pos> firstRead_;        // per slot: first JMPVAR, for the warning
};

void Checker::collectLabels() {
  for (const Instruction& in : program_.instructions) {
    if (in.label.empty()) continue;
    const auto [it, fresh] = labels_.try_emplace(in.label, Named{in.number - 1, in.labelPos});
    if (!fresh)
      diag_.error(in.labelPos, fmt::format("label '{}' is already defined on line {}", in.label, it->second.pos.line));
  }
}

void Checker::collectPoints() {
  for (std::size_t i = 0; i < program_.points.size(); ++i) {
    const PointDef& p = program_.points[i];
    const auto [it, fresh] = points_.try_emplace(p.name, Named{static_cast<std::uint32_t>(i), p.pos});
    if (!fresh) diag_.error(p.pos, fmt::format("point '{}' is already defined on line {}", p.name, it->second.pos.line));
    if (p.values.size() != motors_.size()) continue;  // arity already reported
    for (std::size_t m = 0; m < motors_.size(); ++m) {
      const vm::MotorSpec& spec = motors_[m];
      if (p.values[m].number < spec.min || p.values[m].number > spec.max)
        diag_.error(p.values[m].pos, fmt::format("point {}: value {} for motor {} is outside its range {}..{}", p.name,
                                                 p.values[m].number, spec.letter, spec.min, spec.max));
    }
  }
  if (points_.size() > kMaxSlots) diag_.error(program_.pointsHeader, "more than 65535 points");
}

void Checker::instruction(const Instruction& in) {
  if (vm::info(in.op).flags & vm::kJumps) resolveJump(in);
  switch (vm::info(in.op).format) {
    case vm::Format::Point: resolvePoint(in); break;
    case vm::Format::VarCompare:
    case vm::Format::VarValue: resolveVariable(in); break;
    case vm::Format::InputJump:
    case vm::Format::Input:
    case vm::Format::Output: checkIo(in); break;
    case vm::Format::MotorVector: checkTargets(in); break;
    default: break;
  }
}

void Checker::resolveJump(const Instruction& in) {
  const JumpRef& t = in.target;
  if (t.pos.line == 0) return;  // operand was malformed, already reported
  const std::size_t n = program_.instructions.size();
  if (!t.label.empty()) {
    const auto it = labels_.find(t.label);
    if (it == labels_.end()) return diag_.error(t.pos, fmt::format("undefined label '{}'", t.label));
    res_.target[in.number - 1] = it->second.index;
    return;
  }
  if (t.number == 0) return;
  if (t.number > n)
    return diag_.error(t.pos, fmt::format("line number {} does not exist (the program has {} instruction{})", t.number,
                                          n, n == 1 ? "" : "s"));
  res_.target[in.number - 1] = t.number - 1;
}

void Checker::resolvePoint(const Instruction& in) {
  if (in.name.empty()) return;
  const auto it = points_.find(in.name);
  if (it == points_.end()) return diag_.error(in.namePos, fmt::format("undefined point '{}'", in.name));
  res_.slot[in.number - 1] = static_cast<std::uint16_t>(it->second.index);
}

void Checker::resolveVariable(const Instruction& in) {
  if (in.name.empty()) return;
  auto [it, fresh] = variables_.try_emplace(in.name, Named{static_cast<std::uint32_t>(res_.variables.size()), in.namePos});
  if (fresh) {
    if (res_.variables.size() == kMaxSlots) return diag_.error(in.namePos, "more than 65535 variables");
    res_.variables.push_back(in.name);
    assigned_.push_back(false);
    firstRead_.push_back({});
  }
  const std::uint32_t slot = it->second.index;
  res_.slot[in.number - 1] = static_cast<std::uint16_t>(slot);
  if (in.op == vm::Op::JmpVar) {
    if (firstRead_[slot].line == 0) firstRead_[slot] = in.namePos;
  } else {
    assigned_[slot] = true;
  }
}

void Checker::checkIo(const Instruction& in) {
  if (in.io.pos.line == 0) return;
  if (in.io.number < 1 || in.io.number > vm::kIoCount) {
    const bool output = in.op == vm::Op::OutSig;
    diag_.error(in.io.pos, fmt::format("{} {} is outside 1..8", output ? "output" : "input", in.io.number));
  }
}

// Absolute targets must lie in each motor's range; a relative MOVE larger
// than the whole range can never succeed either.
void Checker::checkTargets(const Instruction& in) {
  if (in.values.size() != motors_.size()) return;
  const std::string_view name = vm::info(in.op).name;
  for (std::size_t m = 0; m < motors_.size(); ++m) {
    const vm::MotorSpec& spec = motors_[m];
    const Value& v = in.values[m];
    if (vm::has(in.op, vm::kRelative)) {
      const std::int64_t span = std::int64_t{spec.max} - spec.min;
      if (v.number > span || -v.number > span)
        diag_.error(v.pos, fmt::format("MOVE by {} can never keep motor {} within its range {}..{}", v.number,
                                       spec.letter, spec.min, spec.max));
    } else if (v.number < spec.min || v.number > spec.max) {
      diag_.error(v.pos, fmt::format("{} target {} for motor {} is outside its range {}..{}", name, v.number,
                                     spec.letter, spec.min, spec.max));
    }
  }
}

void Checker::warnUnassignedVariables() {
  for (std::size_t s = 0; s < res_.variables.size(); ++s)
    if (!assigned_[s] && firstRead_[s].line != 0)
      diag_.warning(firstRead_[s],
                    fmt::format("variable '{}' is never assigned by SET or ADD; it is always 0", res_.variables[s]));
}

// Instructions reachable from `starts`, following fall-through and jumps
// (a GOSUB continues both into its subroutine and, after it, to the next).
std::vector<bool> Checker::reachable(const std::vector<std::uint32_t>& starts) const {
  const std::size_t n = program_.instructions.size();
  std::vector<bool> seen(n, false);
  std::vector<std::uint32_t> work(starts);
  while (!work.empty()) {
    const std::uint32_t i = work.back();
    work.pop_back();
    if (i >= n || seen[i]) continue;
    seen[i] = true;
    const Instruction& in = program_.instructions[i];
    if (!in.known) {
      work.push_back(i + 1);
      continue;
    }
    const std::uint8_t flags = vm::info(in.op).flags;
    if (flags & vm::kFallsThrough) work.push_back(i + 1);
    if (flags & vm::kJumps) work.push_back(res_.target[i]);
  }
  return seen;
}

void Checker::analyseFlow() {
  const auto& code = program_.instructions;
  std::vector<std::uint32_t> subroutines;
  for (std::size_t i = 0; i < code.size(); ++i)
    if (code[i].known && code[i].op == vm::Op::Gosub) subroutines.push_back(res_.target[i]);
  const bool targetsResolved = !diag_.hasErrors();
  // Reachability needs every jump target; with errors, only the check that
  // does not: a RETURN in a program without any GOSUB.
  if (subroutines.empty() || targetsResolved) {
    const std::vector<bool> inSubroutine = reachable(subroutines);
    for (std::size_t i = 0; i < code.size(); ++i) {
      if (!code[i].known || code[i].op != vm::Op::Return || inSubroutine[i]) continue;
      diag_.error(code[i].pos, subroutines.empty() ? std::string("RETURN without any GOSUB in the program")
                                                   : std::string("RETURN that no GOSUB can reach"));
    }
  }
  if (code.empty() || !targetsResolved) return;
  const std::vector<bool> live = reachable({0});
  for (std::size_t i = 1; i < code.size(); ++i) {
    if (live[i] || !live[i - 1]) continue;
    const Instruction& before = code[i - 1];
    diag_.warning(code[i].pos, fmt::format("unreachable code: nothing jumps here and {} on line {} does not continue",
                                           vm::info(before.op).name, before.pos.line));
  }
}

}  // namespace

Resolution check(const Program& program, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics) {
  return Checker(program, motors, diagnostics).run();
}

}  // namespace rs::compiler
