#include "model/urdf/urdf_read_xml.h"

#include <tinyxml2.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <set>

namespace rs::urdf {

namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;

// Attributes that hold numbers in URDF.
bool numeric(std::string_view attribute) {
  static const std::set<std::string_view> kNumeric = {"xyz",   "rpy",    "lower",  "upper",      "velocity",
                                                      "effort", "size",  "radius", "length",     "scale",
                                                      "rgba",  "offset", "multiplier", "value", "damping",
                                                      "friction", "mass", "ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  return kNumeric.contains(attribute);
}

// A word of a numeric attribute that reads as a number that is not finite
// ("nan", "inf", "1e999"), or empty.
std::string nonFinite(std::string_view value) {
  std::size_t i = 0;
  while (i < value.size()) {
    while (i < value.size() && std::isspace(static_cast<unsigned char>(value[i]))) ++i;
    std::size_t j = i;
    while (j < value.size() && !std::isspace(static_cast<unsigned char>(value[j]))) ++j;
    if (j > i) {
      const std::string word(value.substr(i, j - i));
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      if (end != word.c_str() && !std::isfinite(v)) return word;
    }
    i = j;
  }
  return {};
}

bool knownJointType(std::string_view t) {
  for (std::string_view k : {"revolute", "continuous", "prismatic", "fixed", "floating", "planar"})
    if (t == k) return true;
  return false;
}

}  // namespace

diag::Pos XmlIndex::at(int line, std::string_view element) const {
  // The column of "<element" on that line (tinyxml2 keeps lines only).
  std::size_t start = 0;
  for (int l = 1; l < line && start != std::string_view::npos; ++l) {
    start = text_.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (start == std::string_view::npos) return {static_cast<std::uint32_t>(line), 1};
  const std::size_t end = std::min(text_.find('\n', start), text_.size());
  const std::size_t found = text_.substr(start, end - start).find(fmt::format("<{}", element));
  return {static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(found == std::string_view::npos ? 1 : found + 1)};
}

XmlIndex::XmlIndex(std::string_view text, const std::string& file, std::vector<diag::Diagnostic>& out) : text_(text) {
  const auto error = [&](diag::Pos pos, std::string message, std::string hint, std::string_view code) {
    out.push_back({file, pos, diag::Severity::Error, std::move(message), code, std::move(hint)});
  };
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const int line = std::max(1, doc.ErrorLineNum());
    error({static_cast<std::uint32_t>(line), 1}, fmt::format("not well-formed XML: {}", doc.ErrorName()),
          "a URDF file is XML: one <robot name=\"...\"> element holding <link> and <joint> elements", "urdf-xml");
    return;
  }
  const XMLElement* root = doc.RootElement();
  if (!root) {
    error({1, 1}, "not a URDF file: it holds no XML element", "a URDF file's root element is <robot name=\"...\">",
          "urdf-not-urdf");
    return;
  }
  robot_ = at(root->GetLineNum(), root->Name());
  // xacro: macros robotsim does not expand.
  bool xacro = root->Attribute("xmlns:xacro") != nullptr;
  for (const XMLElement* e = root->FirstChildElement(); e && !xacro; e = e->NextSiblingElement())
    xacro = std::string_view(e->Name()).starts_with("xacro:");
  if (xacro) {
    error(robot_, "a xacro file: robotsim reads URDF, not xacro's macros",
          "run xacro first (xacro FILE.urdf.xacro > FILE.urdf) and give robotsim the URDF it writes", "urdf-xacro");
    return;
  }
  if (std::string_view(root->Name()) != "robot") {
    error(robot_, fmt::format("not a URDF file: its root element is <{}>, not <robot>", root->Name()),
          "a URDF file's root element is <robot name=\"...\">", "urdf-not-urdf");
    return;
  }
  bool ok = true;
  // Every element, depth first (iteratively: deep nesting must not run out of stack).
  std::vector<const XMLElement*> stack{root};
  while (!stack.empty()) {
    const XMLElement* e = stack.back();
    stack.pop_back();
    for (const XMLElement* c = e->LastChildElement(); c; c = c->PreviousSiblingElement()) stack.push_back(c);
    const std::string_view name = e->Name();
    const diag::Pos pos = at(e->GetLineNum(), name);
    for (const XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
      if (!numeric(a->Name())) continue;
      if (const std::string word = nonFinite(a->Value()); !word.empty()) {
        error(pos, fmt::format("<{} {}=\"{}\">: '{}' is not a finite number", name, a->Name(), a->Value(), word),
              "write a finite number", "urdf-not-finite");
        ok = false;
      }
    }
    if (e->Parent() != root) continue;
    const char* n = e->Attribute("name");
    if (name == "joint") {
      if (n) joints_.emplace(n, pos);
      const char* type = e->Attribute("type");
      if (type && !knownJointType(type)) {
        error(pos, fmt::format("joint '{}' has unknown type '{}'", n ? n : "", type),
              "URDF's joint types are revolute, continuous, prismatic, fixed, floating and planar", "urdf-joint-type");
        ok = false;
      }
    } else if (name == "link" && n) {
      links_.emplace(n, pos);
    }
  }
  // Links that are two joints' child, and loops, are found here: urdfdom
  // would report them without a line (and, for a loop, keep the links it
  // read alive in a cycle of shared pointers: a leak).
  if (ok) ok = treeChecks(root, file, out);
  ok_ = ok;
}

bool XmlIndex::treeChecks(const tinyxml2::XMLElement* root, const std::string& file, std::vector<diag::Diagnostic>& out) {
  struct Edge {
    std::string joint, parent;
    diag::Pos pos;
  };
  std::map<std::string, Edge> parentOf;  // by child link
  for (const XMLElement* e = root->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    const XMLElement* parent = e->FirstChildElement("parent");
    const XMLElement* child = e->FirstChildElement("child");
    const char* name = e->Attribute("name");
    const char* p = parent ? parent->Attribute("link") : nullptr;
    const char* c = child ? child->Attribute("link") : nullptr;
    if (!name || !p || !c) continue;  // urdfdom says what is missing
    const diag::Pos pos = at(e->GetLineNum(), "joint");
    if (const auto seen = parentOf.find(c); seen != parentOf.end()) {
      out.push_back({file, pos, diag::Severity::Error,
                     fmt::format("link '{}' is the child of joints '{}' and '{}'", c, seen->second.joint, name),
                     "urdf-invalid", "a URDF is a tree: a link is the child of one joint only"});
      return false;
    }
    parentOf.emplace(c, Edge{name, p, pos});
  }
  // Up from every link: a walk longer than the number of joints is a loop.
  for (const auto& [start, edge] : parentOf) {
    std::string link = start;
    for (std::size_t steps = 0; steps <= parentOf.size(); ++steps) {
      const auto up = parentOf.find(link);
      if (up == parentOf.end()) break;
      link = up->second.parent;
      if (link == start) {
        out.push_back({file, edge.pos, diag::Severity::Error,
                       fmt::format("the joints make a loop: joint '{}' leads back to link '{}'", edge.joint, start),
                       "urdf-invalid", "a URDF is a tree: one root link, no joint leading back to a link above it"});
        return false;
      }
    }
  }
  return true;
}

diag::Pos XmlIndex::joint(const std::string& name) const {
  const auto it = joints_.find(name);
  return it == joints_.end() ? robot_ : it->second;
}

diag::Pos XmlIndex::link(const std::string& name) const {
  const auto it = links_.find(name);
  return it == links_.end() ? robot_ : it->second;
}

diag::Pos XmlIndex::named(std::string_view message) const {
  for (std::size_t open = message.find('['); open != std::string_view::npos; open = message.find('[', open + 1)) {
    const std::size_t close = message.find(']', open);
    if (close == std::string_view::npos) break;
    const std::string name(message.substr(open + 1, close - open - 1));
    if (joints_.contains(name)) return joints_.at(name);
    if (links_.contains(name)) return links_.at(name);
  }
  return robot_;
}

}  // namespace rs::urdf
