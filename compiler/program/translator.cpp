#include "compiler/program/translator.h"

#include "compiler/program/kinematics_diagnostic.h"
#include "compiler/program/line_check.h"
#include "model/workcell/pose_solver.h"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/ascii.h"
#include "base/fnv1a.h"
#include "base/near_names.h"
#include "vm/motor_range.h"

namespace rs::compiler {

namespace {

constexpr std::size_t kMaxSlots = 65535;

// Names are case-insensitive, like keywords. The tables key on the name as
// written (a view into the source, which outlives them), hashed and compared
// without regard to ASCII case: no copy per lookup.
struct CaseInsensitiveHash {
  std::size_t operator()(std::string_view s) const {
    return static_cast<std::size_t>(base::fnv1aIgnoringCase(s));
  }
};

struct CaseInsensitiveEqual {
  bool operator()(std::string_view a, std::string_view b) const { return base::sameName(a, b); }
};

struct Named {
  std::uint32_t index = 0;
  diag::Pos pos;
};

using NameTable = std::unordered_map<std::string_view, Named, CaseInsensitiveHash, CaseInsensitiveEqual>;

// What an instruction refers to that only the end of the file settles: a
// label (a jump), a point (MOVEP), or a line number (a jump by number:
// does the program have that many instructions?). 16 bytes: the name is
// read again from the source at `pos` when it is needed.
struct Reference {
  diag::Pos pos;
  std::uint32_t index = 0;   // the instruction's
  std::uint32_t number = 0;  // the line number; 0 for a name
};

// The labels by name, without regard to case: open addressing over their
// ids in the image's label list, 4 bytes a slot (a node-based map takes
// about 56 bytes a label, the largest part of a compile's memory in a
// program of many labels).
class LabelTable {
 public:
  static constexpr std::uint32_t kNone = UINT32_MAX;

  std::uint32_t find(std::string_view name, const vm::Image& image) const {
    if (slots_.empty()) return kNone;
    for (std::size_t i = hash(name) & mask();; i = (i + 1) & mask()) {
      if (slots_[i] == 0) return kNone;
      if (base::sameName(image.labelName(slots_[i] - 1), name)) return slots_[i] - 1;
    }
  }
  /// Adds label `id` unless one of its name is there: then returns that one's id.
  std::uint32_t insert(std::uint32_t id, const vm::Image& image) {
    if (const std::uint32_t there = find(image.labelName(id), image); there != kNone) return there;
    if (2 * (size_ + 1) > slots_.size()) grow(image);
    place(id, image);
    ++size_;
    return kNone;
  }

 private:
  static std::size_t hash(std::string_view s) {
    const std::uint64_t h = base::fnv1aIgnoringCase(s);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
  std::size_t mask() const { return slots_.size() - 1; }
  void place(std::uint32_t id, const vm::Image& image) {
    std::size_t i = hash(image.labelName(id)) & mask();
    while (slots_[i] != 0) i = (i + 1) & mask();
    slots_[i] = id + 1;
  }
  void grow(const vm::Image& image) {
    std::vector<std::uint32_t> old(std::max<std::size_t>(64, slots_.size() * 2), 0);
    old.swap(slots_);
    for (std::uint32_t slot : old)
      if (slot != 0) place(slot - 1, image);
  }

  std::vector<std::uint32_t> slots_;  // label id + 1; 0 = empty
  std::size_t size_ = 0;
};

// The name written at `pos` (a label or point name as the lexer took it).
std::string_view nameAt(const diag::SourceFile& source, diag::Pos pos) {
  const std::string_view text = source.text();
  const std::size_t begin = source.offsetOf(pos);
  std::size_t end = begin;
  const auto namePart = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  };
  while (end < text.size() && namePart(text[end])) ++end;
  return text.substr(begin, end - begin);
}

}  // namespace

struct Translator::State {
  const diag::SourceFile& source;
  diag::Diagnostics& diag;
  vm::Image image;          // built as instructions come; code holds a placeholder for an unknown one
  std::vector<bool> known;  // per instruction: its mnemonic was known
  // Instructions seen. The image (code, known, lines, columns) holds them
  // only up to the first error: a program with errors makes no image, and
  // a file of short wrong lines ("x") would otherwise hold a 12-byte
  // placeholder for each 2-byte line. What the checks after an error need
  // is kept apart: whether any GOSUB was seen, and where later RETURNs are.
  std::uint32_t count = 0;
  bool anyGosub = false;
  std::vector<diag::Pos> returnsAfterError;
  LabelTable labels;        // the first of each name, by id in image.labels
  std::vector<diag::Pos> labelPositions;  // per label id: where it is defined
  NameTable points, variables;
  std::vector<Reference> jumps;      // to labels, and by line number
  std::vector<Reference> pointUses;  // MOVEP
  std::vector<bool> assigned;        // per slot: some SET or ADD writes it
  std::vector<diag::Pos> firstRead;  // per slot: first JMPVAR, for the warning
  diag::Pos pointsHeader;
  std::string cellName = {};  // Target::cellHint
  std::shared_ptr<const workcell::PlacedRobot> robot = nullptr;  // for points written as poses
  std::shared_ptr<workcell::LinePlanCache> linePlans = nullptr;  // Target::linePlans
  bool checkLines = true;                                          // Target::checkLines
  std::unique_ptr<workcell::PoseSolver> poser = nullptr;  // made at the first such point
  std::vector<double> lastPoseQ = {};                      // exact joint values of the last pose point
  std::size_t lastPoseIndex = 0;                           // 1 + its index in image.points (0: none)
  // Per point: a tool pose without GRIP, which leaves the gripper as it is
  // when the move starts (the instructions that use it say so).
  std::vector<bool> keepsGripper = {};
  // Names compared for "did you mean" hints, over the whole compile: a
  // file of a million undefined labels and a million labels must not cost
  // a million million comparisons.
  std::size_t suggestionBudget = 1'000'000;

