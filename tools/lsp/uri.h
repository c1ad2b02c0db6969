// file:// URIs and paths. Other schemes (an editor's "untitled:") have no
// path: their documents are analysed from their text alone.
#pragma once

#include <string>
#include <string_view>

namespace rs::lsp {

/// The path of a file URI (percent-escapes decoded), or "" for another scheme.
std::string pathOfUri(std::string_view uri);
/// The file URI of a path, made absolute and normal (no "." or ".."
/// parts; what is not unreserved is escaped).
std::string uriOfPath(std::string_view path);

}  // namespace rs::lsp
