// The language server's names for the byte streams under the protocol
// (tools/wire/transport.h, shared with the debug adapter).
#pragma once

#include "tools/wire/transport.h"

namespace rs::lsp {

using wire::FdInput;
using wire::FdOutput;
using wire::Input;
using wire::Output;
using wire::StreamInput;
using wire::StreamOutput;

}  // namespace rs::lsp