  /// "did you mean 'PICK'?" with the nearest of `names` to `word`, or "".
  template <class Names, class NameOf>
  std::string didYouMean(std::string_view word, const Names& names, NameOf nameOf) {
    if (names.size() > suggestionBudget) return {};
    suggestionBudget -= names.size();
    const std::string_view near = base::nearestNameBy(word, names, nameOf, base::typoDistance(word));
    return near.empty() ? std::string() : fmt::format("did you mean '{}'?", near);
  }

  std::span<const vm::MotorSpec> motors() const { return image.motors; }
  /// "`what`: --cell NAME ...": a library cell only where its robot has these motors (Target::cellHint).
  std::string cellHint(std::string_view what) const {
    if (!cellName.empty())
      return fmt::format("{}: --cell {} (its robot has these {} motors), or '; cell: NAME' in the program", what,
                         cellName, motors().size());
    return fmt::format("{}: --cell NAME, a cell whose robot has these {} motors, or '; cell: NAME' in the program",
                       what, motors().size());
  }
  diag::Pos posOf(std::size_t i) const { return {image.lines[i], image.columns[i]}; }

  std::uint32_t jump(const Instruction& in, std::uint32_t index);
  std::uint16_t variable(const Instruction& in);
  void checkIo(const Instruction& in);
  void checkTargets(const Instruction& in);
  void checkDistance(const Instruction& in);
  void resolve();
  void resolvePose(const PointDef& p, std::span<const std::int32_t> reference, std::span<const double> referenceQ,
                   vm::Point& point);
  void warnUnassignedVariables();
  void analyseFlow();
  std::vector<bool> reachable(const std::vector<std::uint32_t>& starts) const;
};

Translator::Translator(const Target& target, const diag::SourceFile& source, diag::Diagnostics& diagnostics)
    : s_(std::make_unique<State>(State{source, diagnostics, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}})) {
  vm::Image& im = s_->image;
  s_->robot = target.robot;
  s_->linePlans = target.linePlans;
  s_->checkLines = target.checkLines;
  s_->cellName = target.cellHint;
  im.sourceName = source.name();
  im.robotName = target.robotName;
  im.callDepthLimit = target.callDepthLimit;
  im.motors = target.motors;
  // Room for the most the source can hold, reserved once: one instruction
  // (so one label, one jump, one point used) per line, one constant per two
  // bytes ("1 "). A reservation is address space: only what is written
  // becomes memory, and nothing is copied as a vector's growth would, at
  // twice the size.
  const std::size_t lines = source.lineCount();
  im.code.reserve(lines);
  im.lines.reserve(lines);
  im.columns.reserve(lines);
  im.labels.reserve(lines);
  im.labelNames.reserve(source.text().size());
  s_->labelPositions.reserve(lines);
  im.constants.reserve(source.text().size() / 2 + 1);
  s_->known.reserve(lines);
  s_->jumps.reserve(lines);
  s_->pointUses.reserve(lines);
}

