// The XML side of reading a URDF file, before urdfdom reads it: whether it
// is well-formed XML whose root is <robot> (and not a xacro file), the line
// of every <joint> and <link> (urdfdom's messages name elements but give no
// lines: tinyxml2, which urdfdom reads with, keeps them), and the checks
// whose position only the XML knows (an unknown joint type, a number that
// is not finite).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"

namespace tinyxml2 {
class XMLElement;
}

namespace rs::urdf {

class XmlIndex {
 public:
  /// Parses `text`; problems go to `out` (file `file`). ok() is false when
  /// the file is not a URDF that urdfdom should be given.
  XmlIndex(std::string_view text, const std::string& file, std::vector<diag::Diagnostic>& out);
  bool ok() const { return ok_; }

  /// Where the <joint> or <link> named `name` starts; the <robot> element's
  /// place when there is none.
  diag::Pos joint(const std::string& name) const;
  diag::Pos link(const std::string& name) const;
  diag::Pos robot() const { return robot_; }
  /// The element a urdfdom message names ("... [name] ..."), as a joint or
  /// else a link; the <robot> element when it names neither.
  diag::Pos named(std::string_view message) const;

 private:
  diag::Pos at(int line, std::string_view element) const;
  bool treeChecks(const tinyxml2::XMLElement* root, const std::string& file, std::vector<diag::Diagnostic>& out);
  std::string_view text_;
  std::map<std::string, diag::Pos> joints_, links_;
  diag::Pos robot_{1, 1};
  bool ok_ = false;
};

}  // namespace rs::urdf
