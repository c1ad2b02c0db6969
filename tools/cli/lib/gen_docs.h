// robotsim_gen_docs as a function (tools/cli/gen_docs.cpp calls it, tests run
// it in-process): writes the man pages (man_page.h) and the bash, zsh and
// fish completions (bash_completion.h, zsh_completion.h, fish_completion.h)
// made from the command table. A build-time
// tool, not a robotsim command: robotsim's commands stay exactly the
// table's, and the distribution's build runs this one.
#pragma once

#include <ostream>

namespace rs::cli {

int genDocsCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