Translator::~Translator() = default;

void Translator::instruction(const Instruction& in) {
  State& s = *s_;
  const std::uint32_t index = s.count++;  // in.number - 1
  // Decided before this instruction's own errors, so that code[i] stays instruction i.
  const bool keep = !s.diag.hasErrors();
  if (!in.label.empty()) {
    const auto id = static_cast<std::uint32_t>(s.image.labels.size());
    s.image.addLabel(index, in.label);
    s.labelPositions.push_back(in.labelPos);
    if (const std::uint32_t first = s.labels.insert(id, s.image); first != LabelTable::kNone) {
      const diag::Pos there = s.labelPositions[first];
      s.diag.error(in.labelPos, fmt::format("label '{}' is already defined on line {}", in.label, there.line),
                   "duplicate-label", {s.diag.relatedAt(there, fmt::format("'{}' is first defined here", in.label))});
    }
  }
  if (keep) {
    s.known.push_back(in.known);
    s.image.lines.push_back(in.pos.line);
    s.image.columns.push_back(in.pos.col);
  }
  if (!in.known) {
    if (keep) s.image.code.emplace_back();
    return;
  }
  if (vm::has(in.op, vm::kCalls)) s.anyGosub = true;
  if (vm::has(in.op, vm::kReturns) && !keep) s.returnsAfterError.push_back(in.pos);
  std::uint32_t target = 0;
  std::uint16_t slot = 0;
  if (vm::info(in.op).flags & vm::kJumps) target = s.jump(in, index);
  switch (vm::info(in.op).format) {
    case vm::Format::Point:
      if (!in.name.empty()) s.pointUses.push_back({in.namePos, index, 0});
      break;
    case vm::Format::VarCompare:
    case vm::Format::VarValue: slot = s.variable(in); break;
    case vm::Format::InputJump:
    case vm::Format::Input:
    case vm::Format::Output: s.checkIo(in); break;
    case vm::Format::MotorVector: s.checkTargets(in); break;
    case vm::Format::Distance: s.checkDistance(in); break;
    default: break;
  }
  if (vm::has(in.op, vm::kStraight) && !s.robot)
    s.diag.error(in.pos,
                 fmt::format("{} moves the tool along a straight line, which needs the robot's kinematics: this "
                             "program is compiled for motors alone",
                             vm::info(in.op).name),
                 diag::Hint{s.cellHint("compile and run it on a workcell or a robot")},
                 "needs-kinematics");
  if (keep) s.image.code.push_back(encode(in, slot, target, s.image.constants));
}

void Translator::pointsHeader(diag::Pos pos) { s_->pointsHeader = pos; }

void Translator::point(const PointDef& p) {
  State& s = *s_;
  const auto index = static_cast<std::uint32_t>(s.image.points.size());
  const auto [it, fresh] = s.points.try_emplace(p.name, Named{index, p.pos});
  if (!fresh)
    s.diag.error(p.pos, fmt::format("point '{}' is already defined on line {}", p.name, it->second.pos.line),
                 "duplicate-point", {s.diag.relatedAt(it->second.pos, fmt::format("'{}' is first defined here", p.name))});
  if (p.isPose) {
    // The previous point with a value per motor is the reference; home (all 0) for the first.
    std::vector<std::int32_t> reference(s.motors().size(), 0);
    std::size_t from = s.image.points.size();
    while (from > 0 && s.image.points[from - 1].values.size() != reference.size()) --from;
    if (from > 0) reference = s.image.points[from - 1].values;
    // A pose point before it: its exact joint values, so what is kept does not drift.
    const bool exact = from > 0 && from == s.lastPoseIndex;
    vm::Point& point = s.image.points.emplace_back(vm::Point{std::string(p.name), {}, {}});
    s.keepsGripper.push_back(!p.pose.gripGiven && std::any_of(s.motors().begin(), s.motors().end(), [](const vm::MotorSpec& m) {
      return m.kind == vm::JointKind::Gripper;
    }));
    s.resolvePose(p, reference, exact ? std::span<const double>(s.lastPoseQ) : std::span<const double>(), point);
    return;
  }
  vm::Point& point = s.image.points.emplace_back(vm::Point{std::string(p.name), {}, {}});
  s.keepsGripper.push_back(false);
  for (const Value& v : p.values) point.values.push_back(static_cast<std::int32_t>(v.number));
  if (p.values.size() != s.motors().size()) return;  // arity already reported
  for (std::size_t m = 0; m < s.motors().size(); ++m) {
    const vm::MotorSpec& spec = s.motors()[m];
    if (!vm::inRange(spec, p.values[m].number))
      s.diag.error(p.values[m].pos, fmt::format("point {}: value {} for motor {} is {}", p.name, p.values[m].number,
                                                spec.letter, vm::outsideRange(spec)),
                   "value-out-of-range");
  }
}

