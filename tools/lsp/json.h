// JSON for the language server: tools/wire/json.h (nlohmann-json and the one way
// a value is written out), under the server's names.
#pragma once

#include "tools/wire/json.h"

namespace rs::lsp {

using wire::dumpJson;
using wire::Json;

}  // namespace rs::lsp
