#include "compiler/description/library.h"

#include <sys/stat.h>

#include "base/ascii.h"
#include "compiler/description/library_dir.h"
#include "compiler/program/kinematics_diagnostic.h"
#include "diag/read_input.h"

#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "model/kinematics/chain_model.h"
#include "model/kinematics/frame.h"
#include "model/urdf/urdf_read_remote.h"
#include "model/workcell/collision_model.h"

namespace rs::compiler {

namespace fs = std::filesystem;

namespace {

std::string_view kindName(int kind) {
  static constexpr std::string_view names[] = {"link", "object", "gripper", "robot", "workcell"};
  return names[kind];
}

std::string_view kindFolder(int kind) {
  static constexpr std::string_view folders[] = {"links", "objects", "grippers", "robots", "workcells"};
  return folders[kind];
}

template <typename Def>
const Def* findIn(const std::vector<Def>& defs, const std::string& name) {
  for (const Def& d : defs)
    if (d.name == name) return &d;
  return nullptr;
}

template <typename Def>
const std::vector<Def>& defsOf(const DescriptionFile& f);
template <> const std::vector<GripperDef>& defsOf(const DescriptionFile& f) { return f.grippers; }
template <> const std::vector<RobotDef>& defsOf(const DescriptionFile& f) { return f.robots; }

// Objects share ShapeDef with links, so they need their own accessor.
const ShapeDef* findShape(const DescriptionFile& f, bool object, const std::string& name) {
  return findIn(object ? f.objects : f.links, name);
}

diag::Pos frameErrorPos(const RobotDef& def, const NameRef& gripperRef, int index) {
  if (index >= 0 && static_cast<std::size_t>(index) < def.links.size()) {
    const RobotLinkDef& l = def.links[static_cast<std::size_t>(index)];
    return l.hasOrigin ? l.origin.pos : l.link.pos;
  }
  return gripperRef.name.empty() ? def.pos : gripperRef.pos;
}

// "arm.rsd", "ARM.RSD": what a description file is called.
bool isDescriptionName(const fs::path& path) {
  const std::string ext = path.extension().string();
  return base::sameName(ext, ".rsd");
}

}  // namespace

std::vector<fs::path> librarySearchPath(const std::vector<std::string>& libDirs) {
  std::vector<fs::path> path;
  if (std::optional<fs::path> own = libraryDir()) path.push_back(std::move(*own));
  for (const std::string& d : libDirs) path.emplace_back(d);
  if (const char* env = std::getenv("ROBOTSIM_PATH")) {
    std::stringstream entries(env);
    for (std::string e; std::getline(entries, e, ':');)
      if (!e.empty()) path.emplace_back(e);
  }
  return path;
}

Library::Library(std::vector<fs::path> searchPath) : searchPath_(std::move(searchPath)) {}

bool Library::hasErrors() const { return diag::hasErrors(diagnostics_); }

const diag::SourceFile* Library::source(const std::string& file) const {
  for (const auto& f : files_)
    if (f->source && f->source->name() == file) return f->source.get();
  for (const auto& s : urdfSources_)
    if (s->name() == file) return s.get();
  return nullptr;
}

void Library::error(const DescriptionFile& file, diag::Pos pos, std::string message, std::string hint) {
  diagnostics_.push_back({file.source->name(), pos, diag::Severity::Error, std::move(message), {}, std::move(hint)});
}

bool Library::reachesSpeed(const DescriptionFile& file, diag::Pos at, std::int32_t speed, std::int32_t acceleration) {
  if (acceleration <= 0 || speed / acceleration < vm::kMaxSecondsToSpeed) return true;
  error(file, at,
        fmt::format("acceleration {} takes {} s or more to reach speed {}: give at least {}", acceleration,
                    vm::kMaxSecondsToSpeed, speed, speed / vm::kMaxSecondsToSpeed + 1));
  return false;
}

void Library::overlay(const fs::path& path, std::string text) {
  std::error_code ec;
  overlay_[fs::weakly_canonical(path, ec).string()] = std::move(text);
}

// Reads and parses a file once; later loads of the same path reuse it.
const DescriptionFile* Library::load(const fs::path& path) {
  std::error_code ec;
  const std::string key = fs::weakly_canonical(path, ec).string();
  if (auto it = byPath_.find(key); it != byPath_.end()) return it->second;
  std::optional<diag::Result<std::string>> read;
  if (auto open = overlay_.find(key); open != overlay_.end()) read.emplace(std::move(open->second));
  else read.emplace(diag::readInput(path.string(), kMaxDescriptionBytes, "cannot read description file"));
  if (!*read) {
    diagnostics_.push_back(read->failure());
    return nullptr;
  }
  if (!isDescriptionName(path) && !looksLikeDescription(**read)) {
    // Refused whole: its lines are not quoted back (docs/models.md).
    diagnostics_.push_back({path.string(), {}, diag::Severity::Error,
                            "not a robot or workcell description: its first word opens no LINK, OBJECT, GRIPPER, "
                            "ROBOT or WORKCELL block",
                            "not-a-description", "name a library robot or cell (robotsim list) or a .rsd file"});
    return nullptr;
  }
  diag::Diagnostics d(path.string());
  auto file = std::make_unique<DescriptionFile>(
      parseDescription(std::make_unique<diag::SourceFile>(path.string(), std::move(**read)), d));
  for (const diag::Diagnostic& diag : d.sorted()) diagnostics_.push_back(diag);
  files_.push_back(std::move(file));
  byPath_[key] = files_.back().get();
  return files_.back().get();
}

// A definition by name: in `first` (the referring file), then in every file
// loaded so far, then as NAME.rsd in the referring file's own folder and
// then on the search path (each directly or in the kind's folder: links/,
// grippers/, robots/, objects/, workcells/): a cell written beside its
// robot's file finds it with no --lib.
template <typename Def>
const Def* Library::find(Kind kind, const std::string& name, const DescriptionFile* first) {
  const bool object = kind == Kind::Object;
  const auto lookIn = [&](const DescriptionFile& f) -> const Def* {
    if constexpr (std::is_same_v<Def, ShapeDef>) return findShape(f, object, name);
    else return findIn(defsOf<Def>(f), name);
  };
  if (first)
    if (const Def* d = lookIn(*first)) return d;
  for (const auto& f : files_)
    if (const Def* d = lookIn(*f)) return d;
  std::vector<fs::path> folders;
  if (first && first->source) {
    const fs::path own = fs::path(first->source->name()).parent_path();
    folders.push_back(own.empty() ? fs::path(".") : own);
  }
  folders.insert(folders.end(), searchPath_.begin(), searchPath_.end());
  for (const fs::path& dir : folders) {
    for (const fs::path& candidate : {dir / (name + ".rsd"), dir / kindFolder(static_cast<int>(kind)) / (name + ".rsd")}) {
      std::error_code ec;
      if (!fs::is_regular_file(candidate, ec)) continue;
      if (const DescriptionFile* f = load(candidate))
        if (const Def* d = lookIn(*f)) return d;
    }
  }
  return nullptr;
}

// The loaded file that holds `def` (messages about a definition point into
// its own file), or `fallback`.
template <typename Def>
const DescriptionFile& Library::definingFile(const std::vector<Def>& (*defs)(const DescriptionFile&), const Def* def,
                                             const DescriptionFile& fallback) const {
  for (const auto& f : files_)
    for (const Def& d : defs(*f))
      if (&d == def) return *f;
  return fallback;
}

std::optional<workcell::Shape> Library::shape(Kind kind, const NameRef& ref, const DescriptionFile& from) {
  const ShapeDef* def = find<ShapeDef>(kind, ref.name, &from);
  if (!def) {
    error(from, ref.pos, fmt::format("unknown {} '{}': not defined in this file, and no {}.rsd beside it or on the "
                                     "library path",
                                     kindName(static_cast<int>(kind)), ref.name, ref.name));
    return std::nullopt;
  }
  return workcell::Shape{def->name, def->segments, def->collision(), def->drawn};
}

std::optional<workcell::Gripper> Library::gripper(const NameRef& ref, const DescriptionFile& from) {
  const GripperDef* def = find<GripperDef>(Kind::Gripper, ref.name, &from);
  if (!def) {
    error(from, ref.pos, fmt::format("unknown gripper '{}': not defined in this file, and no {}.rsd beside it or on "
                                     "the library path",
                                     ref.name, ref.name));
    return std::nullopt;
  }
  if (const auto built = grippers_.find(def); built != grippers_.end()) return built->second;
  return grippers_[def] = buildGripper(*def, definingFile(defsOf<GripperDef>, def, from));
}

std::optional<workcell::Gripper> Library::buildGripper(const GripperDef& gripperDef, const DescriptionFile& at) {
  const GripperDef* def = &gripperDef;
  bool ok = !def->damaged;
  const auto need = [&](bool present, std::string_view what) {
    if (present) return;
    ok = false;
    if (!def->damaged) error(at, def->pos, fmt::format("gripper '{}' has no {}", def->name, what));
  };
  need(!def->base.name.empty(), "BASE link");
  need(!def->finger2.name.empty(), "FINGERS");
  need(def->hasLetter, "LETTER");
  need(def->hasPrecision, "PRECISION");
  need(def->hasRange, "RANGE");
  need(def->hasAxis2, "AXIS2 (finger 2's rotation axis r2)");
  need(def->hasAxis3, "AXIS3 (finger 3's rotation axis r3)");
  need(def->hasNormal, "NORMAL vector");
  need(def->hasApproach, "APPROACH vector");
  // Its links are looked up whatever else is wrong, so that an unknown
  // one is reported in the same run (a name left empty was reported).
  const auto link = [&](const NameRef& r) { return r.name.empty() ? std::nullopt : shape(Kind::Link, r, at); };
  auto base = link(def->base);
  auto f2 = link(def->finger2);
  auto f3 = link(def->finger3);
  // A bad PRECISION value was reported where it was written.
  if (!ok || def->precision <= 0 || !base || !f2 || !f3) return std::nullopt;
  workcell::Gripper g;
  g.name = def->name;
  g.base = std::move(*base), g.finger2 = std::move(*f2), g.finger3 = std::move(*f3);
  g.letter = def->letter, g.min = def->min, g.max = def->max, g.speed = def->speed;
  g.acceleration = def->acceleration, g.actuation = def->actuation;
  if (!reachesSpeed(at, def->accelerationPos, g.speed, g.acceleration)) return std::nullopt;
  const kinematics::GripperPoints points{def->axis2[0].v, def->axis2[1].v, def->axis3[0].v,  def->axis3[1].v,
                                         def->normal[0].v, def->normal[1].v, def->approach[0].v, def->approach[1].v};
  kinematics::Built<kinematics::GripperModel> model = kinematics::makeGripper(points, def->precision);
  // The kinematics core says which vector the error is about; point at its line.
  const compiler::KinematicsPlaces places{
      at.source->name(), fmt::format("gripper '{}'", def->name), def->normal[0].pos, {}, [&](int part) {
        return part == kinematics::kGripperAxis2      ? def->axis2[0].pos
               : part == kinematics::kGripperAxis3    ? def->axis3[0].pos
               : part == kinematics::kGripperApproach ? def->approach[0].pos
                                                      : def->normal[0].pos;
      }};
  for (const kinematics::KinematicsError& e : model.errors)
    diagnostics_.push_back(compiler::kinematicsDiagnostic(e, places));
  if (!model.ok()) return std::nullopt;
  g.model = *model.value;
  return g;
}

std::optional<workcell::Robot> Library::buildRobot(const RobotDef& def, const DescriptionFile& from) {
  if (const auto built = robots_.find(&def); built != robots_.end()) return built->second;
  return robots_[&def] = checkRobot(def, from);
}

// Every check of a robot that its own errors leave meaningful: references
// are always looked up, the whole (counts, numbering, missing parts, the
// chain) only when no line of it had an error (RobotDef::damaged).
std::optional<workcell::Robot> Library::checkRobot(const RobotDef& def, const DescriptionFile& from) {
  workcell::Robot robot;
  robot.name = def.name;
  bool ok = !def.damaged;
  if (def.links.empty()) {
    if (!def.damaged) error(from, def.pos, fmt::format("robot '{}' has no LINK", def.name));
    ok = false;
  }
  for (std::size_t i = 0; i < def.links.size(); ++i) {
    const RobotLinkDef& l = def.links[i];
    auto s = l.link.name.empty() ? std::nullopt : shape(Kind::Link, l.link, from);  // no name: reported
    if (!s) ok = false;
    else robot.links.push_back(std::move(*s));
    if (l.damaged) {
      ok = false;
      continue;
    }
    if (!l.hasOrigin || !l.hasX || !l.hasZ) {
      const char* missing = !l.hasFrame() ? "FRAME (ORIGIN, XAXIS and ZAXIS points)"
                            : !l.hasOrigin ? "ORIGIN point in its FRAME"
                            : !l.hasX      ? "XAXIS point in its FRAME"
                                           : "ZAXIS point in its FRAME";
      error(from, l.link.pos, fmt::format("link '{}' has no {}", l.link.name, missing));
      ok = false;
      continue;
    }
    auto frame = kinematics::frameFromPoints(l.origin.v, l.xPoint.v, l.zPoint.v, {}, static_cast<int>(i));
    const compiler::KinematicsPlaces places{from.source->name(), fmt::format("link '{}'", l.link.name), l.origin.pos};
    for (const auto& e : frame.errors) diagnostics_.push_back(compiler::kinematicsDiagnostic(e, places));
    if (frame.ok()) robot.frames.push_back(*frame.value);
    else ok = false;
  }
  if (def.tool && !def.tool->damaged) {
    const RobotLinkDef& t = *def.tool;
    if (!def.gripper.name.empty()) {
      error(from, t.link.pos, "a robot with a GRIPPER has its tool centre point there: TOOL and GRIPPER exclude each other");
      ok = false;
    } else if (!t.hasOrigin || !t.hasX || !t.hasZ) {
      error(from, t.link.pos, "TOOL needs ORIGIN, XAXIS and ZAXIS points");
      ok = false;
    } else {
      auto frame = kinematics::frameFromPoints(t.origin.v, t.xPoint.v, t.zPoint.v, {}, -1);
      const compiler::KinematicsPlaces places{from.source->name(), "the TOOL", t.origin.pos};
      for (const auto& e : frame.errors) diagnostics_.push_back(compiler::kinematicsDiagnostic(e, places));
      if (frame.ok()) robot.tool = *frame.value;
      else ok = false;
    }
  } else if (def.tool) {
    ok = false;
  }
  if (!def.gripper.name.empty()) {
    auto g = gripper(def.gripper, from);
    if (!g) ok = false;
    else robot.hasGripper = true, robot.gripper = std::move(*g), robot.frames.push_back(robot.gripper.model.F_G_E);
  }
  // Joints: numbered 1, 2, 3 ... in order, each with its motor data.
  for (std::size_t i = 0; i < def.joints.size(); ++i) {
    const JointDef& j = def.joints[i];
    // A JOINT line that failed may be missing: the numbering is then off.
    if (j.number != static_cast<int>(i + 1) && !def.damaged)
      error(from, j.pos, fmt::format("joints are numbered in order: expected JOINT {}, found JOINT {}", i + 1, j.number)), ok = false;
    if (!j.damaged)
      for (auto [present, what] : {std::pair{j.hasLetter, "LETTER"}, std::pair{j.hasPrecision, "PRECISION"},
                                   std::pair{j.hasRange, "RANGE"}})
        if (!present) error(from, j.pos, fmt::format("JOINT {} has no {}", j.number, what)), ok = false;
    if (!reachesSpeed(from, j.accelerationPos, j.spec.speed, j.spec.acceleration)) ok = false;
    robot.joints.push_back(j.spec);
  }
  const std::size_t frames = def.links.size() + (def.gripper.name.empty() ? 0 : 1);
  if (ok && def.joints.size() + 1 != frames)
    error(from, def.pos, fmt::format("robot '{}' has {} link{}{} and so needs {} joint{}, found {}", def.name,
                                     def.links.size(), def.links.size() == 1 ? "" : "s",
                                     def.gripper.name.empty() ? "" : " and a gripper", frames - 1,
                                     frames - 1 == 1 ? "" : "s", def.joints.size())),
        ok = false;
  // Motor letters are unique across the arm and the gripper.
  std::string letters;
  for (std::size_t i = 0; i < def.joints.size(); ++i) {
    if (!def.joints[i].hasLetter) continue;  // reported above
    if (letters.find(def.joints[i].spec.letter) != std::string::npos)
      error(from, def.joints[i].pos, fmt::format("motor letter {} is used twice", def.joints[i].spec.letter)), ok = false;
    letters += def.joints[i].spec.letter;
  }
  if (robot.hasGripper && letters.find(robot.gripper.letter) != std::string::npos)
    error(from, def.gripper.pos, fmt::format("the gripper's motor letter {} is also a joint's", robot.gripper.letter)),
        ok = false;
  if (!ok) return std::nullopt;

  std::vector<kinematics::JointType> types;
  std::vector<kinematics::JointDrive> drives;
  for (const workcell::JointSpec& j : robot.joints) {
    types.push_back(j.type);
    drives.push_back({j.precision, -1, j.coupling});
  }
  auto chain = kinematics::ChainModel::fromFrames(robot.frames, types, drives);
  compiler::KinematicsPlaces places{from.source->name(), fmt::format("robot '{}'", def.name), def.pos};
  places.joint = [&def](int joint) {
    return joint >= 1 && static_cast<std::size_t>(joint) <= def.joints.size()
               ? def.joints[static_cast<std::size_t>(joint - 1)].pos
               : diag::Pos{};
  };
  places.frame = [&def](int frame) { return frameErrorPos(def, def.gripper, frame); };
  for (const kinematics::KinematicsError& e : chain.errors)
    diagnostics_.push_back(compiler::kinematicsDiagnostic(e, places));
  if (!chain.ok()) return std::nullopt;
  robot.chain = std::move(chain.value);
  if (robot.tool) robot.chain = robot.chain->withTool(robot.frames.back().inverse(Eigen::Isometry) * *robot.tool);
  return robot;
}

std::optional<workcell::Workcell> Library::buildWorkcell(const WorkcellDef& def, const DescriptionFile& from) {
  cellsBuilt_.insert(&def);
  workcell::Workcell cell;
  cell.name = def.name;
  cell.floor = def.floor;
  bool ok = true;
  for (const PlacementDef& p : def.placements) {
    if (p.what.name.empty()) {  // a placement whose name was missing: reported
      ok = false;
      continue;
    }
    if (p.isRobot && urdf::isUrdfName(p.what.name)) {
      // A URDF file, named relative to the cell's file: its root link's
      // origin goes to AT (docs/models.md, "Reading URDF").
      const fs::path file = findUrdf(p.what.name, fs::path(from.source->name()).parent_path());
      if (file.empty()) {
        error(from, p.what.pos, fmt::format("no URDF file '{}' beside this file or on the library path", p.what.name));
        ok = false;
        continue;
      }
      auto robot = urdfRobot(file);
      if (!robot) {
        ok = false;
        continue;
      }
      Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
      place.linear() = p.rotation;
      place.translation() = p.at;
      cell.robots.push_back({std::move(*robot), place});
      if (!placeRobot(p, from, cell)) ok = false;
    } else if (p.isRobot) {
      const RobotDef* r = find<RobotDef>(Kind::Robot, p.what.name, &from);
      if (!r) {
        error(from, p.what.pos, fmt::format("unknown robot '{}': not defined in this file, and no {}.rsd beside it "
                                            "or on the library path", p.what.name, p.what.name));
        ok = false;
        continue;
      }
      auto robot = buildRobot(*r, definingFile(defsOf<RobotDef>, r, from));
      if (!robot) {
        ok = false;
        continue;
      }
      // The origin of link 0 goes to AT, turned by the ROTATE clauses.
      const Eigen::Vector3d o0 = robot->frames[0].translation();
      Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
      place.linear() = p.rotation;
      place.translation() = p.at - p.rotation * o0;
      cell.robots.push_back({std::move(*robot), place});
      if (!placeRobot(p, from, cell)) ok = false;
    } else {
      auto s = shape(Kind::Object, p.what, from);
      if (!s) {
        ok = false;
        continue;
      }
      Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
      place.linear() = p.rotation;
      place.translation() = p.at - p.rotation * workcell::atCorner(*s);
      const ShapeDef* sd = find<ShapeDef>(Kind::Object, p.what.name, &from);
      workcell::PlacedObject placed{std::move(*s), place};
      placed.kind = p.kind.value_or(sd->kind);
      placed.name = p.as.name.empty() ? p.what.name : p.as.name;
      placed.belt = sd->belt;
      placed.pos = p.what.pos;
      cell.objects.push_back(std::move(placed));
    }
  }
  if (def.damaged) ok = false;
  if (ok && !buildDevices(def, from, cell)) ok = false;
  if (ok && cell.robots.empty() && cell.objects.empty())
    error(from, def.pos, fmt::format("workcell '{}' places no robot and no object", def.name)), ok = false;
  if (!ok) return std::nullopt;
  reportHomeCollisions(cell, def, from);
  reportRobotOverlaps(cell, from);
  return cell;
}

// Every robot and workcell of a file is built, whether the command uses it
// or not, so that one run reports every error of the file (docs/models.md,
// "Errors"); each robot is built once (buildRobot remembers).
void Library::checkAll(const DescriptionFile& f) {
  for (const RobotDef& r : f.robots) buildRobot(r, f);
  for (const WorkcellDef& w : f.workcells)
    if (!cellsBuilt_.contains(&w)) buildWorkcell(w, f);
}

// A file path if it names an existing file (or one an editor holds), else a
// library name.
const DescriptionFile* Library::loadRoot(const std::string& fileOrName, Kind kind) {
  std::error_code ec;
  if (!libraryNamesOnly_ &&
      (fs::is_regular_file(fileOrName, ec) || overlay_.count(fs::weakly_canonical(fileOrName, ec).string())))
    return load(fileOrName);
  // The kind's own folder first; a workcell may also be a lone robot.
  for (const fs::path& dir : searchPath_) {
    std::vector<fs::path> candidates{dir / (fileOrName + ".rsd"), dir / kindFolder(static_cast<int>(kind)) / (fileOrName + ".rsd")};
    if (kind == Kind::Workcell) candidates.push_back(dir / kindFolder(static_cast<int>(Kind::Robot)) / (fileOrName + ".rsd"));
    for (const fs::path& candidate : candidates)
      if (fs::is_regular_file(candidate, ec)) return load(candidate);
  }
  // Something at that path that is no file to read (a FIFO, a device, a
  // folder): said as what it is, as every reader says it (base/file_io.h).
  struct stat st {};
  if (!libraryNamesOnly_ && ::stat(fileOrName.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    diagnostics_.push_back(
        diag::unreadable(fileOrName, "cannot read description file", base::notRegularFileReason(st.st_mode)));
    return nullptr;
  }
  // (A workcell may also be a lone robot: the message says both.)
  diagnostics_.push_back({fileOrName, {}, diag::Severity::Error,
                          fmt::format("no such file, and no {} of that name on the library path",
                                      kind == Kind::Workcell ? "workcell or robot" : kindName(static_cast<int>(kind)))});
  return nullptr;
}

std::optional<workcell::Robot> Library::robot(const std::string& fileOrName) {
  if (urdf::isUrdfName(fileOrName)) {
    const fs::path file = findUrdf(fileOrName, {});
    if (file.empty()) {
      diagnostics_.push_back({fileOrName, {}, diag::Severity::Error, "no such URDF file, here or on the library path"});
      return std::nullopt;
    }
    return urdfRobot(file);
  }
  // Build even when the root file has errors, so the files it uses are
  // read and their errors reported too; only an error-free build returns.
  const DescriptionFile* f = loadRoot(fileOrName, Kind::Robot);
  if (!f) return std::nullopt;
  if (f->robots.empty()) {
    if (!hasErrors())  // (a ROBOT line that failed is no news)
      diagnostics_.push_back({f->source->name(), {}, diag::Severity::Error, "the file defines no ROBOT"});
    checkAll(*f);
    return std::nullopt;
  }
  auto r = buildRobot(f->robots.front(), *f);
  checkAll(*f);
  return hasErrors() ? std::nullopt : std::move(r);
}

std::optional<workcell::Workcell> Library::workcell(const std::string& fileOrName) {
  if (urdf::isUrdfName(fileOrName)) {
    // A URDF robot alone: where it was drawn, in no room.
    std::optional<workcell::Robot> r = robot(fileOrName);
    if (!r) return std::nullopt;
    workcell::Workcell cell;
    cell.name = r->name;
    cell.floor.reset();
    cell.robots.push_back({std::move(*r), Eigen::Isometry3d::Identity()});
    return cell;
  }
  const DescriptionFile* f = loadRoot(fileOrName, Kind::Workcell);
  if (!f) return std::nullopt;
  std::optional<workcell::Workcell> cell;
  if (!f->workcells.empty()) {
    cell = buildWorkcell(f->workcells.front(), *f);
  } else if (!f->robots.empty()) {
    WorkcellDef alone{f->robots.front().name, f->robots.front().pos, {}};
    alone.floor.reset();  // a robot alone stands in no room
    PlacementDef p;
    p.what = {f->robots.front().name, f->robots.front().pos};
    p.at = Eigen::Vector3d::Zero();
    alone.placements.push_back(p);
    cell = buildWorkcell(alone, *f);
    // Alone, the robot stays where it was drawn.
    if (cell) cell->robots.front().F_world_design = Eigen::Isometry3d::Identity();
  } else if (!hasErrors()) {
    diagnostics_.push_back({f->source->name(), {}, diag::Severity::Error, "the file defines no WORKCELL and no ROBOT"});
  }
  checkAll(*f);
  return hasErrors() ? std::nullopt : std::move(cell);
}

bool Library::holdsWorkcell(const std::string& fileOrName) {
  if (urdf::isUrdfName(fileOrName)) return false;
  const DescriptionFile* f = loadRoot(fileOrName, Kind::Workcell);  // read once: load() keeps it
  return f && !f->workcells.empty();
}

std::vector<vm::MotorSpec> motorTable(const workcell::Robot& robot) {
  std::vector<vm::MotorSpec> motors;
  for (const workcell::JointSpec& j : robot.joints)
    motors.push_back({j.letter,
                      j.type == kinematics::JointType::Revolute ? vm::JointKind::Revolute : vm::JointKind::Prismatic,
                      j.precision, j.min, j.max, j.speed, j.acceleration, 0});
  if (robot.hasGripper) {
    const workcell::Gripper& g = robot.gripper;
    motors.push_back(
        {g.letter, vm::JointKind::Gripper, g.model.precision, g.min, g.max, g.speed, g.acceleration, g.actuation});
  }
  return motors;
}

}  // namespace rs::compiler