std::span<const std::int32_t> Translator::lastPointValues() const {
  if (s_->image.points.empty()) return {};
  return s_->image.points.back().values;
}

// A point written as a tool pose, to encoder counts with the target's robot.
void Translator::State::resolvePose(const PointDef& p, std::span<const std::int32_t> reference,
                                 std::span<const double> referenceQ, vm::Point& point) {
  const PointPose& pose = p.pose;
  if (!robot) {
    diag.error(pose.at.pos,
               fmt::format("point {} is written as a tool pose, but robot {} has no kinematic model here to resolve "
                           "it",
                           p.name, image.robotName),
               diag::Hint{cellHint("compile for a workcell or a robot description")},
               "pose-no-model");
    return;
  }
  if (!poser) poser = std::make_unique<workcell::PoseSolver>(*robot);
  workcell::PoseRequest request;
  request.robotFrame = pose.robotFrame;
  request.position = Eigen::Vector3d(pose.at.v[0], pose.at.v[1], pose.at.v[2]);
  if (pose.approach.given) request.approach = Eigen::Vector3d(pose.approach.v[0], pose.approach.v[1], pose.approach.v[2]);
  if (pose.normal.given) request.normal = Eigen::Vector3d(pose.normal.v[0], pose.normal.v[1], pose.normal.v[2]);
  if (pose.gripGiven) request.grip = static_cast<std::int32_t>(pose.grip.number);
  const workcell::PoseResult r = poser->solve(request, reference, referenceQ);
  if (!r.ok()) {
    const KinematicsPlaces places{{}, fmt::format("point {}", p.name), pose.at.pos, {}, {}, {},
                                  [&pose](workcell::PoseField field) {
                                    return field == workcell::PoseField::Approach ? pose.approach.pos
                                           : field == workcell::PoseField::Normal ? pose.normal.pos
                                           : field == workcell::PoseField::Grip   ? pose.grip.pos
                                                                                  : pose.at.pos;
                                  }};
    diag::Diagnostic d = kinematicsDiagnostic(*r.problem, places);
    diag.add(d.pos, d.severity, std::move(d.message), d.code, {}, std::move(d.hint));
    return;
  }
  point.values = r.encoders;
  // The pose as written, its words one space apart (a listing lines up its own columns).
  point.origin.clear();
  for (const char c : pose.text) {
    const bool blank = c == ' ' || c == '\t';
    if (!blank) point.origin += c;
    else if (!point.origin.empty() && point.origin.back() != ' ') point.origin += ' ';
  }
  lastPoseQ = r.q;
  lastPoseIndex = image.points.size();  // 1 + this point's index
}

std::optional<vm::Image> Translator::finish() {
  State& s = *s_;
  if (s.count == 0) s.diag.error({1, 1}, "the program has no instructions", "empty-program");
  s.resolve();
  s.warnUnassignedVariables();
  s.analyseFlow();
  if (!s.diag.hasErrors() && s.checkLines && s.robot && s.robot->robot.chain)
    checkLinePaths(s.image, *s.robot, s.diag, s.linePlans.get());
  if (s.diag.hasErrors()) return std::nullopt;
  return std::move(s.image);
}

