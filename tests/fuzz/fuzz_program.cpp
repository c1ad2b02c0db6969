// libFuzzer target: any bytes as a robot program (.rsp). The compiler must
// answer with diagnostics or an image, never crash, hang or go superlinear;
// the diagnostics must render; an image it writes must load and verify again
// (the compiler never writes what the loader refuses).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "compiler/program/compiler.h"
#include "diag/diagnostic.h"
#include "launch/program.h"
#include "vm/image_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rs::compiler::Target target = rs::launch::defaultTarget();
  const rs::diag::SourceFile source("fuzz.rsp", std::string(reinterpret_cast<const char*>(data), size));
  const rs::compiler::CompileResult result = rs::compiler::compile(source, target, 50);
  for (const rs::diag::Diagnostic& d : result.diagnostics) (void)rs::diag::render(d, &source);
  if (result.image) {
    const std::vector<std::uint8_t> bytes = rs::vm::writeImage(*result.image);
    const rs::diag::Result<rs::vm::Image> loaded =
        rs::vm::loadImage(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    if (!loaded.ok()) std::abort();  // the compiler wrote an image its own loader refuses
  }
  return 0;
}
