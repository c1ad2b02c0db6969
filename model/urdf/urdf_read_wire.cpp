#include "model/urdf/urdf_read_wire.h"

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <stdexcept>
#include "model/kinematics/chain_model.h"

namespace rs::urdf {

namespace {

using Json = nlohmann::json;

// The codes the reader gives (Diagnostic::code is a view of a static string).
std::string_view knownCode(const std::string& code) {
  static constexpr std::string_view kCodes[] = {
      "urdf-xml",   "urdf-not-urdf",      "urdf-xacro",      "urdf-not-finite", "urdf-joint-type",
      "urdf-size",  "urdf-precision",     "urdf-invalid",    "urdf-chain",      "urdf-held-joint",
      "urdf-limit", "urdf-range-widened", "urdf-mesh",       "urdf-mesh-missing", "urdf-kinematics",
      "urdf-helper"};
  for (std::string_view c : kCodes)
    if (c == code) return c;
  return {};
}

Json pose(const Eigen::Isometry3d& p) {
  Json a = Json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(p.matrix()(r, c));
  return a;
}

Eigen::Isometry3d pose(const Json& a) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) p.matrix()(r, c) = a.at(static_cast<std::size_t>(4 * r + c)).get<double>();
  return p;
}

Json point(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }
Eigen::Vector3d point(const Json& a) { return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()}; }

Json robotJson(const workcell::Robot& r) {
  Json j;
  j["name"] = r.name;
  if (r.urdf) j["urdf"] = {{"file", r.urdf->file}, {"root", r.urdf->rootLink}, {"tip", r.urdf->tipLink}};
  for (const Eigen::Isometry3d& f : r.frames) j["frames"].push_back(pose(f));
  if (r.tool) j["tool"] = pose(*r.tool);
  for (const workcell::JointSpec& s : r.joints)
    j["joints"].push_back({{"prismatic", s.type == kinematics::JointType::Prismatic},
                           {"letter", std::string(1, s.letter)},
                           {"precision", s.precision},
                           {"min", s.min},
                           {"max", s.max},
                           {"coupling", s.coupling},
                           {"speed", s.speed}});
  for (const workcell::Shape& s : r.links) {
    Json link{{"name", s.name}, {"segments", Json::array()}, {"pieces", Json::array()}};
    for (const workcell::Segment& seg : s.segments)
      link["segments"].push_back({point(seg.a), point(seg.b), static_cast<int>(seg.color)});
    for (const workcell::ConvexPiece& p : s.collision) {
      Json points = Json::array();
      for (const Eigen::Vector3d& v : p.points) points.push_back(point(v));
      link["pieces"].push_back({{"box", p.box}, {"points", points}});
    }
    j["links"].push_back(link);
  }
  return j;
}

workcell::Robot robotOf(const Json& j) {
  workcell::Robot r;
  r.name = j.at("name").get<std::string>();
  if (j.contains("urdf"))
    r.urdf = workcell::UrdfSource{j["urdf"].at("file").get<std::string>(), j["urdf"].at("root").get<std::string>(),
                                  j["urdf"].at("tip").get<std::string>()};
  for (const Json& f : j.at("frames")) r.frames.push_back(pose(f));
  if (j.contains("tool")) r.tool = pose(j["tool"]);
  for (const Json& s : j.at("joints")) {
    workcell::JointSpec spec;
    spec.type = s.at("prismatic").get<bool>() ? kinematics::JointType::Prismatic : kinematics::JointType::Revolute;
    spec.letter = s.at("letter").get<std::string>().at(0);
    spec.precision = s.at("precision").get<double>();
    spec.min = s.at("min").get<std::int32_t>(), spec.max = s.at("max").get<std::int32_t>();
    spec.coupling = s.at("coupling").get<bool>();
    spec.speed = s.at("speed").get<std::int32_t>();
    r.joints.push_back(spec);
  }
  for (const Json& l : j.at("links")) {
    workcell::Shape shape;
    shape.name = l.at("name").get<std::string>();
    for (const Json& seg : l.at("segments"))
      shape.segments.push_back({point(seg.at(0)), point(seg.at(1)), static_cast<workcell::Color>(seg.at(2).get<int>() & 15)});
    for (const Json& p : l.at("pieces")) {
      workcell::ConvexPiece piece;
      piece.box = p.at("box").get<bool>();
      for (const Json& v : p.at("points")) piece.points.push_back(point(v));
      shape.collision.push_back(std::move(piece));
    }
    r.links.push_back(std::move(shape));
  }
  return r;
}

}  // namespace

std::string encodeUrdfRead(const UrdfRead& read) {
  Json j;
  j["diagnostics"] = Json::array();
  for (const diag::Diagnostic& d : read.diagnostics)
    j["diagnostics"].push_back({{"file", d.file},
                                {"line", d.pos.line},
                                {"col", d.pos.col},
                                {"warning", d.severity != diag::Severity::Error},
                                {"message", d.message},
                                {"code", std::string(d.code)},
                                {"hint", d.hint}});
  if (read.robot) j["robot"] = robotJson(*read.robot);
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

UrdfRead decodeUrdfRead(std::string_view bytes, const std::string& file) {
  UrdfRead out;
  try {
    const Json j = Json::parse(bytes);
    for (const Json& d : j.at("diagnostics"))
      out.diagnostics.push_back({d.at("file").get<std::string>(),
                                 {d.at("line").get<std::uint32_t>(), d.at("col").get<std::uint32_t>()},
                                 d.at("warning").get<bool>() ? diag::Severity::Warning : diag::Severity::Error,
                                 d.at("message").get<std::string>(),
                                 knownCode(d.at("code").get<std::string>()),
                                 d.at("hint").get<std::string>()});
    if (j.contains("robot")) {
      workcell::Robot r = robotOf(j["robot"]);
      std::vector<kinematics::JointType> types;
      std::vector<kinematics::JointDrive> drives;
      for (const workcell::JointSpec& s : r.joints) types.push_back(s.type), drives.push_back({s.precision, -1, s.coupling});
      auto chain = kinematics::ChainModel::fromFrames(r.frames, types, drives);
      if (!chain.ok()) throw std::runtime_error(chain.errors.front().message);
      r.chain = std::move(chain.value);
      if (r.tool) r.chain = r.chain->withTool(r.frames.back().inverse(Eigen::Isometry) * *r.tool);
      out.robot = std::move(r);
    }
  } catch (const std::exception& e) {
    out.robot.reset();
    out.diagnostics.push_back({file, {}, diag::Severity::Error,
                               fmt::format("the URDF reader's answer could not be read: {}", e.what()), "urdf-helper",
                               "reinstall robotsim: robotsim-urdf and robotsim must come from the same build"});
  }
  return out;
}

}  // namespace rs::urdf