// A jump by number is encoded now and checked against the program's length
// at the end; a jump to a label waits for the label.
std::uint32_t Translator::State::jump(const Instruction& in, std::uint32_t index) {
  const JumpRef& t = in.target;
  if (t.pos.line == 0) return 0;  // operand was malformed, already reported
  if (!t.label.empty()) {
    jumps.push_back({t.pos, index, 0});
    return 0;
  }
  if (t.number == 0) return 0;
  jumps.push_back({t.pos, index, t.number});
  return t.number - 1;
}

std::uint16_t Translator::State::variable(const Instruction& in) {
  if (in.name.empty()) return 0;
  auto [it, fresh] =
      variables.try_emplace(in.name, Named{static_cast<std::uint32_t>(image.variables.size()), in.namePos});
  if (fresh) {
    if (image.variables.size() == kMaxSlots) {
      variables.erase(it);
      diag.error(in.namePos, "more than 65535 variables", "too-many-names");
      return 0;
    }
    image.variables.emplace_back(in.name);
    assigned.push_back(false);
    firstRead.push_back({});
  }
  const std::uint32_t slot = it->second.index;
  if (!vm::has(in.op, vm::kWritesVariable)) {  // a comparison reads it
    if (firstRead[slot].line == 0) firstRead[slot] = in.namePos;
  } else {
    assigned[slot] = true;
  }
  return static_cast<std::uint16_t>(slot);
}

void Translator::State::checkIo(const Instruction& in) {
  if (in.io.pos.line == 0) return;
  if (in.io.number < 1 || in.io.number > vm::kIoCount) {
    const bool output = vm::info(in.op).format == vm::Format::Output;
    diag.error(in.io.pos, fmt::format("{} {} is outside 1..{}", output ? "output" : "input", in.io.number, vm::kIoCount),
               "io-out-of-range");
  }
}

// APPRO and DEPART go a whole number of length units, forward or back by
// their name: the distance itself is positive.
void Translator::State::checkDistance(const Instruction& in) {
  if (in.value.pos.line == 0) return;
  const std::int64_t d = in.value.number;
  if (d >= 1 && d <= vm::kMaxToolDistance) return;
  diag.error(in.value.pos,
             fmt::format("{} goes 1 to {} length units, found {}", vm::info(in.op).name, vm::kMaxToolDistance, d),
             diag::Hint{d <= 0 ? "APPRO goes along the tool's approach axis and DEPART back along it: use the other "
                                 "one with a positive distance"
                               : "split the move, or use MOVES to a point"},
             "value-out-of-range");
}

// Absolute targets must lie in each motor's range; a relative MOVE larger
// than the whole range can never succeed either.
void Translator::State::checkTargets(const Instruction& in) {
  if (in.values.size() != motors().size()) return;
  const std::string_view name = vm::info(in.op).name;
  for (std::size_t m = 0; m < motors().size(); ++m) {
    const vm::MotorSpec& spec = motors()[m];
    const Value& v = in.values[m];
    if (vm::has(in.op, vm::kRelative)) {
      const std::int64_t span = std::int64_t{spec.max} - spec.min;
      if (v.number > span || -v.number > span)
        diag.error(v.pos, fmt::format("MOVE by {} can never keep motor {} within its range {}..{}", v.number,
                                      spec.letter, spec.min, spec.max),
                   "value-out-of-range");
    } else if (!vm::inRange(spec, v.number)) {
      diag.error(v.pos, fmt::format("{} target {} for motor {} is {}", name, v.number, spec.letter,
                                    vm::outsideRange(spec)),
                   "value-out-of-range");
    }
  }
}

