// The language server's names for the Content-Length framing, which lives
// in tools/wire/framing.h (the debug adapter frames its messages with the same
// code).
#pragma once

#include "tools/wire/framing.h"

namespace rs::lsp {

using wire::Frame;
using wire::FrameParser;
using wire::frameHeader;
using wire::frameMessage;
using wire::kMaxHeaderBytes;
using wire::kMaxMessageBytes;
using wire::parseFrames;

}  // namespace rs::lsp
