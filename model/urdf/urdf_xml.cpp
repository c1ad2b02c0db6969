#include "model/urdf/urdf_xml.h"

#include <cassert>
#include <charconv>
#include <cmath>

namespace rs::urdf {

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') out += '?';
        else out += c;
    }
  }
  return out;
}

std::string xmlNumber(double v) {
  if (!std::isfinite(v)) return "nan";  // never written by the export; visible if it were
  if (std::abs(v) < 1e-15) return "0";
  char buffer[400];  // a fixed-notation double is at most ~330 characters
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed);
  assert(ec == std::errc{});
  return std::string(buffer, end);
}

std::string xmlNumbers(double a, double b, double c) {
  return xmlNumber(a) + ' ' + xmlNumber(b) + ' ' + xmlNumber(c);
}

void XmlWriter::declaration() { text_ += "<?xml version=\"1.0\"?>\n"; }

void XmlWriter::startTag(std::string_view name, const Attributes& attributes) {
  text_.append(2 * open_.size(), ' ');
  text_ += '<';
  text_ += name;
  for (const auto& [key, value] : attributes) {
    text_ += ' ';
    text_ += key;
    text_ += "=\"";
    text_ += xmlEscape(value);
    text_ += '"';
  }
}

void XmlWriter::open(std::string_view name, const Attributes& attributes) {
  startTag(name, attributes);
  text_ += ">\n";
  open_.emplace_back(name);
}

void XmlWriter::element(std::string_view name, const Attributes& attributes) {
  startTag(name, attributes);
  text_ += "/>\n";
}

void XmlWriter::close() {
  assert(!open_.empty());
  const std::string name = std::move(open_.back());
  open_.pop_back();
  text_.append(2 * open_.size(), ' ');
  text_ += "</" + name + ">\n";
}

void XmlWriter::comment(std::string_view text) {
  // A comment is read literally (no entities): only what XML forbids in it changes.
  std::string body;
  for (const char c : text) body += static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' ? '?' : c;
  // "--" may not stand in a comment, nor "-" just before its end.
  for (std::size_t at = body.find("--"); at != std::string::npos; at = body.find("--", at)) body.insert(at + 1, " ");
  if (!body.empty() && body.back() == '-') body += ' ';
  text_.append(2 * open_.size(), ' ');
  text_ += "<!-- " + body + " -->\n";
}

void XmlWriter::blank() { text_ += '\n'; }

std::string XmlWriter::take() {
  assert(open_.empty());
  return std::move(text_);
}

}  // namespace rs::urdf
