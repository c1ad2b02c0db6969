// The commands that compile or show a program without running it:
// `robotsim compile`, `disasm`, and the teaching views `tokens` and `ast`.
#pragma once

#include <ostream>
#include <string>

#include "launch/program.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct ProgramCommandOptions {
  launch::ProgramRequest program;
  std::string output;  // compile -o
  bool tree = false;   // ast --tree
};

/// The options of each (one ProgramCommandOptions serves all four).
void addCompileOptions(CLI::App* cmd, ProgramCommandOptions& o);
void addDisasmOptions(CLI::App* cmd, ProgramCommandOptions& o);
void addTokensOptions(CLI::App* cmd, ProgramCommandOptions& o);
void addAstOptions(CLI::App* cmd, ProgramCommandOptions& o);

int compileCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int disasmCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int tokensCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);
int astCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
