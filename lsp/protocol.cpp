#include "lsp/protocol.h"

namespace rs::lsp {

Json toJson(Position p) { return {{"line", p.line}, {"character", p.character}}; }

Json toJson(const Range& r) { return {{"start", toJson(r.start)}, {"end", toJson(r.end)}}; }

Json location(const std::string& uri, const Range& r) { return {{"uri", uri}, {"range", toJson(r)}}; }

Json textEdit(const Range& r, std::string newText) { return {{"range", toJson(r)}, {"newText", std::move(newText)}}; }

Position positionFrom(const Json& j) {
  return {j.at("line").get<std::uint32_t>(), j.at("character").get<std::uint32_t>()};
}

Range rangeFrom(const Json& j) { return {positionFrom(j.at("start")), positionFrom(j.at("end"))}; }

}  // namespace rs::lsp
