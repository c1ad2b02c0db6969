// robotsim_gen_docs: robotsim's man pages and bash, zsh and fish completions, from
// the command table. All the work is in tools/cli/lib/gen_docs.cpp.
#include <iostream>

#include "tools/cli/lib/gen_docs.h"

int main(int argc, char** argv) { return rs::cli::genDocsCommand(argc, argv, std::cout, std::cerr); }
