// A small XML text writer for the URDF export: elements, attributes and
// comments, indented two spaces a level, escaped, numbers written so that
// they read back as the same double. The same calls give the same bytes.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rs::urdf {

/// `text` as attribute value or character data: & < > " ' as entities;
/// a character XML 1.0 does not allow (the C0 controls but tab, line feed
/// and carriage return) becomes '?'.
std::string xmlEscape(std::string_view text);

/// `v` as the shortest decimal that reads back as the same double, without
/// an exponent; a value within 1e-15 of 0 (a rounding residue such as
/// cos 90° = 6e-17) and -0 are written "0".
std::string xmlNumber(double v);

/// Three numbers separated by spaces (URDF's xyz, rpy and size).
std::string xmlNumbers(double a, double b, double c);

class XmlWriter {
 public:
  using Attributes = std::vector<std::pair<std::string_view, std::string>>;

  /// `<?xml version="1.0"?>` and a line feed.
  void declaration();
  /// `<name a="v" ...>`; close() ends it.
  void open(std::string_view name, const Attributes& attributes = {});
  /// `<name a="v" .../>`
  void element(std::string_view name, const Attributes& attributes = {});
  /// The innermost open element's end tag.
  void close();
  /// `<!-- text -->`, with "--" (which a comment cannot hold) written "- -".
  void comment(std::string_view text);
  /// An empty line, between groups of elements.
  void blank();

  /// What was written; every element must be closed.
  std::string take();

 private:
  void startTag(std::string_view name, const Attributes& attributes);
  std::string text_;
  std::vector<std::string> open_;
};

}  // namespace rs::urdf
