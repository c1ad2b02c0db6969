// The verifier: checks an image before anything runs it. Everything the
// interpreter relies on without checking (operand ranges, jump targets,
// constant and point indices, table sizes) is established here once.
#pragma once

#include <string>

#include "vm/image.h"

namespace rs::vm {

struct VerifyError {
  std::string message;  // names the instruction index (1-based) when relevant
};

/// Returns an empty message when the image is sound.
VerifyError verify(const Image& image);

}  // namespace rs::vm
