// The commands that compile or show a program without running it:
// `robotsim compile`, `disasm`, and the teaching views `tokens` and `ast`.
#pragma once

#include <ostream>
#include <string>

#include "launch/program.h"

namespace rs::cli {

struct ProgramCommandOptions {
  launch::ProgramRequest program;
  std::string output;  // compile -o
  bool tree = false;   // ast --tree
};

int compileCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int disasmCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int tokensCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int astCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
