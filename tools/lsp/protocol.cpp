#include "tools/lsp/protocol.h"

namespace rs::lsp {

Json toJson(Position p) { return {{"line", p.line}, {"character", p.character}}; }

Json toJson(const Range& r) { return {{"start", toJson(r.start)}, {"end", toJson(r.end)}}; }

Json location(const std::string& uri, const Range& r) { return {{"uri", uri}, {"range", toJson(r)}}; }

Json textEdit(const Range& r, std::string newText) { return {{"range", toJson(r)}, {"newText", std::move(newText)}}; }

Position positionFrom(const Field& f) {
  f.object();
  return {f["line"].uinteger(), f["character"].uinteger()};
}

Range rangeFrom(const Field& f) {
  f.object();
  return {positionFrom(f["start"]), positionFrom(f["end"])};
}

std::string documentUri(const Field& params) { return params["textDocument"]["uri"].string(); }

}  // namespace rs::lsp
