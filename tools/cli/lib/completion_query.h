// `robotsim __complete cells|robots [--lib DIR]...`: the names a shell
// offers after --cell (workcells and robots) or --robot (robots), one a
// line, sorted: every NAME.rsd of the library search path
// (compiler::librarySearchPath: the library, --lib, ROBOTSIM_PATH), in
// each folder itself and in its workcells/ and robots/ folders, as the
// library looks names up. The completions of all three shells ask it, so
// they follow wherever the library is. A hidden query, not a command: no
// row in the table, no man page.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rs::cli {

/// Library names of the given kind ("cells" or "robots") on the search
/// path made of `libDirs`.
std::vector<std::string> libraryNames(const std::string& kind, const std::vector<std::string>& libDirs);

/// The query; argv[0] is the word after __complete. 0 with the names, 2
/// with an error on `err` for anything else.
int completionQuery(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
