#include "model/urdf/urdf_read.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <system_error>
#include <fmt/format.h>

#include "diag/read_input.h"
#include "model/kinematics/angles.h"
#include "model/kinematics/chain_model.h"
#include "model/urdf/urdf_chain.h"
#include "model/urdf/urdf_dh.h"
#include "model/urdf/urdf_mesh.h"
#include "model/urdf/urdf_read_xml.h"

namespace rs::urdf {

namespace fs = std::filesystem;

namespace {

constexpr double kMaxCounts = 1e9;  // the description language's largest number

// urdfdom reports through console_bridge: kept here, not printed.
class Captured : public console_bridge::OutputHandler {
 public:
  Captured() { console_bridge::useOutputHandler(this); }
  ~Captured() override { console_bridge::restorePreviousOutputHandler(); }
  Captured(const Captured&) = delete;
  Captured& operator=(const Captured&) = delete;
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> errors;
};

// A hint for what urdfdom said.
std::string hintFor(std::string_view message) {
  const auto has = [&](std::string_view w) { return message.find(w) != std::string_view::npos; };
  if (has("Two root")) return "a URDF is a tree with one root: join the other link to it with a joint";
  if (has("No root")) return "the joints make a loop: a tree has one link that is no joint's child";
  if (has("parent link") || has("child link") || has("Failed to find"))
    return "a joint's <parent link=\"...\"> and <child link=\"...\"> must name <link> elements of the file";
  if (has("multiple parents") || has("already has a parent")) return "a link may be the child of one joint only";
  if (has("limit")) return "a revolute or prismatic joint needs <limit lower=\"...\" upper=\"...\" velocity=\"...\" effort=\"...\"/>";
  return "check the element against the URDF format";
}

struct Reader {
  const std::string& file;
  const UrdfOptions& options;
  XmlIndex& xml;
  UrdfRead& out;

  void report(diag::Pos pos, diag::Severity severity, std::string message, std::string hint, std::string_view code) {
    out.diagnostics.push_back({file, pos, severity, std::move(message), code, std::move(hint)});
  }

  // Counts of a joint value in degrees or millimetres.
  std::optional<std::int32_t> counts(double value, bool up, const ChainJoint& j) {
    const double c = up ? std::ceil(value / options.precision - 1e-9) : std::floor(value / options.precision + 1e-9);
    if (std::abs(c) > kMaxCounts) {
      report(xml.joint(j.name), diag::Severity::Error,
             fmt::format("joint '{}': its limit {} is more than {} counts at precision {}", j.name, value, kMaxCounts,
                         options.precision),
             "give a larger --precision", "urdf-limit");
      return std::nullopt;
    }
    return static_cast<std::int32_t>(c);
  }

  std::optional<workcell::JointSpec> motor(const ChainJoint& j, std::size_t k) {
    workcell::JointSpec spec;
    spec.type = j.type;
    spec.letter = static_cast<char>('A' + k);
    spec.precision = options.precision;
    spec.coupling = j.coupling;
    const bool revolute = j.type == kinematics::JointType::Revolute;
    const double unit = revolute ? kinematics::kRadToDeg : 1000.0;  // to degrees or mm
    if (j.mimics) {
      spec.min = spec.max = 0;  // moved by COUPLING alone
    } else if (j.continuous || !j.hasLimits) {
      const auto c = counts(kContinuousRangeDegrees, false, j);
      if (!c) return std::nullopt;
      spec.min = -*c, spec.max = *c;
    } else {
      const auto lo = counts(j.lower * unit, true, j), hi = counts(j.upper * unit, false, j);
      if (!lo || !hi) return std::nullopt;
      spec.min = *lo, spec.max = *hi;
      if (spec.min > 0 || spec.max < 0) {
        report(xml.joint(j.name), diag::Severity::Warning,
               fmt::format("joint '{}': its limits {}..{} leave out its zero pose, robotsim's home (encoder 0): the "
                           "range is widened to include 0",
                           j.name, j.lower, j.upper),
               "", "urdf-range-widened");
        spec.min = std::min(spec.min, 0), spec.max = std::max(spec.max, 0);
      }
    }
    const double velocity = j.velocity > 0 ? j.velocity * unit : (revolute ? kDefaultRevoluteSpeed : kDefaultPrismaticSpeed);
    spec.speed = static_cast<std::int32_t>(std::clamp(std::round(velocity / options.precision), 1.0, kMaxCounts));
    return spec;
  }

