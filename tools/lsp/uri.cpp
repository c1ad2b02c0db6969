#include "tools/lsp/uri.h"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

namespace rs::lsp {

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string pathOfUri(std::string_view uri) {
  constexpr std::string_view kScheme = "file://";
  if (uri.substr(0, kScheme.size()) != kScheme) return {};
  uri.remove_prefix(kScheme.size());
  // "file://host/path": only the local host (empty or localhost) is a path here.
  const std::size_t slash = uri.find('/');
  if (slash == std::string_view::npos) return {};
  const std::string_view host = uri.substr(0, slash);
  if (!host.empty() && host != "localhost") return {};
  uri.remove_prefix(slash);
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
      path += static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  return path;
}

std::string uriOfPath(std::string_view given) {
  // One file, one URI: "cells/../cell.rsd" and "./cell.rsd" are the file
  // "cell.rsd", made absolute (editors match URIs as strings).
  std::error_code ec;
  std::filesystem::path path(given);
  if (!given.empty() && !path.is_absolute()) path = std::filesystem::absolute(path, ec);
  const std::string normal = path.lexically_normal().string();
  std::string uri = "file://";
  for (const char c : normal) {
    const auto u = static_cast<unsigned char>(c);
    const bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' ||
                      c == '.' || c == '_' || c == '~' || c == '/';
    uri += keep ? std::string(1, c) : fmt::format("%{:02X}", u);
  }
  return uri;
}

}  // namespace rs::lsp
