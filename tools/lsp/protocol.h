// LSP's JSON shapes for the few structures every feature uses: positions,
// ranges, locations, text edits.
#pragma once

#include <string>

#include "tools/lsp/document.h"
#include "tools/lsp/json.h"
#include "tools/lsp/params.h"

namespace rs::lsp {

Json toJson(Position p);
Json toJson(const Range& r);
Json location(const std::string& uri, const Range& r);
Json textEdit(const Range& r, std::string newText);

/// From params (a missing or mistyped field throws BadParams, which the
/// dispatcher answers with InvalidParams).
Position positionFrom(const Field& f);
Range rangeFrom(const Field& f);
/// params.textDocument.uri
std::string documentUri(const Field& params);

/// LSP's SymbolKind, CompletionItemKind, DiagnosticSeverity values used here.
namespace symbol_kind {
inline constexpr int kModule = 2;
inline constexpr int kNamespace = 3;
inline constexpr int kClass = 5;
inline constexpr int kField = 8;
inline constexpr int kFunction = 12;
inline constexpr int kVariable = 13;
inline constexpr int kConstant = 14;
inline constexpr int kKey = 20;
inline constexpr int kObject = 19;
inline constexpr int kStruct = 23;
inline constexpr int kEvent = 24;
}  // namespace symbol_kind

}  // namespace rs::lsp