  void build(const ::urdf::ModelInterface& model) {
    UrdfChain chain = extractChain(model, options.tip);
    for (const ChainProblem& p : chain.problems)
      report(p.name.empty() ? xml.robot() : p.joint ? xml.joint(p.name) : xml.link(p.name),
             p.warning ? diag::Severity::Warning : diag::Severity::Error, p.message, p.hint,
             p.warning ? "urdf-held-joint" : "urdf-chain");
    if (!chain.ok()) return;
    if (chain.joints.size() > 26) {
      report(xml.robot(), diag::Severity::Error,
             fmt::format("the chain has {} moving joints; robotsim's motors are lettered A to Z (26)", chain.joints.size()),
             "end the chain earlier with --tip LINK", "urdf-chain");
      return;
    }
    workcell::Robot robot;
    robot.name = model.getName().empty() ? fs::path(file).stem().string() : model.getName();
    robot.urdf = workcell::UrdfSource{file, chain.root, chain.tip};
    std::vector<DhAxis> axes;
    for (const ChainJoint& j : chain.joints) axes.push_back({j.point, j.direction, j.F_design_child, j.F_design_parent});
    const DhFrames dh = dhFramesFromAxes(axes, chain.F_design_root, chain.F_design_tip);
    robot.frames = dh.frames;
    robot.tool = dh.tool;
    bool ok = true;
    for (std::size_t k = 0; k < chain.joints.size(); ++k) {
      auto spec = motor(chain.joints[k], k);
      if (!spec) ok = false;
      else robot.joints.push_back(*spec);
    }
    if (!ok) return;
    // Geometry: each robotsim link draws the URDF links folded into it.
    const fs::path dir = fs::path(file).parent_path();
    for (std::size_t i = 0; i < chain.links.size(); ++i) {
      workcell::Shape shape;
      LinkGeometry g;
      for (const ChainLink& l : chain.links[i]) {
        if (shape.name.empty()) shape.name = l.link->name;
        std::vector<::urdf::VisualSharedPtr> visuals = l.link->visual_array;
        if (visuals.empty() && l.link->visual) visuals.push_back(l.link->visual);
        for (const auto& v : visuals) {
          if (!v) continue;
          std::vector<MeshProblem> problems;
          addVisual(*v, l.F_root_link, dir, g, problems);
          for (const MeshProblem& p : problems) {
            report(xml.link(l.link->name), p.warning ? diag::Severity::Warning : diag::Severity::Error, p.message,
                   p.hint, p.warning ? "urdf-mesh-missing" : "urdf-mesh");
            if (!p.warning) ok = false;
          }
        }
      }
      if (shape.name.empty()) shape.name = fmt::format("link{}", i);
      shape.segments = std::move(g.segments);
      shape.collision = std::move(g.pieces);
      robot.links.push_back(std::move(shape));
    }
    if (!ok) return;
    std::vector<kinematics::JointType> types;
    std::vector<kinematics::JointDrive> drives;
    for (const workcell::JointSpec& j : robot.joints) types.push_back(j.type), drives.push_back({j.precision, -1, j.coupling});
    auto built = kinematics::ChainModel::fromFrames(robot.frames, types, drives);
    for (const kinematics::KinematicsError& e : built.errors)
      report(xml.robot(), diag::Severity::Error, e.message, "", "urdf-kinematics");
    if (!built.ok()) return;
    robot.chain = std::move(built.value);
    if (robot.tool) robot.chain = robot.chain->withTool(robot.frames.back().inverse(Eigen::Isometry) * *robot.tool);
    out.robot = std::move(robot);
  }
};

}  // namespace

UrdfRead readUrdfText(std::string_view text, const std::string& file, const UrdfOptions& options) {
  UrdfRead out;
  if (text.size() > kMaxUrdfBytes) {
    out.diagnostics.push_back(urdfTooLarge(file, text.size()));
    return out;
  }
  if (!(options.precision > 0) || !std::isfinite(options.precision)) {
    out.diagnostics.push_back({file, {}, diag::Severity::Error,
                               fmt::format("precision {} must be a positive number", options.precision), "urdf-precision"});
    return out;
  }
  XmlIndex xml(text, file, out.diagnostics);
  if (!xml.ok()) return out;
  ::urdf::ModelInterfaceSharedPtr model;
  std::vector<std::string> errors;
  {
    Captured captured;
    model = ::urdf::parseURDF(std::string(text));
    errors = std::move(captured.errors);
  }
  if (!model) {
    // The first error is the cause; urdfdom's later ones only say it gave up.
    const std::string message = errors.empty() ? std::string("urdfdom could not read the robot") : errors.front();
    out.diagnostics.push_back(
        {file, xml.named(message), diag::Severity::Error, fmt::format("not a valid URDF: {}", message), "urdf-invalid", hintFor(message)});
    return out;
  }
  Reader reader{file, options, xml, out};
  reader.build(*model);
  if (diag::hasErrors(out.diagnostics)) out.robot.reset();
  return out;
}

UrdfRead readUrdfFile(const fs::path& path, const UrdfOptions& options) {
  // A FIFO or a device is refused before it is opened: opening one waits.
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    UrdfRead out;
    out.diagnostics.push_back({path.string(), {}, diag::Severity::Error,
                               "cannot read URDF file: not a regular file (a folder, FIFO or device)", "urdf-not-urdf",
                               "name a .urdf file"});
    return out;
  }
  // Judged by its size before a byte is read (readInput would refuse it
  // too, with base/'s words and no hint).
  if (const std::uintmax_t size = fs::file_size(path, ec); !ec && size > kMaxUrdfBytes)
    return UrdfRead{std::nullopt, {urdfTooLarge(path.string(), size)}};
  diag::Result<std::string> text = diag::readInput(path.string(), kMaxUrdfBytes, "cannot read URDF file");
  if (!text) return UrdfRead{std::nullopt, text.failures()};
  return readUrdfText(*text, path.string(), options);
}

}  // namespace rs::urdf