// Labels, points and line numbers, now that the whole file is read.
void Translator::State::resolve() {
  const std::size_t n = count;
  for (const Reference& r : jumps) {
    if (r.number != 0) {
      if (r.number > n)
        diag.error(r.pos, fmt::format("line number {} does not exist (the program has {} instruction{})", r.number, n,
                                      n == 1 ? "" : "s"),
                   "undefined-line-number");
      continue;
    }
    const std::string_view name = nameAt(source, r.pos);
    const std::uint32_t id = labels.find(name, image);
    if (id == LabelTable::kNone) {
      diag.error(r.pos, fmt::format("undefined label '{}'", name),
                 diag::Hint{didYouMean(name, image.labels, [&](const vm::Label& l) { return image.labelName(l); })},
                 "undefined-label");
      continue;
    }
    if (r.index < image.code.size()) image.code[r.index].d = static_cast<std::int32_t>(image.labels[id].index);
  }
  for (const Reference& r : pointUses) {
    const std::string_view name = nameAt(source, r.pos);
    const auto it = points.find(name);
    if (it == points.end()) {
      diag.error(r.pos, fmt::format("undefined point '{}'", name),
                 diag::Hint{didYouMean(name, image.points, [](const vm::Point& p) -> std::string_view { return p.name; })},
                 "undefined-point");
      continue;
    }
    if (r.index >= image.code.size()) continue;
    image.code[r.index].b = static_cast<std::uint16_t>(it->second.index);
    if (keepsGripper[it->second.index]) image.code[r.index].a = vm::kPointKeepsGripper;
  }
  if (points.size() > kMaxSlots) diag.error(pointsHeader, "more than 65535 points", "too-many-names");
  std::vector<Reference>().swap(jumps);
  std::vector<Reference>().swap(pointUses);
}

// A variable only read is most often a misspelling of one that is set.
void Translator::State::warnUnassignedVariables() {
  std::vector<std::string_view> set;
  for (std::size_t s = 0; s < image.variables.size(); ++s)
    if (assigned[s]) set.push_back(image.variables[s]);
  for (std::size_t s = 0; s < image.variables.size(); ++s)
    if (!assigned[s] && firstRead[s].line != 0)
      diag.warning(firstRead[s],
                   fmt::format("variable '{}' is never assigned by SET or ADD; it is always 0", image.variables[s]),
                   diag::Hint{didYouMean(image.variables[s], set, [](std::string_view v) { return v; })},
                   "unassigned-variable");
}

// Instructions reachable from `starts`, following fall-through and jumps
// (a GOSUB continues both into its subroutine and, after it, to the next).
std::vector<bool> Translator::State::reachable(const std::vector<std::uint32_t>& starts) const {
  const std::size_t n = image.code.size();
  std::vector<bool> seen(n, false);
  std::vector<std::uint32_t> work(starts);
  while (!work.empty()) {
    const std::uint32_t i = work.back();
    work.pop_back();
    if (i >= n || seen[i]) continue;
    seen[i] = true;
    if (!known[i]) {
      work.push_back(i + 1);
      continue;
    }
    const std::uint16_t flags = vm::info(image.code[i].op).flags;
    if (flags & vm::kFallsThrough) work.push_back(i + 1);
    if (flags & vm::kJumps) work.push_back(static_cast<std::uint32_t>(image.code[i].d));
  }
  return seen;
}

void Translator::State::analyseFlow() {
  const std::vector<vm::Instr>& code = image.code;
  // Reachability needs every jump target; with errors (the code then ends
  // at the first), only the check that does not: a RETURN in a program
  // without any GOSUB.
  if (diag.hasErrors()) {
    if (anyGosub) return;
    for (std::size_t i = 0; i < code.size(); ++i)
      if (known[i] && vm::has(code[i].op, vm::kReturns))
        diag.error(posOf(i), "RETURN without any GOSUB in the program", "unmatched-return");
    for (const diag::Pos& pos : returnsAfterError)
      diag.error(pos, "RETURN without any GOSUB in the program", "unmatched-return");
    return;
  }
  std::vector<std::uint32_t> subroutines;
  for (std::size_t i = 0; i < code.size(); ++i)
    if (known[i] && vm::has(code[i].op, vm::kCalls)) subroutines.push_back(static_cast<std::uint32_t>(code[i].d));
  const std::vector<bool> inSubroutine = reachable(subroutines);
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (!known[i] || !vm::has(code[i].op, vm::kReturns) || inSubroutine[i]) continue;
    diag.error(posOf(i), subroutines.empty() ? std::string("RETURN without any GOSUB in the program")
                                             : std::string("RETURN that no GOSUB can reach"),
               "unmatched-return");
  }
  if (code.empty()) return;
  const std::vector<bool> live = reachable({0});
  for (std::size_t i = 1; i < code.size(); ++i) {
    if (live[i] || !live[i - 1]) continue;
    diag.warning(posOf(i), fmt::format("unreachable code: nothing jumps here and {} on line {} does not continue",
                                       vm::info(code[i - 1].op).name, image.lines[i - 1]),
                 "unreachable-code");
  }
}

}  // namespace rs::compiler
