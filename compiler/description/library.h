// Robot and workcell descriptions, second stage: names resolved across
// files and the library search path, then each robot built (frames, D-H
// table, chain model) and each workcell placed. Every error from every file
// is collected, with the file it belongs to.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "compiler/description/description.h"
#include "model/urdf/urdf_read.h"
#include "model/workcell/model.h"
#include "vm/image.h"

namespace rs::compiler {

/// The largest description file read (docs/reliability.md): every reader
/// of descriptions, `robotsim list` too, refuses a larger one.
constexpr std::size_t kMaxDescriptionBytes = std::size_t{64} << 20;

/// Where names are looked up after the file itself: the project's stdlib/,
/// then --lib directories, then the ROBOTSIM_PATH entries (colon-separated).
std::vector<std::filesystem::path> librarySearchPath(const std::vector<std::string>& libDirs);

class Library {
 public:
  explicit Library(std::vector<std::filesystem::path> searchPath);

  /// A robot from a description file (its first ROBOT), a URDF file
  /// (`.urdf`: docs/models.md, "Reading URDF") or a library name.
  std::optional<workcell::Robot> robot(const std::string& fileOrName);
  /// How URDF files are read (--tip, --precision): before the first lookup.
  void setUrdfOptions(urdf::UrdfOptions options) { urdfOptions_ = std::move(options); }
  /// A workcell from a file (its first WORKCELL, or else its first ROBOT
  /// placed alone at the origin) or a library name.
  std::optional<workcell::Workcell> workcell(const std::string& fileOrName);
  /// After workcell() found a cell: whether its file holds a WORKCELL (true)
  /// or the cell is a lone ROBOT standing where it was drawn (false), which
  /// decides whether its coordinates are a workcell's world or a robot's
  /// design coordinates.
  bool holdsWorkcell(const std::string& fileOrName);

  /// The text of `path` as an editor holds it, unsaved: read instead of the
  /// file on disk (the language server checks what the user sees). Before
  /// the first lookup.
  void overlay(const std::filesystem::path& path, std::string text);

  /// From now on a root name (robot(), workcell()) is looked up on the
  /// library path only, never as a file from the working directory: a
  /// name a submission wrote (grading) cannot reach a file that way.
  void lookUpNamesOnly() { libraryNamesOnly_ = true; }

  const std::vector<diag::Diagnostic>& diagnostics() const { return diagnostics_; }
  bool hasErrors() const;
  /// The source of a diagnostic's file, for rendering; null if unknown.
  const diag::SourceFile* source(const std::string& file) const;

 private:
  enum class Kind { Link, Object, Gripper, Robot, Workcell };
  const DescriptionFile* load(const std::filesystem::path& path);
  const DescriptionFile* loadRoot(const std::string& fileOrName, Kind kind);
  /// Builds every robot and workcell of `f` (each once), for its errors.
  void checkAll(const DescriptionFile& f);
  template <typename Def>
  const DescriptionFile& definingFile(const std::vector<Def>& (*defs)(const DescriptionFile&), const Def* def,
                                      const DescriptionFile& fallback) const;
  template <typename Def>
  const Def* find(Kind kind, const std::string& name, const DescriptionFile* first);
  std::optional<workcell::Shape> shape(Kind kind, const NameRef& ref, const DescriptionFile& from);
  std::optional<workcell::Gripper> gripper(const NameRef& ref, const DescriptionFile& from);
  std::optional<workcell::Gripper> buildGripper(const GripperDef& def, const DescriptionFile& at);
  std::optional<workcell::Robot> buildRobot(const RobotDef& def, const DescriptionFile& from);
  std::optional<workcell::Robot> checkRobot(const RobotDef& def, const DescriptionFile& from);
  std::optional<workcell::Workcell> buildWorkcell(const WorkcellDef& def, const DescriptionFile& from);
  void error(const DescriptionFile& file, diag::Pos pos, std::string message, std::string hint = {});
  /// library_devices.cpp: resolves the workcell's devices into `cell`
  /// (its objects placed); false after reporting an error.
  bool buildDevices(const WorkcellDef& def, const DescriptionFile& from, workcell::Workcell& cell);
  bool placeRobot(const PlacementDef& p, const DescriptionFile& from, workcell::Workcell& cell);
  bool programFitsRobot(const workcell::PlacedRobot& r, const DescriptionFile& from);
  void reportRobotOverlaps(const workcell::Workcell& cell, const DescriptionFile& from);
  /// False (with an error at the ACCELERATION) when the motor would take
  /// vm::kMaxSecondsToSpeed or more to reach its speed.
  bool reachesSpeed(const DescriptionFile& file, diag::Pos at, std::int32_t speed, std::int32_t acceleration);
  void reportHomeCollisions(const workcell::Workcell& cell, const WorkcellDef& def, const DescriptionFile& from);
  /// A URDF file's robot, read once (in the helper robotsim-urdf); its
  /// diagnostics join this library's.
  std::optional<workcell::Robot> urdfRobot(const std::filesystem::path& path);
  /// The URDF file a name stands for: the file itself, else NAME on the
  /// library path (directly or in robots/); empty when there is none.
  std::filesystem::path findUrdf(const std::string& fileOrName, const std::filesystem::path& besides) const;

  std::vector<std::filesystem::path> searchPath_;
  std::vector<std::unique_ptr<DescriptionFile>> files_;  // in load order
  std::map<std::string, const DescriptionFile*> byPath_;
  std::map<std::string, std::string> overlay_;  // canonical path -> text
  std::vector<diag::Diagnostic> diagnostics_;
  bool libraryNamesOnly_ = false;
  // Each robot and gripper is built (and its errors reported) once, however
  // many places use it.
  std::map<const RobotDef*, std::optional<workcell::Robot>> robots_;
  std::map<const GripperDef*, std::optional<workcell::Gripper>> grippers_;
  std::set<const WorkcellDef*> cellsBuilt_;
  urdf::UrdfOptions urdfOptions_;
  std::map<std::string, std::optional<workcell::Robot>> urdfRobots_;  // by canonical path
  std::vector<std::unique_ptr<diag::SourceFile>> urdfSources_;        // for carets under their lines
};

/// The motor table a program sees on a robot: arm joints in order, then
/// the gripper's motor.
std::vector<vm::MotorSpec> motorTable(const workcell::Robot& robot);

}  // namespace rs::compiler
